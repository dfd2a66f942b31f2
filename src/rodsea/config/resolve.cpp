#include "rodsea/config/detail/resolve.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>

#include "rodsea/builder/placement.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/config/schema.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"

namespace rodsea::config {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::string shown(const TableValues& t, std::string_view table, std::string_view key) {
    return find_key(table, key)->shown(t.at(key));
}

std::string seconds(double s) {
    return format_number(s) + " s";
}

}  // namespace

std::vector<TableValues> default_species() {
    TableValues polar, medium;
    polar.path = "species[0]";
    polar.entries = {{"name", {std::string("polar"), 0}},
                     {"kind", {std::string("polar_rod"), 0}},
                     {"area_fraction", {0.05, 0}}};
    medium.path = "species[1]";
    medium.entries = {{"name", {std::string("medium"), 0}},
                      {"kind", {std::string("apolar_rod"), 0}},
                      {"length", {2.5, 0}},
                      {"area_fraction", {0.50, 0}}};
    return {polar, medium};
}

namespace {

// Keys whose default is fixed (not kind-dependent) and whose alternative was not given.
void fill_defaults(TableValues& t, std::string_view table) {
    for (const KeySpec* spec : keys_of(table)) {
        if (t.has(spec->name) || !spec->default_value) continue;
        if (!spec->alternative.empty() && t.has(spec->alternative)) continue;
        t.entries[spec->name] = {*spec->default_value, 0};
    }
}

// D_r needs the table to turn it into ε; a table without D_r would be silently unused.
void check_noise(const TableValues& noise, const std::string& source) {
    if (noise.has("rotational_diffusion") && !noise.has("calibration_table"))
        throw InvalidParameter(
            "noise.calibration_table", "missing",
            "the calibration.csv of `rodsea calibrate` (docs/validation.md)",
            join_why("noise.rotational_diffusion is turned into ε through that table",
                     noise.where("rotational_diffusion", source)));
    if (noise.has("calibration_table") && !noise.has("rotational_diffusion"))
        throw InvalidParameter(
            "noise.calibration_table", toml_literal(noise.at("calibration_table")),
            "only with noise.rotational_diffusion",
            join_why("the table turns D_r into ε; with noise.epsilon it is not used",
                     noise.where("calibration_table", source)));
}

// noise.rotational_diffusion → noise.epsilon through the table, measured at this run's gap and
// dt. The resolved config then holds ε (so that a stored run never needs the table again) and
// D_r as its commented equivalent.
double epsilon_from_calibration(ConfigValues& c, const EngineParameters& engine,
                                const EpsilonLookup& lookup) {
    TableValues& noise = c.one("noise");
    if (!lookup)
        throw InvalidParameter("noise.rotational_diffusion",
                               toml_literal(noise.at("rotational_diffusion")) + " rad²/s",
                               "noise.epsilon here",
                               "the program reading this config was given no reader of "
                               "calibration tables (calibration_table_lookup())");
    std::filesystem::path table = noise.text("calibration_table");
    const std::filesystem::path config_dir = std::filesystem::path(c.source).parent_path();
    if (table.is_relative() && std::filesystem::is_regular_file(c.source))
        table = config_dir / table;  // relative to the config file, like a path in a Makefile
    const double d_r = noise.real("rotational_diffusion");
    const double epsilon = lookup(table, engine.drive.gap, engine.dt, engine.noise_mode, d_r);
    const long line = noise.entries.at("rotational_diffusion").line;
    noise.entries.erase("rotational_diffusion");
    noise.entries.erase("calibration_table");
    noise.entries["epsilon"] = {epsilon, line};
    c.equivalents["noise.rotational_diffusion"] = d_r;
    return epsilon;
}

void check_unique_names(const std::vector<TableValues>& species, const std::string& source) {
    for (size_t i = 0; i < species.size(); ++i) {
        for (size_t j = 0; j < i; ++j) {
            if (species[i].text("name") == species[j].text("name")) {
                throw InvalidParameter(
                    species[i].key_path("name"), toml_literal(species[i].at("name")),
                    "a name no other species has",
                    join_why(species[j].path + " has it too", species[i].where("name", source)));
            }
        }
    }
}

// [[collisions.pair]] → the symmetric species × species table (empty when there are no pairs).
std::vector<ContactCoefficients> pair_table(std::vector<TableValues>& pairs,
                                            const std::vector<TableValues>& species,
                                            const TableValues& collisions,
                                            const std::string& source) {
    if (pairs.empty()) return {};
    const size_t n = species.size();
    std::vector<std::string> names;
    for (const TableValues& s : species)
        names.push_back(s.text("name"));
    std::vector<ContactCoefficients> table(
        n * n, {collisions.real("friction"), collisions.real("restitution")});
    std::set<std::pair<size_t, size_t>> seen;
    for (TableValues& pair : pairs) {
        if (!pair.has("species")) {
            throw InvalidParameter(pair.key_path("species"), "missing",
                                   find_key("collisions.pair", "species")->allowed_text(),
                                   "every [[collisions.pair]] names its two species");
        }
        const auto& given = std::get<std::vector<std::string>>(pair.at("species"));
        size_t index[2] = {0, 0};
        for (int side = 0; side < 2; ++side) {
            const auto it = std::find(names.begin(), names.end(), given[side]);
            if (it == names.end()) {
                const auto guess = closest_match(given[side], names);
                std::string allowed;
                for (const std::string& name : names)
                    allowed += (allowed.empty() ? "\"" : ", \"") + name + "\"";
                throw InvalidParameter(
                    pair.key_path("species"), toml_literal(pair.at("species")),
                    "names of [[species]]: " + allowed,
                    join_why("no species is named \"" + given[side] + "\"" +
                                 (guess ? "; did you mean \"" + *guess + "\"?" : ""),
                             pair.where("species", source)));
            }
            index[side] = static_cast<size_t>(it - names.begin());
        }
        const auto key = std::minmax(index[0], index[1]);
        if (!seen.insert(key).second) {
            throw InvalidParameter(pair.key_path("species"), toml_literal(pair.at("species")),
                                   "each pair of species once",
                                   join_why("an earlier [[collisions.pair]] has the same pair",
                                            pair.where("species", source)));
        }
        if (!pair.has("friction")) pair.entries["friction"] = {collisions.real("friction"), 0};
        if (!pair.has("restitution"))
            pair.entries["restitution"] = {collisions.real("restitution"), 0};
        const ContactCoefficients c{pair.real("friction"), pair.real("restitution")};
        table[index[0] * n + index[1]] = c;
        table[index[1] * n + index[0]] = c;
    }
    return table;
}

}  // namespace

