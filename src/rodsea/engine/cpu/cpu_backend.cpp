#include "rodsea/engine/cpu/cpu_backend.hpp"

#include "rodsea/engine/cpu/free_flight.hpp"
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
    stats = response_.respond(contacts_, bodies, species_, spheres_, context, threads_, profile,
                              found, fastest, bodies.size());
}

}  // namespace rodsea::cpu
