#include "rodsea/engine/cpu/contact_response.hpp"

#include "rodsea/engine/cpu/plate_noise.hpp"
#include "rodsea/engine/stage_timer.hpp"

namespace rodsea::cpu {

StepStatistics ContactResponse::respond(const std::vector<Contact>& contacts, BodyView bodies,
                                        const SpeciesTable& species, SphereTable& spheres,
                                        const StepContext& context, int threads,
                                        StageProfile& profile, const ContactSearchStats& found,
                                        double fastest, std::size_t flown) {
    ResolutionStats resolved;
    {
        StageTimer t(profile.resolution);
        inverse_inertia_.update_for(contacts, bodies, species);
        plate_hits_.clear();
        resolved =
            resolver_.resolve(contacts, bodies, inverse_inertia_, context, plate_hits_, threads);
        plate_projection_.apply(contacts, bodies, spheres);
    }
    std::size_t kicks = 0;
    {
        StageTimer t(profile.noise);
        kicks = apply_plate_noise(plate_hits_, bodies, species, context, threads);
    }
    return {found.body_contacts,
            found.plate_contacts,
            resolved.sweeps,
            resolved.impulses,
            resolved.body_collisions,
            resolved.plate_collisions,
            resolved.unresolved + found.gross_overlaps,
            kicks,
            found.max_overlap_fraction,
            fastest,
            flown};
}

}  // namespace rodsea::cpu
