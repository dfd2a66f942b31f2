#pragma once
// A rigid body's shape in its principal frame: the origin is the centre of mass and the body
// axes are principal axes of inertia, so that torque-free rotation can be integrated exactly
// (axisymmetric bodies) or by an exact-subflow splitting (asymmetric ones). For rods built by
// sphere_chain.hpp the principal frame is the definition frame shifted to the centre of mass:
// the rod axis stays body x, pointing from the thick to the thin end for polar rods.
#include <string>
#include <vector>

#include "rodsea/math/quat.hpp"
#include "rodsea/shape/sphere.hpp"

namespace rodsea {

struct Shape {
    std::vector<Vec3> offsets;     // sphere centres, principal body frame (mm)
    std::vector<double> radii;     // mm
    double mass = 1.0;             // arbitrary mass unit (docs/model.md: only ratios matter)
    Vec3 principal_inertia;        // mass unit · mm², about the body axes
    double volume = 0.0;           // mm³
    double projected_area = 0.0;   // mm², footprint lying flat (union of great discs)
    double max_radius = 0.0;       // mm
    double extent = 0.0;           // mm, largest distance between two points of the body
    Vec3 com_in_definition_frame;  // where the centre of mass was in the input frame (mm)
    Quat definition_to_body;       // rotation from the definition frame to the principal frame

    size_t sphere_count() const { return radii.size(); }
};

// Builds a shape from spheres in any frame, scaling the inertia to `mass`. Throws
// InvalidParameter (naming `name`) for a non-positive mass or radius.
Shape make_shape(const SphereList& spheres, double mass, const std::string& name = "shape");

// Eigen-decomposition of a symmetric matrix: m = R diag(values) Rᵀ with R a proper rotation.
// Already-diagonal input returns R = 𝟙 with the values in their original order.
struct SymmetricEigen {
    Vec3 values;
    Mat3 rotation;
};
SymmetricEigen symmetric_eigen(const Mat3& m);

}  // namespace rodsea