void check_alternatives(const TableValues& t, std::string_view table, const std::string& source) {
    for (const KeySpec* spec : keys_of(table)) {
        if (spec->alternative.empty() || !t.has(spec->name) || !t.has(spec->alternative)) continue;
        const KeySpec* alt = find_key(table, spec->alternative);
        if (alt < spec) continue;  // reported once, naming the key that comes second
        throw InvalidParameter(
            t.key_path(alt->name), alt->shown(t.at(alt->name)),
            "either " + t.key_path(spec->name) + " or " + t.key_path(alt->name) + ", not both",
            join_why("they are alternatives", t.where(alt->name, source)));
    }
}

namespace {

// Every table present, every default in place, each table consistent on its own.
void complete_tables(ConfigValues& c) {
    for (const TableSpec& table : config_tables()) {
        if (table.array) continue;
        std::vector<TableValues>& tables = c.all(table.path);
        if (tables.empty()) tables.push_back(TableValues{table.path, 0, {}});
        if (table.path == "noise") check_noise(tables.front(), c.source);
        check_alternatives(tables.front(), table.path, c.source);
        fill_defaults(tables.front(), table.path);
    }
    if (c.tables.find("species") == c.tables.end()) c.tables["species"] = default_species();
    std::vector<TableValues>& species = c.all("species");
    if (species.empty()) {
        throw InvalidParameter("species", "an empty array", "at least one [[species]] table");
    }
    for (TableValues& s : species)
        complete_species(s, c.source);
    check_unique_names(species, c.source);
}

void build_box_and_drive(ConfigValues& c, EngineParameters& e) {
    const TableValues& box = c.one("box");
    const double side =
        box.has("side") ? box.real("side") : box.real("side_in_polar_lengths") * kPolarRodLength;
    e.box = {side, side};
    if (box.has("side"))
        c.equivalents["box.side_in_polar_lengths"] = side / kPolarRodLength;
    else
        c.equivalents["box.side"] = side;

    const TableValues& drive = c.one("drive");
    e.drive.gamma = drive.real("gamma");
    if (drive.has("frequency")) {
        e.drive.angular_frequency = kTwoPi * drive.real("frequency");
        c.equivalents["drive.angular_frequency"] = e.drive.angular_frequency;
    } else {
        e.drive.angular_frequency = drive.real("angular_frequency");
        c.equivalents["drive.frequency"] = e.drive.angular_frequency / kTwoPi;
    }
    e.drive.gap = drive.real("gap");
    e.drive.gravity = drive.real("gravity");
}

// Species, their counts (N = round(φL²/A) or as given) and the collision coefficients.
void build_bodies(ConfigValues& c, RunPlan& plan) {
    EngineParameters& e = plan.engine;
    const double box_area = e.box.lx * e.box.ly;
    for (const TableValues& s : c.all("species")) {
        e.species.push_back(make_species(s));
        const Shape& shape = e.species.back().shape;
        if (s.has("area_fraction")) {
            const double phi = s.real("area_fraction");
            plan.counts.push_back(count_for_area_fraction(phi, e.box, shape));
            plan.requested_area_fraction.push_back(phi);
            c.equivalents[s.key_path("count")] = std::int64_t{plan.counts.back()};
        } else {
            plan.counts.push_back(s.integer("count"));
            plan.requested_area_fraction.push_back(-1.0);
            c.equivalents[s.key_path("area_fraction")] =
                static_cast<double>(plan.counts.back()) * shape.projected_area / box_area;
        }
        if (e.species.back().kind == BodyKind::apolar_rod) {
            if (s.has("length"))
                c.equivalents[s.key_path("aspect_ratio")] = s.real("length") / kApolarRodDiameter;
            else
                c.equivalents[s.key_path("length")] = apolar_length(s);
        }
    }
    const TableValues& collisions = c.one("collisions");
    e.body_body = {collisions.real("friction"), collisions.real("restitution")};
    e.body_body_by_pair =
        pair_table(c.all("collisions.pair"), c.all("species"), collisions, c.source);
}

void build_time_and_output(ConfigValues& c, RunPlan& plan) {
    const double period = kTwoPi / plan.engine.drive.angular_frequency;
    const TableValues& time = c.one("time");
    plan.engine.dt = time.real("dt");
    if (time.has("duration")) {
        plan.control.duration = time.real("duration");
        c.equivalents["time.periods"] = plan.control.duration / period;
    } else {
        plan.control.duration = time.real("periods") * period;
        c.equivalents["time.duration"] = plan.control.duration;
    }
    const TableValues& output = c.one("output");
    if (output.has("interval")) {
        plan.control.output_interval = output.real("interval");
        c.equivalents["output.interval_periods"] = plan.control.output_interval / period;
    } else {
        plan.control.output_interval = output.real("interval_periods") * period;
        c.equivalents["output.interval"] = plan.control.output_interval;
    }
    plan.control.checkpoint_interval = output.real("checkpoint_interval");
    plan.control.steady_samples = time.integer("steady_samples");
    plan.control.steady_series = time.text("steady_series");
}

void build_the_rest(ConfigValues& c, RunPlan& plan, const EpsilonLookup& epsilon) {
    plan.engine.noise_mode =
        c.one("noise").text("mode") == "set" ? physics::NoiseMode::set : physics::NoiseMode::add;
    plan.engine.noise_epsilon = c.one("noise").has("rotational_diffusion")
                                    ? epsilon_from_calibration(c, plan.engine, epsilon)
                                    : c.one("noise").real("epsilon");
    const TableValues& run = c.one("run");
    plan.engine.seed = static_cast<std::uint64_t>(run.integer("seed"));
    plan.control.threads = static_cast<int>(run.integer("threads"));
    parse_backend(run.text("backend"), plan.control.backend);  // one of the key's options
    const TableValues& initial = c.one("initial");
    const std::string& orientation = initial.text("orientation");
    plan.builder.orientation = orientation == "aligned"         ? InitialOrientation::aligned
                               : orientation == "polar_aligned" ? InitialOrientation::polar_aligned
                                                                : InitialOrientation::isotropic;
    plan.builder.randomisation_sweeps = static_cast<int>(initial.integer("randomisation_sweeps"));
    plan.builder.domain_size = initial.real("domain_size");
    const TableValues& engine = c.one("engine");
    plan.engine.max_sweeps = static_cast<int>(engine.integer("max_sweeps"));
    plan.engine.approach_tolerance = engine.real("approach_tolerance");
}

// Checks across keys, each naming the key the user wrote.
void check_across_keys(const ConfigValues& c, const RunPlan& plan) {
    const EngineParameters& e = plan.engine;
    // Each noise mode has its own ε range (kMaxNoiseEpsilonAdd and ...Set say why).
    if (const TableValues& noise = c.one("noise");
        noise.has("epsilon") && e.noise_epsilon > max_noise_epsilon(e.noise_mode))
        throw InvalidParameter(
            noise.key_path("epsilon"), shown(noise, "noise", "epsilon"),
            "[0, " + format_number(max_noise_epsilon(e.noise_mode)) + "] 1/mm",
            join_why(std::string("the range of noise.mode = \"") + to_string(e.noise_mode) + "\"" +
                         (e.noise_mode == physics::NoiseMode::add
                              ? ": added kicks accumulate, and above it the rods spin up "
                                "without bound"
                              : ""),
                     noise.where("epsilon", c.source)));
    // The box first: a box too small for its bodies also rounds every count to 0.
    const Species* longest = &e.species.front();
    for (const Species& s : e.species)
        if (s.shape.extent > longest->shape.extent) longest = &s;
    const TableValues& box = c.one("box");
    if (e.box.lx < 2.0 * longest->shape.extent) {
        const std::string key = box.has("side") ? "side" : "side_in_polar_lengths";
        throw InvalidParameter(
            box.key_path(key), shown(box, "box", key),
            ">= " + format_number(2.0 * longest->shape.extent) + " mm",
            join_why("twice the longest body, " + std::string(to_string(longest->kind)) + " '" +
                         longest->name + "' (" + format_number(longest->shape.extent) +
                         " mm), so that no body meets two images of another",
                     box.where(key, c.source)));
    }

    long long total = 0;
    for (const long long n : plan.counts)
        total += n;
    if (total > kMaxBodies) {
        const auto& all = c.all("species");
        std::size_t largest = 0;
        for (std::size_t s = 1; s < plan.counts.size(); ++s)
            if (plan.counts[s] > plan.counts[largest]) largest = s;
        const TableValues& s = all[largest];
        const std::string key = s.has("area_fraction") ? "area_fraction" : "count";
        throw InvalidParameter(
            s.key_path(key), shown(s, "species", key),
            "at most " + std::to_string(kMaxBodies) + " bodies in all species together",
            join_why(std::to_string(total) + " bodies in a " + format_number(e.box.lx) + " × " +
                         format_number(e.box.ly) + " mm box (" +
                         std::to_string(plan.counts[largest]) + " of them " +
                         e.species[largest].name +
                         "): a smaller box.side or smaller area fractions",
                     s.where(key, c.source)));
    }
    if (total < 1) {
        throw InvalidParameter("species", "0 bodies in total", "at least one body",
                               "every species has count 0 or rounds to 0 bodies");
    }

    const TableValues& time = c.one("time");
    const std::string duration_key = time.has("duration") ? "duration" : "periods";
    if (!(plan.control.duration >= e.dt)) {
        throw InvalidParameter(
            time.key_path(duration_key), shown(time, "time", duration_key),
            ">= time.dt = " + seconds(e.dt),
            join_why("the run must take a step", time.where(duration_key, c.source)));
    }

    const TableValues& output = c.one("output");
    const std::string interval_key = output.has("interval") ? "interval" : "interval_periods";
    if (!(plan.control.output_interval >= e.dt) ||
        !(plan.control.output_interval <= plan.control.duration)) {
        const std::string given = shown(output, "output", interval_key);
        throw InvalidParameter(output.key_path(interval_key),
                               interval_key == "interval"
                                   ? given
                                   : given + " (" + seconds(plan.control.output_interval) + ")",
                               "[time.dt, the run's duration] = [" + seconds(e.dt) + ", " +
                                   seconds(plan.control.duration) + "]",
                               output.where(interval_key, c.source));
    }
}

// The step resolves a collision while no sphere crosses more than a quarter of the smallest
// radius in it (planar_speed_bound, the blow-up guard). Bodies leave the plates at up to about
// twice the plates' peak speed AΩ and start at up to the builder's random speeds: a time step
// whose bound is not four times the one and twice the other blows up in its first periods, or is
// refused at the start naming a body, never the key to change.
void check_time_step_resolves_the_drive(const EngineParameters& engine) {
    double start = 0.0;  // mm/s, the fastest sphere of a fresh start
    for (const Species& s : engine.species)
        start = std::max(
            start, std::sqrt(2.0) * kStartSpeed + std::sqrt(3.0) * kStartSpin * s.shape.extent);
    const double plates = engine.drive.amplitude() * engine.drive.angular_frequency;
    const double needed = std::max(4.0 * plates, 2.0 * start);
    const double bound = planar_speed_bound(engine);
    if (bound >= needed) return;
    const double largest = engine.dt * bound / needed;
    const std::string why =
        4.0 * plates >= 2.0 * start
            ? "four times the plates' peak speed AΩ, " + format_number(plates) + " mm/s"
            : "twice the fastest sphere of a fresh start, " + format_number(start) + " mm/s";
    throw InvalidParameter("time.dt", format_number(engine.dt) + " s",
                           "at most " + format_number(largest) + " s",
                           "a sphere at " + format_number(needed) + " mm/s, " + why +
                               ", must move less than a quarter of the smallest sphere radius "
                               "in a step");
}

}  // namespace

RunPlan resolve(ConfigValues& c, const EpsilonLookup& epsilon) {
    complete_tables(c);
    RunPlan plan;
    build_box_and_drive(c, plan.engine);
    build_bodies(c, plan);
    build_time_and_output(c, plan);
    build_the_rest(c, plan, epsilon);
    check_across_keys(c, plan);
    validate(plan.engine);  // the engine's own checks, e.g. that every sphere fits the gap
    // A sphere that fits but not with the builder's clearance above the base would be refused
    // by the start's check, naming a body instead of the key.
    for (const Species& s : plan.engine.species) {
        const double needed = 2.0 * s.shape.max_radius + kRestingClearance;
        if (!(needed < plan.engine.drive.gap))
            throw InvalidParameter("drive.gap", format_number(plan.engine.drive.gap) + " mm",
                                   "> " + format_number(needed) + " mm",
                                   "'" + s.name + "' has a sphere of diameter " +
                                       format_number(2.0 * s.shape.max_radius) +
                                       " mm, and a body starts " +
                                       format_number(kRestingClearance) + " mm above the base");
    }
    check_time_step_resolves_the_drive(plan.engine);
    return plan;
}

}  // namespace rodsea::config
