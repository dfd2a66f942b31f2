// The config module: TOML → validated RunPlan. Every number checked here is fixed by docs/model.md
// or the paper (defaults, Table S1 counts, A = Γg/Ω²) or by the key table itself (each key's value
// lands in its RunPlan field in engine units), and every error names the key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/config/schema.hpp"
#include "rodsea/error.hpp"
#include "rodsea/shape/sphere_chain.hpp"

namespace rodsea {
namespace {

constexpr double kPi = std::numbers::pi;

RunPlan load(const std::string& toml) {
    return load_config_string(toml, "test.toml");
}

// Small box and two species: the cases below change one key of this.
const std::string kTwoSpecies = R"(
[[species]]
name = "polar"
kind = "polar_rod"
area_fraction = 0.05

[[species]]
name = "medium"
kind = "apolar_rod"
length = 2.5
area_fraction = 0.5
)";

void expect_same_shape(const Shape& a, const Shape& b) {
    EXPECT_EQ(a.offsets, b.offsets);
    EXPECT_EQ(a.radii, b.radii);
    EXPECT_EQ(a.mass, b.mass);
    EXPECT_EQ(a.principal_inertia, b.principal_inertia);
    EXPECT_EQ(a.volume, b.volume);
    EXPECT_EQ(a.projected_area, b.projected_area);
    EXPECT_EQ(a.max_radius, b.max_radius);
    EXPECT_EQ(a.extent, b.extent);
}

// Bit-for-bit: a resumed run must simulate exactly the same system.
void expect_same_plan(const RunPlan& a, const RunPlan& b, bool same_text = true) {
    const EngineParameters &e = a.engine, &f = b.engine;
    EXPECT_EQ(e.box.lx, f.box.lx);
    EXPECT_EQ(e.box.ly, f.box.ly);
    EXPECT_EQ(e.drive.gamma, f.drive.gamma);
    EXPECT_EQ(e.drive.angular_frequency, f.drive.angular_frequency);
    EXPECT_EQ(e.drive.gap, f.drive.gap);
    EXPECT_EQ(e.drive.gravity, f.drive.gravity);
    ASSERT_EQ(e.species.size(), f.species.size());
    for (size_t i = 0; i < e.species.size(); ++i) {
        EXPECT_EQ(e.species[i].name, f.species[i].name);
        EXPECT_EQ(e.species[i].kind, f.species[i].kind);
        EXPECT_EQ(e.species[i].plate.friction, f.species[i].plate.friction);
        EXPECT_EQ(e.species[i].plate.restitution, f.species[i].plate.restitution);
        expect_same_shape(e.species[i].shape, f.species[i].shape);
    }
    EXPECT_EQ(e.body_body.friction, f.body_body.friction);
    EXPECT_EQ(e.body_body.restitution, f.body_body.restitution);
    ASSERT_EQ(e.body_body_by_pair.size(), f.body_body_by_pair.size());
    for (size_t i = 0; i < e.body_body_by_pair.size(); ++i) {
        EXPECT_EQ(e.body_body_by_pair[i].friction, f.body_body_by_pair[i].friction);
        EXPECT_EQ(e.body_body_by_pair[i].restitution, f.body_body_by_pair[i].restitution);
    }
    EXPECT_EQ(e.dt, f.dt);
    EXPECT_EQ(e.noise_epsilon, f.noise_epsilon);
    EXPECT_EQ(e.seed, f.seed);
    EXPECT_EQ(e.max_sweeps, f.max_sweeps);
    EXPECT_EQ(e.approach_tolerance, f.approach_tolerance);
    EXPECT_EQ(a.counts, b.counts);
    EXPECT_EQ(a.requested_area_fraction, b.requested_area_fraction);
    EXPECT_EQ(a.builder.orientation, b.builder.orientation);
    EXPECT_EQ(a.builder.randomisation_sweeps, b.builder.randomisation_sweeps);
    EXPECT_EQ(a.builder.domain_size, b.builder.domain_size);
    EXPECT_EQ(a.control.steady_samples, b.control.steady_samples);
    EXPECT_EQ(a.control.steady_series, b.control.steady_series);
    EXPECT_EQ(a.control.duration, b.control.duration);
    EXPECT_EQ(a.control.output_interval, b.control.output_interval);
    EXPECT_EQ(a.control.checkpoint_interval, b.control.checkpoint_interval);
    EXPECT_EQ(a.control.threads, b.control.threads);
    if (same_text) {
        EXPECT_EQ(a.config_toml, b.config_toml);
    }
    EXPECT_EQ(a.choices, b.choices);
}

// The lines at which two texts of the same number of lines differ, both versions.
std::vector<std::string> differing_lines(const std::string& a, const std::string& b) {
    std::istringstream sa(a), sb(b);
    std::vector<std::string> out;
    std::string la, lb;
    while (std::getline(sa, la)) {
        if (!std::getline(sb, lb)) return {"(second text shorter)"};
        if (la != lb) out.insert(out.end(), {la, lb});
    }
    if (std::getline(sb, lb)) out.push_back("(second text longer)");
    return out;
}

void expect_reloads_identically(const RunPlan& plan) {
    SCOPED_TRACE("reloading config_toml");
    const RunPlan reloaded = load_config_string(plan.config_toml, "resolved.toml");
    expect_same_plan(reloaded, plan, false);
    // Same text too, except that a config giving D_r resolves to the ε its table gives, and
    // keeps D_r only as a comment that a reload (with ε and no table) cannot know; from the
    // first reload on the text is fixed.
    for (const std::string& line : differing_lines(plan.config_toml, reloaded.config_toml))
        EXPECT_EQ(line.rfind("# rotational_diffusion = ", 0), 0u) << line;
    EXPECT_EQ(load_config_string(reloaded.config_toml, "twice.toml").config_toml,
              reloaded.config_toml);
}

// The error names `name` and its message contains every one of `parts`.
void expect_invalid(const std::string& toml, const std::string& name,
                    const std::vector<std::string>& parts) {
    SCOPED_TRACE(toml);
    try {
        load(toml);
        ADD_FAILURE() << "accepted; expected an error naming " << name;
    } catch (const InvalidParameter& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.name(), name) << what;
        for (const std::string& part : parts)
            EXPECT_NE(what.find(part), std::string::npos) << "'" << part << "' not in: " << what;
    }
}

