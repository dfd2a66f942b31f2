#pragma once
// Stage 4 of the step: impulses on every approaching contact, swept Gauss–Seidel style until
// no contact approaches or the sweep cap is reached. After the first sweep only contacts with
// a body that changed since they were last checked are looked at again.
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/contact.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

// Inverse mass and world-frame inverse inertia of every body for the current orientations.
struct InverseInertia {
    std::vector<double> inv_mass;
    std::vector<Mat3> inv_inertia;  // R I⁻¹ Rᵀ

    void update(const BodyState& bodies, const std::vector<Species>& species);
};

// A body's collision with a plate this step: the approach speed |u_n| before its impulse.
struct PlateHit {
    std::uint32_t body = 0;
    std::uint32_t plate = 0;  // kBasePlate or kLidPlate
    double approach_speed = 0.0;
};

// A collision, as opposed to a contact that merely persists: an impulse on a contact approaching
// faster than this. Bodies resting on or pressed against each other or a plate approach at about
// (Γ + 1) g dt per step (0.09 mm/s at 1.25 µs, 0.4 mm/s at 5 µs) and get an impulse every step,
// so impulses grow as 1/dt; real impacts in the vibrated cell come at mm/s to tens of mm/s, and
// their count per second does not depend on dt.
inline constexpr double kCollisionSpeed = 1.0;  // mm/s

struct ResolutionStats {
    int sweeps = 0;
    size_t impulses = 0;
    size_t body_collisions = 0;   // impulses between two bodies approaching > kCollisionSpeed
    size_t plate_collisions = 0;  // impulses with a plate approaching > kCollisionSpeed
    size_t unresolved = 0;        // contacts still approaching when the sweep cap was reached
};

class ContactResolver {
  public:
    ResolutionStats resolve(const std::vector<Contact>& contacts, BodyState& bodies,
                            const InverseInertia& inertia, double plate_velocity_z,
                            const EngineParameters& params, std::vector<PlateHit>& hits);

  private:
    std::vector<int> last_changed_;  // per body: the last sweep that gave it an impulse
};

}  // namespace rodsea
