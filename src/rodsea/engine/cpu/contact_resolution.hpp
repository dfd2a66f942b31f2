#pragma once
// Stage 4 of the CPU step: impulses on every approaching contact, swept Gauss–Seidel style until
// no contact approaches or the sweep cap is reached. After the first sweep only contacts with
// a body that changed since they were last checked are looked at again.
//
// Contacts fall into islands: bodies joined by body–body contacts (a plate joins nothing). An
// island's sweeps never touch another island's bodies, and an island that got no impulse in a
// sweep is skipped by every later one, so sweeping each island on its own, in list order,
// applies exactly the impulses that sweeping the whole list does. Islands are swept in parallel:
// the result is the same, bit for bit, on any number of threads.
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/math/mat3.hpp"

namespace rodsea::cpu {

// Inverse mass and world-frame inverse inertia R I⁻¹ Rᵀ of the bodies in contact, for their
// current orientations: in a vibrated monolayer a step has a contact for a few per cent of the
// bodies, and the resolver reads no others. The others keep stale values.
class InverseInertia {
  public:
    void update_for(const std::vector<Contact>& contacts, BodyView bodies,
                    const SpeciesTable& species);
    double inv_mass(std::uint32_t b) const { return inv_mass_[b]; }
    const Mat3& inv_inertia(std::uint32_t b) const { return inv_inertia_[b]; }

  private:
    std::vector<double> inv_mass_;
    std::vector<Mat3> inv_inertia_;
    std::vector<std::uint64_t> stamp_;  // the update_for() call that last computed each body
    std::uint64_t calls_ = 0;
};

// A body's collision with a plate this step: the approach speed |u_n| before its impulse.
struct PlateHit {
    std::uint32_t body = 0;
    std::uint32_t plate = 0;  // kBasePlate or kLidPlate
    double approach_speed = 0.0;
};

struct ResolutionStats {
    int sweeps = 0;
    size_t impulses = 0;
    size_t body_collisions = 0;   // impulses between two bodies approaching > kCollisionSpeed
    size_t plate_collisions = 0;  // impulses with a plate approaching > kCollisionSpeed
    size_t unresolved = 0;        // contacts still approaching when the sweep cap was reached
};

class ContactResolver {
  public:
    // Appends the plate hits to `hits`, island by island: the same list on any number of threads.
    ResolutionStats resolve(const std::vector<Contact>& contacts, BodyView bodies,
                            const InverseInertia& inertia, const StepContext& step,
                            std::vector<PlateHit>& hits, int threads);
    size_t islands() const { return island_count_; }  // of the last resolve()

  private:
    void find_islands(const std::vector<Contact>& contacts, size_t bodies);
    ResolutionStats sweep_island(size_t island, const std::vector<Contact>& contacts,
                                 BodyView bodies, const InverseInertia& inertia,
                                 const StepContext& step, std::vector<PlateHit>& hits);

    std::vector<int> last_changed_;  // per body: the last sweep that gave it an impulse
    // Islands, rebuilt every step: union–find over bodies, then the contacts of each island in
    // list order (island_contacts_[island_start_[k] .. island_start_[k + 1]]).
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint32_t> island_of_root_;
    std::vector<std::uint32_t> contact_island_;
    std::vector<std::uint32_t> island_start_;
    std::vector<std::uint32_t> island_contacts_;
    std::vector<std::uint32_t> island_cursor_;  // scratch: a cursor per island
    std::vector<std::vector<PlateHit>> island_hits_;
    std::vector<ResolutionStats> island_stats_;
    size_t island_count_ = 0;
};

}  // namespace rodsea::cpu