// ---------------------------------------------------------------------------------------------
// Defaults

TEST(ConfigDefaults, EmptyFileIsThePapersMainSystemWithModelMdValues) {
    const RunPlan p = load("");
    const EngineParameters& e = p.engine;
    EXPECT_EQ(e.box.lx, 252.0);  // 56 ℓ_p
    EXPECT_EQ(e.box.ly, 252.0);
    EXPECT_EQ(e.drive.gamma, 7.0);
    EXPECT_DOUBLE_EQ(e.drive.angular_frequency, 400.0 * kPi);
    // A = Γg/Ω² = 7 × 9810 / (400π)² = 0.043487 mm: docs/model.md's 43.49 µm to its 4 digits.
    EXPECT_NEAR(e.drive.amplitude() * 1000.0, 43.49, 0.005);
    EXPECT_EQ(e.drive.gap, 1.40);  // docs/model.md: a lone polar rod goes thick → thin
    EXPECT_EQ(e.drive.gravity, 9810.0);
    EXPECT_EQ(e.dt, 1.25e-6);  // docs/model.md: the first specification's 5 µs is not converged
    EXPECT_EQ(e.noise_epsilon, 0.0);
    EXPECT_EQ(e.seed, 1u);
    EXPECT_EQ(e.max_sweeps, 2000);
    EXPECT_EQ(e.approach_tolerance, 1e-6);
    EXPECT_EQ(e.body_body.friction, 0.05);  // Table S2, every pair
    EXPECT_EQ(e.body_body.restitution, 0.30);
    EXPECT_TRUE(e.body_body_by_pair.empty());

    ASSERT_EQ(e.species.size(), 2u);
    EXPECT_EQ(e.species[0].name, "polar");
    EXPECT_EQ(e.species[0].kind, BodyKind::polar_rod);
    EXPECT_EQ(e.species[0].shape.sphere_count(), 13u);
    EXPECT_EQ(e.species[0].shape.mass, 1.0);
    EXPECT_EQ(e.species[0].plate.friction, 0.03);  // Table S2, polar rod – plate
    EXPECT_EQ(e.species[0].plate.restitution, 0.10);
    EXPECT_EQ(e.species[1].name, "medium");
    EXPECT_EQ(e.species[1].kind, BodyKind::apolar_rod);
    EXPECT_EQ(e.species[1].shape.sphere_count(), 9u);  // 4 ℓ_a − 1 at ℓ_a = 2.5 mm
    EXPECT_NEAR(e.species[1].shape.extent, 2.5, 1e-12);
    EXPECT_EQ(e.species[1].shape.mass, 0.2);       // m_apolar / m_polar = 0.20
    EXPECT_EQ(e.species[1].plate.friction, 0.01);  // Table S2, apolar rod – plate
    EXPECT_EQ(e.species[1].plate.restitution, 0.30);

    // Table S1: 800 polar rods at φ_p = 0.05 (13 spheres); φ_a = 0.50 of ℓ_a = 2.5 mm rods
    // (A = 1.36762 mm²) is 0.5 × 252² / 1.36762 = 23217.2 → 23217.
    EXPECT_EQ(p.counts, (std::vector<long long>{800, 23217}));
    EXPECT_EQ(p.requested_area_fraction, (std::vector<double>{0.05, 0.50}));

    EXPECT_EQ(p.control.duration, 1.0);
    EXPECT_EQ(p.control.output_interval, 0.05);
    EXPECT_EQ(p.control.checkpoint_interval, 30.0);
    EXPECT_EQ(p.control.threads, 1);
    EXPECT_EQ(p.builder.orientation, InitialOrientation::isotropic);
    EXPECT_EQ(p.builder.randomisation_sweeps, 50);
    EXPECT_EQ(p.builder.domain_size, 20.0);
    EXPECT_EQ(p.total_steps(), 800'000u);  // 4000 steps per 5 ms period, for one second
    EXPECT_EQ(p.steps_per_output(), 40'000u);
}

TEST(ConfigDefaults, DefaultConfigTomlIsTheEmptyConfigWrittenOut) {
    const std::string text = default_config_toml();
    // Every key of the table appears, set or (alternatives, unset keys) commented out.
    for (const config::KeySpec& k : config::config_keys()) {
        EXPECT_NE(text.find(k.name + " = "), std::string::npos) << k.path();
    }
    EXPECT_NE(text.find("# CHOICE: the paper's 1.2 mm cannot hold"), std::string::npos);
    EXPECT_NE(text.find("allowed (0, 100] mm; default 1.4"), std::string::npos);
    expect_same_plan(load_config_string(text, "defaults.toml"), load(""));
}

// ---------------------------------------------------------------------------------------------
// Every key round-trips

struct KeyCase {
    std::string key;   // schema path, e.g. "drive.gamma" or "species.length"
    std::string toml;  // a config setting that key to a valid non-default value
    std::function<void(const RunPlan&)> check;
};

std::string species_block(const std::string& body) {
    return "[[species]]\n" + body + "\n";
}

std::vector<KeyCase> key_cases() {
    const std::string medium = species_block(
        "name = \"medium\"\nkind = \"apolar_rod\"\n"
        "length = 2.5\narea_fraction = 0.5");
    const std::string polar = species_block(
        "name = \"polar\"\nkind = \"polar_rod\"\n"
        "area_fraction = 0.05");
    return {
        {"box.side", "[box]\nside = 45.5",
         [](const RunPlan& p) {
             EXPECT_EQ(p.engine.box.lx, 45.5);
             EXPECT_EQ(p.engine.box.ly, 45.5);
         }},
        {"box.side_in_polar_lengths", "[box]\nside_in_polar_lengths = 10",
         [](const RunPlan& p) {
             EXPECT_EQ(p.engine.box.lx, 45.0);  // 10 ℓ_p
             EXPECT_EQ(p.engine.box.ly, 45.0);
         }},
        {"drive.gamma", "[drive]\ngamma = 3.5",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.drive.gamma, 3.5); }},
        {"drive.frequency", "[drive]\nfrequency = 100",
         [](const RunPlan& p) { EXPECT_DOUBLE_EQ(p.engine.drive.angular_frequency, 200.0 * kPi); }},
        {"drive.angular_frequency", "[drive]\nangular_frequency = 1000.0",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.drive.angular_frequency, 1000.0); }},
        {"drive.gap", "[drive]\ngap = 1.8",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.drive.gap, 1.8); }},
        {"drive.gravity", "[drive]\ngravity = 5000.0",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.drive.gravity, 5000.0); }},
        {"species.name",
         species_block("name = \"tracer\"\nkind = \"polar_rod\"\ncount = 3") + medium,
         [](const RunPlan& p) { EXPECT_EQ(p.engine.species[0].name, "tracer"); }},
        {"species.kind", species_block("name = \"b\"\nkind = \"bead\"\ncount = 10"),
         [](const RunPlan& p) {
             ASSERT_EQ(p.engine.species.size(), 1u);
             EXPECT_EQ(p.engine.species[0].kind, BodyKind::bead);
             EXPECT_EQ(p.engine.species[0].shape.sphere_count(), 1u);
             EXPECT_EQ(p.engine.species[0].shape.max_radius, 0.4);
         }},
        {"species.length",
         polar + species_block("name = \"m\"\nkind = \"apolar_rod\"\nlength = 1.5\ncount = 5"),
         [](const RunPlan& p) {
             EXPECT_NEAR(p.engine.species[1].shape.extent, 1.5, 1e-12);
             EXPECT_EQ(p.engine.species[1].shape.sphere_count(), 5u);  // 4 × 1.5 − 1
         }},
        {"species.aspect_ratio",
         polar +
             species_block("name = \"m\"\nkind = \"apolar_rod\"\naspect_ratio = 5.625\ncount = 5"),
         [](const RunPlan& p) {
             EXPECT_NEAR(p.engine.species[1].shape.extent, 4.5, 1e-12);  // 0.8 mm × 5.625
             EXPECT_EQ(p.engine.species[1].shape.sphere_count(), 17u);
         }},
        {"species.area_fraction",
         species_block("name = \"p\"\nkind = \"polar_rod\"\narea_fraction = 0.1"),
         [](const RunPlan& p) {
             EXPECT_EQ(p.requested_area_fraction[0], 0.1);
             // 0.1 × 252² / 3.971 mm² = 1599.2 (Table S1's 800 at 0.05 is 799.6 rounded up).
             EXPECT_EQ(p.counts[0], 1599);
         }},
        {"species.count", species_block("name = \"p\"\nkind = \"polar_rod\"\ncount = 17"),
         [](const RunPlan& p) {
             EXPECT_EQ(p.counts[0], 17);
             EXPECT_LT(p.requested_area_fraction[0], 0.0);
         }},
        {"species.spheres",
         species_block("name = \"p\"\nkind = \"polar_rod\"\ncount = 1\nspheres = 7"),
         [](const RunPlan& p) { EXPECT_EQ(p.engine.species[0].shape.sphere_count(), 7u); }},
        {"species.mass", species_block("name = \"p\"\nkind = \"polar_rod\"\ncount = 1\nmass = 2.5"),
         [](const RunPlan& p) { EXPECT_EQ(p.engine.species[0].shape.mass, 2.5); }},
        {"species.density",
         polar + species_block("name = \"m\"\nkind = \"apolar_rod\"\nlength = 2.5\ncount = "
                               "5\ndensity = 0.2"),
         [](const RunPlan& p) {
             // The volumes of the union of spheres: 0.6364 mm³ (ℓ_a = 2.5 mm, 9 spheres) and
             // 3.119 mm³ (the polar rod, mass 1), 0.2 × 0.6364 / 3.119 = 0.0408 polar-rod masses;
             // the frustums the profiles bound hold 0.733 and 3.06 mm³, a bound the unions of
             // spheres stay below.
             const Shape& rod = p.engine.species[1].shape;
             EXPECT_NEAR(rod.mass, 0.2 * rod.volume / p.engine.species[0].shape.volume, 1e-12);
             EXPECT_NEAR(rod.mass, 0.0408, 0.0002);
         }},
        {"species.plate_friction",
         species_block("name = \"p\"\nkind = \"bead\"\ncount = 1\nplate_friction = 0.2"),
         [](const RunPlan& p) { EXPECT_EQ(p.engine.species[0].plate.friction, 0.2); }},
        {"species.plate_restitution",
         species_block("name = \"p\"\nkind = \"bead\"\ncount = 1\nplate_restitution = 0.5"),
         [](const RunPlan& p) { EXPECT_EQ(p.engine.species[0].plate.restitution, 0.5); }},
        {"collisions.friction", "[collisions]\nfriction = 0.1",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.body_body.friction, 0.1); }},
        {"collisions.restitution", "[collisions]\nrestitution = 0.6",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.body_body.restitution, 0.6); }},
        {"collisions.pair.species",
         kTwoSpecies + "[[collisions.pair]]\nspecies = [\"medium\", \"polar\"]\n",
         [](const RunPlan& p) {
             // Without coefficients the pair keeps [collisions]' values, in a full table.
             ASSERT_EQ(p.engine.body_body_by_pair.size(), 4u);
             for (const ContactCoefficients& c : p.engine.body_body_by_pair) {
                 EXPECT_EQ(c.friction, 0.05);
                 EXPECT_EQ(c.restitution, 0.30);
             }
         }},
        {"collisions.pair.friction",
         kTwoSpecies + "[[collisions.pair]]\nspecies = [\"medium\", \"polar\"]\nfriction = 0.2\n",
         [](const RunPlan& p) {
             EXPECT_EQ(p.engine.pair_coefficients(0, 1).friction, 0.2);
             EXPECT_EQ(p.engine.pair_coefficients(1, 0).friction, 0.2);  // both orders
             EXPECT_EQ(p.engine.pair_coefficients(0, 0).friction, 0.05);
             EXPECT_EQ(p.engine.pair_coefficients(1, 1).friction, 0.05);
             EXPECT_EQ(p.engine.pair_coefficients(0, 1).restitution, 0.30);
         }},
        {"collisions.pair.restitution",
         kTwoSpecies + "[collisions]\nrestitution = 0.4\n[[collisions.pair]]\n"
                       "species = [\"polar\", \"polar\"]\nrestitution = 0.9\n",
         [](const RunPlan& p) {
             EXPECT_EQ(p.engine.pair_coefficients(0, 0).restitution, 0.9);
             EXPECT_EQ(p.engine.pair_coefficients(0, 1).restitution, 0.4);
             EXPECT_EQ(p.engine.pair_coefficients(1, 1).restitution, 0.4);
         }},
        {"noise.mode", "[noise]\nmode = \"set\"\nepsilon = 3.5",
         [](const RunPlan& p) {
             EXPECT_EQ(p.engine.noise_mode, physics::NoiseMode::set);
             EXPECT_EQ(p.engine.noise_epsilon, 3.5);  // beyond the add rule's 0.5 /mm
         }},
        {"noise.epsilon", "[noise]\nepsilon = 0.25",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.noise_epsilon, 0.25); }},
        // Need a table file: ConfigFromCalibrationTable in test_calibration.cpp.
        {"noise.rotational_diffusion", "", {}},
        {"noise.calibration_table", "", {}},
        {"time.dt", "[time]\ndt = 2.5e-6",
         [](const RunPlan& p) {
             EXPECT_EQ(p.engine.dt, 2.5e-6);
             EXPECT_EQ(p.total_steps(), 400'000u);
         }},
        {"time.duration", "[time]\nduration = 0.5",
         [](const RunPlan& p) {
             EXPECT_EQ(p.control.duration, 0.5);
             EXPECT_EQ(p.total_steps(), 400'000u);
         }},
        {"time.periods", "[time]\nperiods = 20",
         [](const RunPlan& p) {
             EXPECT_NEAR(p.control.duration, 0.1, 1e-15);  // 20 × 5 ms
             EXPECT_EQ(p.total_steps(), 80'000u);
         }},
        {"output.interval", "[output]\ninterval = 0.02",
         [](const RunPlan& p) {
             EXPECT_EQ(p.control.output_interval, 0.02);
             EXPECT_EQ(p.steps_per_output(), 16000u);
         }},
        {"output.interval_periods", "[output]\ninterval_periods = 2",
         [](const RunPlan& p) {
             EXPECT_NEAR(p.control.output_interval, 0.01, 1e-15);  // 2 × 5 ms
             EXPECT_EQ(p.steps_per_output(), 8000u);
         }},
        {"output.checkpoint_interval", "[output]\ncheckpoint_interval = 5",
         [](const RunPlan& p) { EXPECT_EQ(p.control.checkpoint_interval, 5.0); }},
        {"run.seed", "[run]\nseed = 9223372036854775807",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.seed, 9223372036854775807u); }},
        {"run.threads", "[run]\nthreads = 4",
         [](const RunPlan& p) { EXPECT_EQ(p.control.threads, 4); }},
        // Resolving a config needs no GPU: run refuses an unusable one (test_run.cpp).
        {"run.backend", "[run]\nbackend = \"gpu\"",
         [](const RunPlan& p) { EXPECT_EQ(p.control.backend, BackendKind::gpu); }},
        {"initial.orientation", "[initial]\norientation = \"aligned\"",
         [](const RunPlan& p) { EXPECT_EQ(p.builder.orientation, InitialOrientation::aligned); }},
        {"initial.randomisation_sweeps", "[initial]\nrandomisation_sweeps = 0",
         [](const RunPlan& p) { EXPECT_EQ(p.builder.randomisation_sweeps, 0); }},
        {"time.steady_samples", "[time]\nsteady_samples = 200",
         [](const RunPlan& p) { EXPECT_EQ(p.control.steady_samples, 200); }},
        {"time.steady_series", "[time]\nsteady_series = \"segregation\"",
         [](const RunPlan& p) { EXPECT_EQ(p.control.steady_series, "segregation"); }},
        {"initial.domain_size", "[initial]\ndomain_size = 35.5",
         [](const RunPlan& p) { EXPECT_EQ(p.builder.domain_size, 35.5); }},
        {"engine.max_sweeps", "[engine]\nmax_sweeps = 17",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.max_sweeps, 17); }},
        {"engine.approach_tolerance", "[engine]\napproach_tolerance = 0.001",
         [](const RunPlan& p) { EXPECT_EQ(p.engine.approach_tolerance, 0.001); }},
    };
}

