#include "rodsea/calibration/calibration_grid.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodsea/config/config_file.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

const char* const kCalibrationKeysHelp =
    R"(  [calibrate]
  species   "polar_rod" (default), "apolar_rod" or "bead", with the paper's shapes and
            coefficients (docs/model.md §2, §3)
  length    mm, apolar rods only: ℓ_a, [1, 20] (default 2.5)
  noise_mode "add" (default: ω_z += ε|u_n|η) or "set" (ω_z = ε|u_n|η), docs/model.md §3
  epsilon   1/mm, noise amplitudes, each in [0, 0.5] under add, [0, 5] under set
            (default [0.0])
  gap       mm, plate gaps w, each in (largest sphere diameter, 20] (default [1.40])
  dt        s, time steps, each in [1e-8, 1e-4] (default [1.25e-6])
  copies    independent bodies per point, [2, 10000] (default 8); at most 10^5
            simulations in all (points × copies)
  duration  s measured per copy, [0.1, 1e5]: at least 20 drive periods (default 2.0)
  warmup    s discarded per copy before measuring, [0, 1e5] (default 0.2)
  seed      random seed of starts and noise, [0, 2^63] (default 1)
)";

namespace {

const std::vector<std::string> kKeys{"species", "length", "noise_mode", "epsilon", "gap",
                                     "dt",      "copies", "duration",   "warmup",  "seed"};

std::string key(const std::string& name) {
    return "calibrate." + name;
}

double number(const toml::node& node, const std::string& name) {
    if (const auto v = node.value<double>()) return *v;
    throw InvalidParameter(key(name), "not a number", "a number");
}

double in_range(const toml::node& node, const std::string& name, double lo, double hi,
                const std::string& unit) {
    const double v = number(node, name);
    require_in_closed_range(key(name), v, lo, hi, unit);
    return v;
}

std::vector<double> number_list(const toml::table& t, const std::string& name, double lo, double hi,
                                const std::string& unit, std::vector<double> fallback) {
    const toml::node* node = t.get(name);
    if (!node) return fallback;
    std::vector<double> values;
    if (const toml::array* a = node->as_array()) {
        for (const toml::node& item : *a)
            values.push_back(in_range(item, name, lo, hi, unit));
    } else {
        values.push_back(in_range(*node, name, lo, hi, unit));
    }
    if (values.empty()) throw InvalidParameter(key(name), "[]", "at least one value");
    return values;
}

}  // namespace

std::vector<SingleBodyExperiment> CalibrationGrid::experiments() const {
    std::vector<SingleBodyExperiment> out;
    for (double w : gap)
        for (double step : dt)
            for (double e : epsilon) {
                SingleBodyExperiment x;
                x.species = species;
                x.drive.gap = w;
                x.dt = step;
                x.epsilon = e;
                x.noise_mode = noise_mode;
                x.copies = copies;
                x.duration = duration;
                x.warmup = warmup;
                x.seed = seed;
                out.push_back(x);
            }
    return out;
}

