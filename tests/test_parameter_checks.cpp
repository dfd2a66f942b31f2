// Bad input is refused before anything runs, with a message naming the parameter, its value
// and the allowed range.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/scenes/scenes.hpp"
#include "rodsea/shape/sphere_chain.hpp"

namespace rodsea {
namespace {

void expect_refused(const std::function<void()>& action, const std::string& name,
                    const std::string& value, const std::string& allowed) {
    try {
        action();
        ADD_FAILURE() << "accepted bad " << name;
    } catch (const InvalidParameter& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.name(), name) << what;
        EXPECT_NE(what.find(value), std::string::npos) << what;
        EXPECT_NE(what.find(allowed), std::string::npos) << what;
    }
}

Scene valid_scene() {
    return single_body(polar_rod_species(), 20.0);
}

void build(const Scene& s) {
    Simulation sim(s.params, s.bodies);
}

TEST(Validation, ShapeThatDoesNotFitTheGapNamesRodDiameterAndGap) {
    Scene s = valid_scene();
    s.params.drive.gap = 1.2;  // the paper's gap: its own polar rod cannot fit
    try {
        build(s);
        ADD_FAILURE() << "accepted a 1.375 mm rod in a 1.2 mm gap";
    } catch (const InvalidParameter& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.name(), "drive.gap");
        EXPECT_NE(what.find("polar_rod"), std::string::npos) << what;
        EXPECT_NE(what.find("1.375 mm"), std::string::npos) << what;
        EXPECT_NE(what.find("1.2 mm"), std::string::npos) << what;
    }
}

TEST(Validation, NonPositiveGeometryMassDtAndCount) {
    expect_refused(
        [] {
            PolarRodGeometry g;
            g.length = 0;
            polar_rod_spheres(g);
        },
        "polar_rod.length", "0 mm", "> 0");
    expect_refused(
        [] {
            PolarRodGeometry g;
            g.thin_diameter = -0.4;
            polar_rod_spheres(g);
        },
        "polar_rod.thin_diameter", "-0.4 mm", "> 0");
    expect_refused(
        [] {
            PolarRodGeometry g;
            g.sphere_count = 0;
            polar_rod_spheres(g);
        },
        "polar_rod.sphere_count", "0", ">= 1");
    expect_refused(
        [] {
            auto g = ApolarRodGeometry::with_length(2.5);
            g.centre_diameter = 0;
            apolar_rod_spheres(g);
        },
        "apolar_rod.centre_diameter", "0 mm", "> 0");
    expect_refused([] { apolar_rod_species(-1.0); }, "apolar_rod.length", "-1 mm", "> 0");
    expect_refused(
        [] {
            BeadGeometry g;
            g.diameter = 0;
            bead_spheres(g);
        },
        "bead.diameter", "0 mm", "> 0");
    expect_refused([] { make_shape(bead_spheres({}), 0.0, "bead"); }, "bead.mass", "0", "> 0");
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.params.dt = 0;
            build(s);
        },
        "dt", "0 s", "> 0");
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.params.dt = -1e-6;
            build(s);
        },
        "dt", "-1e-06 s", "> 0");
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.params.max_sweeps = 0;
            build(s);
        },
        "max_sweeps", "0", ">= 1");
}

TEST(Validation, FrictionAndRestitutionOutsidePhysicalRange) {
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.params.body_body.restitution = 1.2;
            build(s);
        },
        "body_body.restitution", "1.2", "[0, 1]");
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.params.body_body.friction = -0.1;
            build(s);
        },
        "body_body.friction", "-0.1", "[0, 10]");
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.params.species[0].plate.restitution = -0.5;
            build(s);
        },
        "species.polar_rod.plate.restitution", "-0.5", "[0, 1]");
}

TEST(Validation, BodiesOutsideTheGapOrTooBigABox) {
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.bodies.position[0].z = 2.0;
            build(s);
        },
        "bodies[0].position.z", "2 mm", "between the base");
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.params.box = {8.0, 20.0};
            build(s);
        },
        "box.lx", "8 mm", ">= 9 mm");
    expect_refused(
        [] {
            Scene s = valid_scene();
            s.bodies = {};
            build(s);
        },
        "bodies", "0 bodies", ">= 1");
}

}  // namespace
}  // namespace rodsea