TEST(ConfigRoundTrip, EveryKeyOfTheTableHasACase) {
    std::set<std::string> covered, keys;
    for (const KeyCase& c : key_cases())
        covered.insert(c.key);
    for (const config::KeySpec& k : config::config_keys())
        keys.insert(k.path());
    EXPECT_EQ(covered, keys) << "add a case to key_cases() for each new key";
}

TEST(ConfigRoundTrip, EveryKeyLandsInThePlanAndSurvivesTheResolvedConfig) {
    for (const KeyCase& c : key_cases()) {
        if (!c.check) continue;
        SCOPED_TRACE(c.key + ":\n" + c.toml);
        const RunPlan plan = load(c.toml);
        c.check(plan);
        const RunPlan again = load_config_string(plan.config_toml, "resolved.toml");
        c.check(again);
        expect_same_plan(again, plan);
    }
}

TEST(ConfigRoundTrip, IntegersAreAcceptedForReals) {
    const RunPlan p = load("[drive]\ngamma = 5\ngap = 2\n[box]\nside = 40");
    EXPECT_EQ(p.engine.drive.gamma, 5.0);
    EXPECT_EQ(p.engine.drive.gap, 2.0);
    EXPECT_EQ(p.engine.box.lx, 40.0);
}

TEST(ConfigRoundTrip, ResolvedConfigNamesEveryKeyExplicitly) {
    const RunPlan p = load("[box]\nside_in_polar_lengths = 20\n" + kTwoSpecies);
    // The form the user chose stays; its alternative is shown as a comment with the same value.
    EXPECT_NE(p.config_toml.find("\nside_in_polar_lengths = 20.0\n"), std::string::npos);
    EXPECT_NE(p.config_toml.find("\n# side = 90.0\n"), std::string::npos);
    EXPECT_NE(p.config_toml.find("\nspheres = 9\n"), std::string::npos);
    EXPECT_NE(p.config_toml.find("\n# aspect_ratio = 3.125\n"), std::string::npos);
    EXPECT_NE(p.config_toml.find("\nseed = 1\n"), std::string::npos);
    expect_reloads_identically(p);
}