CalibrationGrid parse_calibration_grid(std::string_view text, const std::string& source) {
    toml::table root;
    try {
        root = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        throw ConfigSyntaxError(source, static_cast<long>(e.source().begin.line),
                                static_cast<long>(e.source().begin.column),
                                std::string(e.description()));
    }
    for (const auto& [name, node] : root) {
        (void)node;
        if (name.str() != "calibrate")
            throw InvalidParameter(std::string(name.str()), "a table of " + source,
                                   "[calibrate] only", "see rodsea calibrate --help");
    }
    const toml::table* t = root["calibrate"].as_table();
    if (!t) throw InvalidParameter("calibrate", "missing", "a [calibrate] table");
    for (const auto& [name, node] : *t) {
        (void)node;
        const std::string given(name.str());
        if (std::find(kKeys.begin(), kKeys.end(), given) != kKeys.end()) continue;
        const auto guess = config::closest_match(given, kKeys);
        throw InvalidParameter(key(given), "an unknown key",
                               "one of species, length, noise_mode, epsilon, gap, "
                               "dt, copies, duration, warmup, seed",
                               guess ? "did you mean '" + *guess + "'?" : "");
    }

    CalibrationGrid g;
    const std::string kind = (*t)["species"].value_or(std::string("polar_rod"));
    if (t->get("length") && kind != "apolar_rod")
        throw InvalidParameter(key("length"), "given", "only with species = \"apolar_rod\"");
    if (kind == "polar_rod") {
        g.species = polar_rod_species();
    } else if (kind == "apolar_rod") {
        const double length =
            t->get("length") ? in_range(*t->get("length"), "length", 1.0, 20.0, "mm") : 2.5;
        g.species = apolar_rod_species(length);
    } else if (kind == "bead") {
        g.species = bead_species();
    } else {
        throw InvalidParameter(key("species"), "'" + kind + "'",
                               "\"polar_rod\", \"apolar_rod\" or \"bead\"");
    }
    const toml::node* mode_node = t->get("noise_mode");
    if (mode_node && !mode_node->is_string())
        throw InvalidParameter(key("noise_mode"), "not text", "\"add\" or \"set\"");
    const std::string mode = mode_node ? *mode_node->value<std::string>() : std::string("add");
    if (mode != "add" && mode != "set")
        throw InvalidParameter(key("noise_mode"), "'" + mode + "'", "\"add\" or \"set\"");
    g.noise_mode = mode == "set" ? physics::NoiseMode::set : physics::NoiseMode::add;
    g.epsilon = number_list(*t, "epsilon", 0.0, max_noise_epsilon(g.noise_mode), "1/mm", g.epsilon);
    // The largest sphere must fit between the plates (docs/model.md §1), with room to move.
    const double thickest = 2.0 * g.species.shape.max_radius;
    g.gap = number_list(*t, "gap", 0.0, 20.0, "mm", g.gap);
    for (double w : g.gap)
        if (w <= thickest)
            throw InvalidParameter(
                key("gap"), format_number(w) + " mm", "> " + format_number(thickest) + " mm",
                "the " + kind + " has a sphere of diameter " + format_number(thickest) + " mm");
    g.dt = number_list(*t, "dt", 1e-8, 1e-4, "s", g.dt);
    if (const toml::node* n = t->get("copies"))
        g.copies = static_cast<int>(in_range(*n, "copies", 2, 10000, ""));
    // C(t) is fitted over lags up to a quarter of a copy, one drive period apart: 20 periods give
    // 5 lags (0.1 s at the paper's 200 Hz); fewer fit nothing and D_r came out as 0 ± 0.
    const double period = 2.0 * std::numbers::pi / DriveParameters{}.angular_frequency;
    if (const toml::node* n = t->get("duration"))
        g.duration = in_range(*n, "duration", 20.0 * period * (1.0 - 1e-9), 1e5, "s");
    if (const toml::node* n = t->get("warmup")) g.warmup = in_range(*n, "warmup", 0.0, 1e5, "s");
    if (const toml::node* n = t->get("seed"))
        g.seed = static_cast<std::uint64_t>(in_range(*n, "seed", 0.0, 9.2e18, ""));
    if (const toml::node* n = t->get("copies");
        n && std::floor(number(*n, "copies")) != number(*n, "copies"))
        throw InvalidParameter(key("copies"), format_number(number(*n, "copies")),
                               "a whole number");
    // Every point × copy is one simulation held in memory while it runs, and a row of results.
    constexpr double kMaxSimulations = 1e5;
    const double simulations = static_cast<double>(g.epsilon.size()) *
                               static_cast<double>(g.gap.size()) *
                               static_cast<double>(g.dt.size()) * g.copies;
    if (simulations > kMaxSimulations)
        throw InvalidParameter(
            key("copies"), std::to_string(g.copies),
            "at most " + format_number(kMaxSimulations) + " simulations in all (points × copies)",
            format_number(simulations) + " from " + std::to_string(g.epsilon.size()) +
                " epsilon × " + std::to_string(g.gap.size()) + " gap × " +
                std::to_string(g.dt.size()) + " dt points × " + std::to_string(g.copies) +
                " copies");
    return g;
}

}  // namespace rodsea
