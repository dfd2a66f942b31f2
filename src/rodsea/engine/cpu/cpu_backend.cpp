#include "rodsea/engine/cpu/cpu_backend.hpp"

#include "rodsea/engine/cpu/free_flight.hpp"
#include "rodsea/engine/cpu/plate_noise.hpp"
#include "rodsea/engine/stage_timer.hpp"

namespace rodsea::cpu {

CpuBackend::CpuBackend(const SpeciesTable& species, BodyState bodies, int threads)
    : species_(species), bodies_(std::move(bodies)), threads_(threads) {
    spheres_.assign(bodies_.species, species_);
    spheres_.update_positions(bodies_.view(), species_, 1);
}

void CpuBackend::step(const StepContext& context, StepStatistics& stats, StageProfile& profile) {
    const BodyView bodies = bodies_.view();
    double fastest = 0.0;  // bound on any sphere's speed in the plane in this step (mm/s)
    {
        StageTimer t(profile.free_flight);
        fastest = advance_free_flight(bodies, species_, context, threads_);
    }
    {
        StageTimer t(profile.sphere_update);
        spheres_.update_positions(bodies, species_, threads_);
    }
    ContactSearchStats found;
    {
        StageTimer t(profile.contact_search);
        found = finder_.find(spheres_, bodies, species_, context, contacts_, threads_,
                             fastest * context.dt);
    }
    ResolutionStats resolved;
    {
        StageTimer t(profile.resolution);
        inverse_inertia_.update_for(contacts_, bodies, species_);
        plate_hits_.clear();
        resolved =
            resolver_.resolve(contacts_, bodies, inverse_inertia_, context, plate_hits_, threads_);
        plate_projection_.apply(contacts_, bodies, spheres_);
    }
    std::size_t kicks = 0;
    {
        StageTimer t(profile.noise);
        kicks = apply_plate_noise(plate_hits_, bodies, species_, context, threads_);
    }
    stats = {found.body_contacts,
             found.plate_contacts,
             resolved.sweeps,
             resolved.impulses,
             resolved.body_collisions,
             resolved.plate_collisions,
             resolved.unresolved + found.gross_overlaps,
             kicks,
             found.max_overlap_fraction,
             fastest,
             bodies.size()};
}

}  // namespace rodsea::cpu