TEST(ConfigRoundTrip, AwkwardRealsReloadBitForBit) {
    // Values with no short decimal form must still come back as the same doubles.
    const RunPlan p = load(
        "[drive]\nangular_frequency = 1234.5678901234567\ngamma = 6.1\n"
        "[time]\ndt = 3.3333333333333333e-6\nperiods = 7.1\n"
        "[output]\ninterval_periods = 0.7\n" +
        species_block("kind = \"apolar_rod\"\naspect_ratio = 2.7\n"
                      "area_fraction = 0.123456789"));
    expect_reloads_identically(p);
}

// ---------------------------------------------------------------------------------------------
// Table S1

TEST(ConfigCounts, MatchThePapersTableS1AtFullSize) {
    struct Row {
        std::string kind_and_length;
        double phi;
        long long count;
    };
    const std::vector<Row> rows = {
        {"kind = \"bead\"", 0.05, 6317},
        {"kind = \"bead\"", 0.80, 101070},
        {"kind = \"apolar_rod\"\nlength = 1.0", 0.05, 5644},
        {"kind = \"apolar_rod\"\nlength = 1.0", 0.75, 84660},
        {"kind = \"apolar_rod\"\nlength = 1.5", 0.05, 3921},
        {"kind = \"apolar_rod\"\nlength = 1.5", 0.50, 39212},
        {"kind = \"apolar_rod\"\nlength = 2.0", 0.05, 2927},
        {"kind = \"apolar_rod\"\nlength = 2.0", 0.50, 29266},
        {"kind = \"apolar_rod\"\nlength = 2.5", 0.05, 2322},
        {"kind = \"apolar_rod\"\nlength = 2.5", 0.80, 37147},
        {"kind = \"apolar_rod\"\nlength = 4.5", 0.05, 1261},
        {"kind = \"apolar_rod\"\nlength = 4.5", 0.75, 18915},
        // The paper's 801 needs A = 3.964 mm²; 13 spheres give 3.971 mm² (docs/model.md §2).
        {"kind = \"polar_rod\"", 0.05, 800},
    };
    for (const Row& r : rows) {
        SCOPED_TRACE(r.kind_and_length + ", phi = " + std::to_string(r.phi));
        std::ostringstream toml;
        toml << "[box]\nside = 252\n[[species]]\n"
             << r.kind_and_length << "\narea_fraction = " << r.phi << "\n";
        EXPECT_EQ(load(toml.str()).counts.at(0), r.count);
    }
}

// ---------------------------------------------------------------------------------------------
// Errors

TEST(ConfigErrors, UnknownKeyNamesItsPathAndSuggestsTheNearestKey) {
    expect_invalid("[drive]\ngamm = 7", "drive.gamm",
                   {"did you mean drive.gamma?", "keys of [drive]", "test.toml line 2"});
    expect_invalid(kTwoSpecies + "lenght = 2.0\n", "species[1].lenght",
                   {"did you mean species[1].length?"});
    expect_invalid("[drive]\nGamma = 7", "drive.Gamma", {"did you mean drive.gamma?"});
    expect_invalid("[time]\ndurration = 2", "time.durration", {"did you mean time.duration?"});
    expect_invalid("[[collisions.pair]]\nspecies = [\"a\", \"b\"]\nfriktion = 0.1",
                   "collisions.pair[0].friktion", {"did you mean collisions.pair[0].friction?"});
    // Unknown top-level tables, and a key outside its table.
    expect_invalid("[drvie]\ngamma = 7", "drvie", {"did you mean drive?", "one of the tables"});
    expect_invalid("[[specie]]\nkind = \"bead\"", "specie", {"did you mean species?"});
    expect_invalid("seed = 3", "seed", {"did you mean run.seed (in [run])?"});
    expect_invalid("[time]\nseed = 3", "time.seed", {"did you mean run.seed (in [run])?"});
    // Nothing close: no guess, but the list of valid keys.
    expect_invalid("[box]\nzzzzzz = 1", "box.zzzzzz", {"side, side_in_polar_lengths"});
}

TEST(ConfigErrors, WrongTypeNamesTheTypeGivenAndExpected) {
    expect_invalid("[drive]\ngamma = \"fast\"", "drive.gamma",
                   {"a string (\"fast\")", "where a number is expected", "test.toml line 2"});
    expect_invalid("[run]\nthreads = 2.5", "run.threads", {"a float (2.5)", "an integer"});
    expect_invalid("[run]\nseed = true", "run.seed", {"a boolean", "an integer"});
    expect_invalid("[species]\nkind = \"bead\"", "species",
                   {"a table", "an array of tables ([[species]])"});
    expect_invalid("drive = 3", "drive", {"an integer (3)", "a table ([drive])"});
    expect_invalid("[initial]\norientation = 1", "initial.orientation", {"an integer", "a string"});
    expect_invalid("[run]\nbackend = \"cuda\"", "run.backend", {"\"cuda\"", "\"cpu\" or \"gpu\""});
    expect_invalid(kTwoSpecies + "[[collisions.pair]]\nspecies = \"polar\"",
                   "collisions.pair[0].species", {"a string", "an array of two strings"});
    expect_invalid(kTwoSpecies + "[[collisions.pair]]\nspecies = [\"polar\"]",
                   "collisions.pair[0].species", {"1 names", "an array of two strings"});
}

TEST(ConfigErrors, OutOfRangeNamesTheValueWithItsUnitAndTheRange) {
    expect_invalid("[drive]\ngap = -1", "drive.gap", {"= -1 mm", "allowed (0, 100] mm"});
    expect_invalid("[drive]\ngamma = 1e9", "drive.gamma", {"= 1e+09", "[0, 1000]"});
    expect_invalid("[drive]\ngamma = nan", "drive.gamma", {"nan", "[0, 1000]"});
    expect_invalid("[run]\nthreads = 0", "run.threads", {"= 0", "[1, 256]"});
    expect_invalid("[run]\nseed = -1", "run.seed", {"= -1", ">= 0"});
    expect_invalid("[time]\ndt = 0.01", "time.dt", {"0.01 s", "[1e-09, 0.001] s"});
    expect_invalid(species_block("kind = \"bead\"\narea_fraction = 0.95"),
                   "species[0].area_fraction", {"0.95", "(0, 0.9069]"});
    expect_invalid(species_block("kind = \"apolar_rod\"\nlength = 0.8\ncount = 1"),
                   "species[0].length", {"0.8 mm", "(0.8, 20] mm"});
    expect_invalid(species_block("kind = \"polar\"\ncount = 1"), "species[0].kind",
                   {"\"polar\"", "did you mean \"polar_rod\"?"});
    expect_invalid("[initial]\norientation = \"alinged\"", "initial.orientation",
                   {"did you mean \"aligned\"?"});
}

TEST(ConfigErrors, TomlSyntaxErrorGivesSourceLineAndColumn) {
    try {
        load("[drive]\ngamma = 7\ngap = = 2\n");
        ADD_FAILURE() << "accepted bad TOML";
    } catch (const ConfigSyntaxError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.source(), "test.toml");
        EXPECT_EQ(e.line(), 3);
        EXPECT_GT(e.column(), 0);
        EXPECT_NE(what.find("test.toml line 3, column "), std::string::npos) << what;
        EXPECT_NE(what.find("TOML syntax error"), std::string::npos) << what;
    }
    // A table defined twice is a TOML error too, not a silent merge.
    EXPECT_THROW(load("[drive]\ngamma = 7\n[drive]\ngap = 2\n"), ConfigSyntaxError);
}

TEST(ConfigErrors, MissingFileIsAFileErrorWithThePath) {
    const std::filesystem::path path = "/nonexistent/rodsea/run.toml";
    try {
        load_config_file(path);
        ADD_FAILURE() << "loaded a missing file";
    } catch (const FileError& e) {
        EXPECT_EQ(e.path(), path.string());
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos);
    }
    EXPECT_THROW(load_config_file(std::filesystem::temp_directory_path()), FileError);
}

TEST(ConfigErrors, AlternativeKeysExcludeEachOther) {
    expect_invalid("[box]\nside = 90\nside_in_polar_lengths = 20", "box.side_in_polar_lengths",
                   {"either box.side or box.side_in_polar_lengths, not both"});
    expect_invalid("[drive]\nangular_frequency = 1000\nfrequency = 100", "drive.angular_frequency",
                   {"not both"});
    expect_invalid("[time]\nduration = 1\nperiods = 10", "time.periods", {"not both"});
    expect_invalid("[output]\ninterval = 0.1\ninterval_periods = 10", "output.interval_periods",
                   {"not both"});
    expect_invalid(
        species_block("kind = \"apolar_rod\"\nlength = 2\naspect_ratio = 2.5\ncount = 1"),
        "species[0].aspect_ratio", {"not both"});
    expect_invalid(species_block("kind = \"bead\"\narea_fraction = 0.1\ncount = 5"),
                   "species[0].count", {"not both"});
}

TEST(ConfigErrors, SpeciesKeysMustFitTheKind) {
    expect_invalid(species_block("kind = \"bead\"\nlength = 2.5\ncount = 1"), "species[0].length",
                   {"no length for a bead", "applies to apolar_rod only"});
    expect_invalid(species_block("kind = \"polar_rod\"\naspect_ratio = 2\ncount = 1"),
                   "species[0].aspect_ratio", {"applies to apolar_rod only"});
    expect_invalid(species_block("name = \"x\"\ncount = 1"), "species[0].kind",
                   {"missing", "needs a kind", "test.toml line 1"});
    expect_invalid(species_block("kind = \"apolar_rod\"\ncount = 1"), "species[0].length",
                   {"missing", "aspect_ratio"});
    expect_invalid(species_block("kind = \"bead\""), "species[0].area_fraction",
                   {"missing", "count"});
    expect_invalid(species_block("kind = \"polar_rod\"\ncount = 1\nspheres = 1"),
                   "species[0].spheres", {"[2, 200]", "thick and a thin end"});
    expect_invalid(species_block("kind = \"bead\"\ncount = 1\nspheres = 3"), "species[0].spheres",
                   {"1 for a bead"});
    expect_invalid(species_block("name = \"a b\"\nkind = \"bead\"\ncount = 1"), "species[0].name",
                   {"\"a b\"", "letters, digits, _ and -"});
    expect_invalid(species_block("name = \"\"\nkind = \"bead\"\ncount = 1"), "species[0].name",
                   {"non-empty"});
}

TEST(ConfigErrors, CrossKeyChecksNameTheKey) {
    expect_invalid(species_block("name = \"m\"\nkind = \"bead\"\ncount = 1") +
                       species_block("name = \"m\"\nkind = \"polar_rod\"\ncount = 1"),
                   "species[1].name", {"\"m\"", "species[0] has it too"});
    expect_invalid(kTwoSpecies + "[[collisions.pair]]\nspecies = [\"polar\", \"mediun\"]",
                   "collisions.pair[0].species",
                   {"no species is named \"mediun\"", "did you mean \"medium\"?"});
    expect_invalid(kTwoSpecies +
                       "[[collisions.pair]]\nspecies = [\"polar\", \"medium\"]\n"
                       "[[collisions.pair]]\nspecies = [\"medium\", \"polar\"]",
                   "collisions.pair[1].species", {"same pair"});
    expect_invalid(species_block("kind = \"bead\"\ncount = 0"), "species",
                   {"0 bodies", "at least one body"});
    expect_invalid("species = []", "species", {"at least one [[species]]"});
    expect_invalid("[time]\nduration = 1e-6", "time.duration",
                   {"1e-06 s", ">= time.dt = 1.25e-06 s"});
    expect_invalid("[output]\ninterval = 1e-6", "output.interval", {"[1.25e-06 s, 1 s]"});
    expect_invalid("[time]\nduration = 0.1\n[output]\ninterval = 0.2", "output.interval",
                   {"0.2 s", "[1.25e-06 s, 0.1 s]"});
    expect_invalid("[output]\ninterval_periods = 1000", "output.interval_periods",
                   {"1000 periods (5 s)", "[1.25e-06 s, 1 s]"});
    // The box must hold twice the longest body (the ℓ_a = 4.5 mm rod).
    expect_invalid(
        "[box]\nside = 8\n" + species_block("kind = \"apolar_rod\"\nlength = 4.5\ncount = 1"),
        "box.side", {"8 mm", ">= 9 mm", "apolar_rod 'apolar_rod'"});
    // Each noise mode has its own ε range (kMaxNoiseEpsilonAdd and ...Set say why).
    expect_invalid("[noise]\nepsilon = 3.5", "noise.epsilon",
                   {"3.5 1/mm", "[0, 0.5] 1/mm", "noise.mode = \"add\""});
    expect_invalid("[noise]\nmode = \"set\"\nepsilon = 25", "noise.epsilon", {"25 1/mm"});
    // A mass and a density are two answers to one question.
    expect_invalid(species_block("kind = \"bead\"\ncount = 1\nmass = 0.1\ndensity = 0.2"),
                   "species[0].density", {"alternatives"});
    // The engine's own validation comes through: the paper's 1.2 mm gap cannot hold the polar
    // rod's 1.375 mm thick end.
    expect_invalid("[drive]\ngap = 1.2", "drive.gap", {"1.2 mm", "> 1.375 mm", "polar_rod"});
    // A gap the sphere fits but a body started 1 µm above the base does not: named by its key,
    // not by the body the start's check would refuse.
    expect_invalid("[drive]\ngap = 1.3755", "drive.gap",
                   {"1.3755 mm", "> 1.376 mm", "0.001 mm above the base"});
    // A step inside time.dt's range but far too long for the drive: named by its key, not by a
    // body of the start or a blow-up two steps in.
    expect_invalid("[time]\ndt = 1e-3", "time.dt",
                   {"0.001 s", "at most 0.000228746 s", "plates' peak speed"});
}

TEST(ConfigErrors, RotationalDiffusionNeedsACalibrationTable) {
    expect_invalid("[noise]\nrotational_diffusion = 0.026", "noise.calibration_table",
                   {"missing", "rodsea calibrate", "rotational_diffusion"});
    expect_invalid("[noise]\ncalibration_table = \"cal.csv\"", "noise.calibration_table",
                   {"only with noise.rotational_diffusion"});
}

// ---------------------------------------------------------------------------------------------
// CHOICEs

bool has_line_starting(const std::vector<std::string>& lines, const std::string& start) {
    for (const std::string& l : lines)
        if (l.rfind(start, 0) == 0) return true;
    return false;
}

TEST(ConfigChoices, ListEveryChoiceInForceAndWhetherItIsTheDefault) {
    const RunPlan p = load("");
    for (const char* start :
         {"drive.gap = 1.4 mm (the CHOICE default; the paper's 1.2 mm",
          "drive.gravity = 9810 mm/s² (", "time.dt = 1.25e-06 s (the CHOICE default",
          "species[0].spheres = 13 (polar_rod 'polar'",
          "species[1].spheres = 9 (apolar_rod 'medium'", "species[1].mass = 0.2 mass units (",
          "noise.mode = \"add\" (the CHOICE default", "noise.epsilon = 0 1/mm (",
          "sphere chains:"}) {
        EXPECT_TRUE(has_line_starting(p.choices, start)) << start;
    }
    // The polar rod's mass is the unit, not a CHOICE; plate coefficients of rods are the paper's.
    EXPECT_FALSE(has_line_starting(p.choices, "species[0].mass"));
    EXPECT_FALSE(has_line_starting(p.choices, "species[1].plate_friction"));
    EXPECT_EQ(p.choices.size(), 9u);

    const RunPlan q = load("[drive]\ngap = 1.6\n" +
                           species_block("kind = \"bead\"\ncount = 5\nplate_friction = 0.02"));
    EXPECT_TRUE(
        has_line_starting(q.choices, "drive.gap = 1.6 mm (overrides the CHOICE default 1.4 mm;"));
    EXPECT_TRUE(has_line_starting(
        q.choices, "species[0].plate_friction = 0.02 (bead 'bead'; overrides the CHOICE default"));
    EXPECT_TRUE(has_line_starting(q.choices,
                                  "species[0].plate_restitution = 0.3 (bead 'bead'; "
                                  "the CHOICE default"));
    // No polar rods: the form of their noise kick is not in force; no rods: nor the chains.
    EXPECT_FALSE(has_line_starting(q.choices, "noise.epsilon"));
    EXPECT_FALSE(has_line_starting(q.choices, "sphere chains"));
}

// ---------------------------------------------------------------------------------------------
// Files, docs and examples

TEST(ConfigFile, LoadsFromDiskLikeFromAString) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("rodsea-config-" + std::to_string(::getpid()) + ".toml");
    const std::string text = "[box]\nside = 60\n" + kTwoSpecies;
    std::ofstream(path) << text;
    const RunPlan from_file = load_config_file(path);
    std::filesystem::remove(path);
    expect_same_plan(from_file, load(text));
}

TEST(ConfigReference, DocsMatchTheCode) {
    const std::filesystem::path path = std::filesystem::path(RODSEA_SOURCE_DIR) / "docs/config.md";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path << " is missing; generate it with "
                    << "`rodsea config --reference > docs/config.md`";
    std::ostringstream committed;
    committed << in.rdbuf();
    EXPECT_TRUE(committed.str() == config_reference_markdown())
        << path << " is out of date with the key table (src/rodsea/config/schema.cpp); "
        << "regenerate it with `rodsea config --reference > docs/config.md`";
}

TEST(ConfigExamples, EveryExampleLoadsAndReloads) {
    const std::filesystem::path dir = std::filesystem::path(RODSEA_SOURCE_DIR) / "examples";
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".toml") continue;
        SCOPED_TRACE(entry.path().string());
        names.insert(entry.path().filename().string());
        const RunPlan plan = load_config_file(entry.path(), calibration_table_lookup());
        expect_reloads_identically(plan);
    }
    for (const char* name : {"demo.toml", "fig1-rods-vs-density.toml", "fig1-noise.toml",
                             "fig4-aspect-ratio.toml", "figS-beads.toml", "largest.toml"}) {
        EXPECT_TRUE(names.count(name)) << name;
    }
}

TEST(ConfigExamples, DemoIsSmallAndFigureFilesAreThePapersSize) {
    const std::filesystem::path dir = std::filesystem::path(RODSEA_SOURCE_DIR) / "examples";
    const RunPlan demo = load_config_file(dir / "demo.toml");
    EXPECT_EQ(demo.engine.box.lx, 30.0);
    EXPECT_EQ(demo.total_steps(), 160'000u);    // 0.2 s at the default 1.25 µs
    EXPECT_EQ(demo.steps_per_output(), 8000u);  // 0.01 s
    EXPECT_EQ(demo.requested_area_fraction, (std::vector<double>{0.05, 0.30}));

    const RunPlan largest = load_config_file(dir / "largest.toml");
    EXPECT_EQ(largest.engine.box.lx, 252.0);
    EXPECT_EQ(largest.counts, (std::vector<long long>{800, 101070}));  // Table S1
    const RunPlan fig4 = load_config_file(dir / "fig4-aspect-ratio.toml");
    EXPECT_EQ(fig4.counts, (std::vector<long long>{800, 18915}));  // ℓ_a = 4.5 at φ_a = 0.75
}

TEST(ConfigDidYouMean, EditDistanceCountsTranspositionsAsOneEdit) {
    EXPECT_EQ(config::edit_distance("lenght", "length"), 1u);
    EXPECT_EQ(config::edit_distance("gamm", "gamma"), 1u);
    EXPECT_EQ(config::edit_distance("GAMMA", "gamma"), 0u);
    EXPECT_EQ(config::edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(config::edit_distance("", "abc"), 3u);
    EXPECT_EQ(config::closest_match("sead", {"seed", "threads"}), "seed");
    EXPECT_EQ(config::closest_match("xyz", {"seed", "threads"}), std::nullopt);
}

}  // namespace
}  // namespace rodsea
