#include "rodsea/config/schema.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

#include "rodsea/config/run_plan.hpp"
#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"
#include "rodsea/shape/sphere_chain.hpp"

namespace rodsea::config {

namespace {

std::vector<KeySpec> make_keys() {
    constexpr auto int64_max = std::numeric_limits<std::int64_t>::max();
    // Every default comes from the structs the config fills (one source of defaults).
    const EngineParameters engine = default_engine_parameters();
    const RunControl control;
    const BuilderOptions builder;
    std::vector<KeySpec> k;
    // [box]
    k.push_back(real("box", "side")
                    .unit("mm")
                    .def(engine.box.lx)
                    .range(left_open(0.0, 1e5))
                    .alternative("side_in_polar_lengths")
                    .doc("Side L of the square box, periodic in x and y; the paper's 252 mm = "
                         "56 ℓ_p. At least twice the longest body."));
    k.push_back(real("box", "side_in_polar_lengths")
                    .unit("ℓ_p")
                    .def_text("(from side)")
                    .range(left_open(0.0, 2e4))
                    .alternative("side")
                    .doc("The same side in units of the polar rod's length ℓ_p = 4.5 mm (the "
                         "paper: 56)."));
    // [drive]
    k.push_back(real("drive", "gamma")
                    .def(engine.drive.gamma)
                    .range(closed(0.0, 1000.0))
                    .doc("Γ = AΩ²/g, the plates' peak acceleration over g; the amplitude is "
                         "A = Γg/Ω² (43.49 µm at the defaults)."));
    k.push_back(real("drive", "frequency")
                    .unit("Hz")
                    .def(engine.drive.angular_frequency / (2.0 * std::numbers::pi))
                    .range(left_open(0.0, 1e5))
                    .alternative("angular_frequency")
                    .doc("Drive frequency f = Ω/2π (the paper: 200 Hz, period 5 ms)."));
    k.push_back(real("drive", "angular_frequency")
                    .unit("rad/s")
                    .def_text("(from frequency)")
                    .range(left_open(0.0, 6e5))
                    .alternative("frequency")
                    .doc("Ω = 2πf."));
    k.push_back(real("drive", "gap")
                    .unit("mm")
                    .def(engine.drive.gap)
                    .range(left_open(0.0, 100.0))
                    .choice("the paper's 1.2 mm cannot hold the 1.375 mm thick end of its polar "
                            "rod; at 1.40 mm a lone polar rod goes thick → thin as in the "
                            "experiment, at the speed closest to its 3.6 mm/s (2.5 mm/s); "
                            "docs/model.md")
                    .doc("w, the distance from the base to the lid. Every body's largest sphere "
                         "must fit, with the 0.001 mm a body starts above the base: more than "
                         "1.376 mm for the polar rod."));
    k.push_back(real("drive", "gravity")
                    .unit("mm/s²")
                    .def(engine.drive.gravity)
                    .range(closed(0.0, 1e6))
                    .choice("the paper does not give g: 9.81 m/s²; docs/model.md §1")
                    .doc("g, pulling every body toward the base between collisions."));
    // [[species]]
    k.push_back(Key("species", "name", ValueType::text)
                    .def_text("the kind")
                    .doc("Unique name (letters, digits, _ and -), used in outputs and in "
                         "[[collisions.pair]]."));
    k.push_back(Key("species", "kind", ValueType::option)
                    .options({"polar_rod", "apolar_rod", "bead"})
                    .required()
                    .doc("polar_rod: ℓ_p = 4.5 mm, 1.375 mm thick at one end and 0.4 mm at the "
                         "other; apolar_rod: 0.8 mm at the centre, 0.4 mm at both ends; bead: "
                         "a 0.8 mm sphere (docs/model.md §2)."));
    k.push_back(real("species", "length")
                    .unit("mm")
                    .def_text("required (apolar_rod)")
                    .range(left_open(kApolarRodDiameter, 20.0))
                    .kinds(kApolarRod)
                    .alternative("aspect_ratio")
                    .doc("ℓ_a, the apolar rod's length (the paper: 1.0, 1.5, 2.0, 2.5, 4.5)."));
    k.push_back(real("species", "aspect_ratio")
                    .def_text("(from length)")
                    .range(left_open(1.0, 20.0 / kApolarRodDiameter))
                    .kinds(kApolarRod)
                    .alternative("length")
                    .doc("σ = ℓ_a / 0.8 mm (the paper: 1.25, 1.875, 2.5, 3.125, 5.625)."));
    k.push_back(real("species", "area_fraction")
                    .def_text("required, or count")
                    .range(left_open(0.0, kMaxAreaFraction))
                    .alternative("count")
                    .doc("φ: the count is round(φL²/A), A the area of the body lying flat "
                         "(docs/model.md §2); 0.9069 is the densest packing of discs."));
    k.push_back(integer("species", "count")
                    .unit("bodies")
                    .def_text("(from area_fraction)")
                    .integers(0, kMaxBodies)
                    .alternative("area_fraction")
                    .doc("The number of bodies."));
    k.push_back(integer("species", "spheres")
                    .def_text("13 (polar_rod), 4ℓ_a/mm − 1 (apolar_rod), 1 (bead)")
                    .integers(1, 200)
                    .choice("reproduces the paper's Table S1 counts; docs/model.md §2",
                            kPolarRod | kApolarRod)
                    .doc("Spheres in the rigid chain: at least 2 for a polar rod, exactly 1 "
                         "for a bead."));
    k.push_back(real("species", "mass")
                    .unit("mass units")
                    .range(left_open(0.0, 1e6))
                    .alternative("density")
                    .choice("the paper's m_apolar/m_polar = 0.20, kept for every ℓ_a and for "
                            "beads; docs/model.md §2 (under test against density = 0.2)",
                            kApolarRod | kBead)
                    .doc("Mass in arbitrary units, the polar rod's being 1 (only ratios "
                         "matter); the inertia tensor scales with it. A bead's mass decides "
                         "whether dense beads cage the polar rods (0.2 cages them at φ_a = "
                         "0.70; 0.033, aluminium on brass, does not): docs/reproduction.md, "
                         "SI S5."));
    k.push_back(real("species", "density")
                    .unit("× the polar rod's density")
                    .def_text("(from mass)")
                    .example(0.2)
                    .range(left_open(0.0, 1e6))
                    .alternative("mass")
                    .doc("The body's density relative to the paper's polar rod's (mass 1 in its "
                         "3.119 mm³, the union of its 13 spheres); its mass follows from its own "
                         "volume: 0.2 gives the ℓ_a = 2.5 mm rod 0.041 and a bead 0.017 of a "
                         "polar rod's mass (the paper's \"mass ratio 0.20\" read as a density "
                         "ratio). `rodsea info` prints both."));
    k.push_back(
        real("species", "plate_friction")
            .range(closed(0.0, 10.0))
            .choice("the paper gives no bead–plate values: the apolar rod's; docs/model.md §3",
                    kBead)
            .doc("μ, Coulomb friction of collisions with the base and the lid (paper, "
                 "Table S2)."));
    k.push_back(
        real("species", "plate_restitution")
            .range(closed(0.0, 1.0))
            .choice("the paper gives no bead–plate values: the apolar rod's; docs/model.md §3",
                    kBead)
            .doc("e, normal restitution of collisions with the base and the lid (paper, "
                 "Table S2)."));
    // [collisions]
    k.push_back(real("collisions", "friction")
                    .def(engine.body_body.friction)
                    .range(closed(0.0, 10.0))
                    .doc("μ, Coulomb friction of every body–body collision (paper, Table S2)."));
    k.push_back(real("collisions", "restitution")
                    .def(engine.body_body.restitution)
                    .range(closed(0.0, 1.0))
                    .doc("e, normal restitution of every body–body collision (paper, Table S2)."));
    k.push_back(Key("collisions.pair", "species", ValueType::name_pair)
                    .required()
                    .example(std::vector<std::string>{"polar", "medium"})
                    .doc("The two species' names; the same name twice means bodies of one "
                         "species."));
    k.push_back(real("collisions.pair", "friction")
                    .def_text("collisions.friction")
                    .example(0.05)
                    .range(closed(0.0, 10.0))
                    .doc("μ for this pair, both orders."));
    k.push_back(real("collisions.pair", "restitution")
                    .def_text("collisions.restitution")
                    .example(0.3)
                    .range(closed(0.0, 1.0))
                    .doc("e for this pair, both orders."));
    // [noise]
    k.push_back(
        Key("noise", "mode", ValueType::option)
            .def(std::string(to_string(engine.noise_mode)))
            .options({"add", "set"})
            .choice("under test by a screening study: the SI imposes ω_z = ε v_rel η at each plate "
                    "collision (set); the first model specification read it as a kick added to ω_z "
                    "(add); docs/model.md §3")
            .doc("How a polar rod's plate collision meets its spin about z. add: ω_z += "
                 "ε |u_n| η; set: ω_z = ε |u_n| η, so at ε = 0 every plate collision "
                 "stops the rod turning. Each mode has its own ε range and calibration "
                 "rows."));
    k.push_back(
        real("noise", "epsilon")
            .unit("1/mm")
            .def(engine.noise_epsilon)
            .range(closed(0.0, kMaxNoiseEpsilon))
            .alternative("rotational_diffusion")
            .choice("the kick is scaled by the pre-collision normal speed |u_n|; "
                    "docs/model.md §3")
            .doc("ε: at each collision of a polar rod with a plate, ε |u_n| η, η = ±1, "
                 "joins ω_z (noise.mode = add) or becomes it (set). add: at most " +
                 format_number(kMaxNoiseEpsilonAdd) +
                 " /mm (D_r grows as ε², 0.05 /mm gives ~5 rad²/s; above 0.5 /mm the "
                 "rods spin up without bound); set: at most " +
                 format_number(kMaxNoiseEpsilonSet) +
                 " /mm (a lone rod spins from about 3 /mm; the set rule's calibration is in "
                 "docs/validation.md)."));
    k.push_back(real("noise", "rotational_diffusion")
                    .unit("rad²/s")
                    .def_text("none")
                    .example(0.026)
                    .range(closed(0.0, 100.0))
                    .alternative("epsilon")
                    .doc("D_r, the paper's control parameter (0, 0.026, 0.23, 1.21, 1.87), "
                         "turned into ε by linear interpolation in calibration_table; refused "
                         "outside the table's range. The resolved config holds that ε."));
    k.push_back(Key("noise", "calibration_table", ValueType::text)
                    .unit("path")
                    .def_text("none")
                    .example(std::string("calibration.csv"))
                    .doc("The calibration.csv written by `rodsea calibrate`, with polar_rod rows "
                         "at this run's drive.gap and time.dt; a relative path is relative to "
                         "the config file. Needs rotational_diffusion."));
    // [time]
    k.push_back(real("time", "dt")
                    .unit("s")
                    .def(engine.dt)
                    .range(closed(1e-9, 1e-3))
                    .choice("4000 steps per 5 ms drive period: 5 µs makes a lone polar rod 13 % "
                            "too fast; at 1.25 µs D_r agrees with dt/4 and the speed to 3–5 %; "
                            "docs/model.md")
                    .doc("The time step; also small enough that a sphere at four times the "
                         "plates' peak speed AΩ (and twice a fresh start's fastest) moves less "
                         "than a quarter of the smallest sphere radius in it: at most 2.3e-4 s "
                         "at the defaults."));
    k.push_back(real("time", "duration")
                    .unit("s")
                    .def(control.duration)
                    .range(left_open(0.0, 1e6))
                    .alternative("periods")
                    .doc("Simulated time; the run takes round(duration/dt) steps."));
    k.push_back(real("time", "periods")
                    .unit("periods")
                    .def_text("(from duration)")
                    .range(left_open(0.0, 1e9))
                    .alternative("duration")
                    .doc("Simulated time in drive periods 2π/Ω."));
    k.push_back(integer("time", "steady_samples")
                    .def(std::int64_t{control.steady_samples})
                    .integers(0, 1'000'000'000)
                    .doc("Stop when steady: end the run at the first frame whose steady window "
                         "(chosen as `rodsea analyze` chooses it, from every order series) holds "
                         "at least this many independent samples n/(2 τ_int) of steady_series, "
                         "none of them drifting; duration is then the longest it may run. "
                         "0: run for the whole duration. Needs at least 50 frames to judge."));
    k.push_back(Key("time", "steady_series", ValueType::text)
                    .def(control.steady_series)
                    .doc("The series steady_samples counts: all (every order series must have "
                         "the samples), or one time-series column: polar_order_<species>, "
                         "nematic_order_<species>, segregation, largest_flock (checked against "
                         "the run's species before it starts)."));
    // [output]
    k.push_back(real("output", "interval")
                    .unit("s")
                    .def(control.output_interval)
                    .range(left_open(0.0, 1e6))
                    .alternative("interval_periods")
                    .doc("Simulated time between trajectory frames and observable rows, "
                         "rounded to whole steps; at least dt, at most the duration."));
    k.push_back(real("output", "interval_periods")
                    .unit("periods")
                    .def_text("(from interval)")
                    .range(left_open(0.0, 1e9))
                    .alternative("interval")
                    .doc("The same in drive periods."));
    k.push_back(real("output", "checkpoint_interval")
                    .unit("min")
                    .def(control.checkpoint_interval)
                    .range(left_open(0.0, 1e6))
                    .doc("Wall-clock minutes between checkpoints."));
    // [run]
    k.push_back(integer("run", "seed")
                    .def(static_cast<std::int64_t>(engine.seed))
                    .integers(0, int64_max)
                    .doc("Seed of every random choice (initial state, noise signs): the same "
                         "seed gives the same run."));
    k.push_back(integer("run", "threads")
                    .def(std::int64_t{control.threads})
                    .integers(1, kMaxThreads)
                    .doc("Threads of the engine's step (OpenMP). The trajectory is the same, bit "
                         "for bit, on any number of threads; more threads than cores only slow "
                         "it down (docs/performance.md)."));
    k.push_back(Key("run", "backend", ValueType::option)
                    .def(std::string(to_string(control.backend)))
                    .options({"cpu", "gpu"})
                    .doc("What steps the state: cpu, the host's cores (run.threads); gpu, a CUDA "
                         "device (a build with CUDA and an sm_90 or newer GPU: rodsea info says "
                         "whether this machine has one, and run refuses gpu before any work "
                         "where it has none). The GPU runs the CPU's algorithm; its rounding may "
                         "differ, so its trajectory is the CPU's statistically, not promised bit "
                         "for bit (docs/architecture.md). A checkpoint resumes on either (run "
                         "--resume DIR --backend)."));
    // [initial]
    k.push_back(
        Key("initial", "orientation", ValueType::option)
            .def(std::string(builder.orientation == InitialOrientation::isotropic ? "isotropic"
                                                                                  : "aligned"))
            .options({"isotropic", "aligned", "polar_aligned"})
            .doc("isotropic: random in-plane angles; aligned: every rod along x (polar rods +x; "
                 "a lattice above area fraction 0.505, which aligns a dense medium too); "
                 "polar_aligned: the polar rods along +x in an isotropic medium, at any "
                 "density (does an ordered state survive?)."));
    k.push_back(integer("initial", "randomisation_sweeps")
                    .def(std::int64_t{builder.randomisation_sweeps})
                    .integers(0, 100'000)
                    .doc("Monte Carlo sweeps after the start is placed: they relax it locally "
                         "(docs/builder.md)."));
    k.push_back(real("initial", "domain_size")
                    .unit("mm")
                    .def(builder.domain_size)
                    .range(closed(2.0, 10000.0))
                    .doc("Side of the domains of the mosaic start, used only above the jamming "
                         "of random packings (e.g. 2.5 mm rods at 0.80): the medium's S at the "
                         "start is then about 1/sqrt(domains). Smaller domains waste more room "
                         "at their boundaries and may not fit; the build doubles the size until "
                         "they do (docs/builder.md)."));
    // [engine]
    k.push_back(integer("engine", "max_sweeps")
                    .def(std::int64_t{engine.max_sweeps})
                    .integers(1, 1'000'000'000)
                    .doc("Impulse sweeps per step before the contacts left count as "
                         "unresolved."));
    k.push_back(real("engine", "approach_tolerance")
                    .unit("mm/s")
                    .def(engine.approach_tolerance)
                    .range(closed(0.0, 1000.0))
                    .doc("Normal relative speeds above −tolerance count as not approaching."));
    return k;
}

std::string doc_number(double v) {
    // Whole numbers in full ("100000", not "1e+05"): ranges and defaults read as typed.
    if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    return exact_number(v);
}

std::string with_unit(const std::string& text, const std::string& unit) {
    return unit.empty() ? text : text + " " + unit;
}

}  // namespace

Interval closed(double lo, double hi) {
    return {lo, hi, false, false};
}
Interval left_open(double lo, double hi) {
    return {lo, hi, true, false};
}

Key real(std::string table, std::string name) {
    return Key(std::move(table), std::move(name), ValueType::real);
}
Key integer(std::string table, std::string name) {
    return Key(std::move(table), std::move(name), ValueType::integer);
}

Value value_from_text(const KeySpec& spec, const std::string& text) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    const bool number = ec == std::errc() && ptr == end && !text.empty();
    if (spec.type == ValueType::integer) {
        if (!number || v != std::floor(v) || !(v >= static_cast<double>(spec.min_integer)) ||
            !(v <= static_cast<double>(spec.max_integer)))
            throw InvalidParameter(spec.path(), toml_literal(Value{text}), spec.allowed_text());
        return static_cast<std::int64_t>(v);
    }
    if (spec.type != ValueType::real)
        throw InvalidParameter(spec.path(), toml_literal(Value{text}), "a key with a number value");
    if (!number || !spec.range.contains(v))
        throw InvalidParameter(spec.path(), toml_literal(Value{text}), spec.allowed_text());
    return v;
}

KindMask kind_bit(BodyKind kind) {
    switch (kind) {
        case BodyKind::polar_rod:
            return kPolarRod;
        case BodyKind::apolar_rod:
            return kApolarRod;
        case BodyKind::bead:
            return kBead;
    }
    return 0;
}

bool Interval::contains(double v) const {
    // Written so that NaN fails every comparison.
    const bool above = lo_open ? v > lo : v >= lo;
    const bool below = hi_open ? v < hi : v <= hi;
    return above && below && std::isfinite(v);
}

std::string KeySpec::path() const {
    return table.empty() ? name : table + "." + name;
}

std::string KeySpec::type_text() const {
    switch (type) {
        case ValueType::real:
            return "real";
        case ValueType::integer:
            return "integer";
        case ValueType::text:
            return "string";
        case ValueType::option:
            return "string";
        case ValueType::name_pair:
            return "array of 2 strings";
    }
    return "";
}

std::string KeySpec::allowed_text() const {
    switch (type) {
        case ValueType::real: {
            const bool has_lo = std::isfinite(range.lo), has_hi = std::isfinite(range.hi);
            if (has_lo && has_hi) {
                // Appended piece by piece: GCC 12 misreports `"(" + std::string` (-Wrestrict).
                std::string s = range.lo_open ? "(" : "[";
                s += doc_number(range.lo);
                s += ", ";
                s += doc_number(range.hi);
                s += range.hi_open ? ")" : "]";
                return with_unit(s, unit);
            }
            if (has_lo)
                return with_unit((range.lo_open ? "> " : ">= ") + doc_number(range.lo), unit);
            if (has_hi)
                return with_unit((range.hi_open ? "< " : "<= ") + doc_number(range.hi), unit);
            return "any finite number";
        }
        case ValueType::integer:
            if (max_integer == std::numeric_limits<std::int64_t>::max())
                return "an integer >= " + std::to_string(min_integer);
            return "an integer in [" + std::to_string(min_integer) + ", " +
                   std::to_string(max_integer) + "]";
        case ValueType::text:
            return name == "name" ? "1 to 64 letters, digits, _ and -" : "any string";
        case ValueType::option: {
            std::string s;
            for (size_t i = 0; i < options.size(); ++i) {
                if (i > 0) s += i + 1 == options.size() ? " or " : ", ";
                s += "\"" + options[i] + "\"";
            }
            return s;
        }
        case ValueType::name_pair:
            return "two names of [[species]]";
    }
    return "";
}

std::string markdown_cell(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out;
}

std::string doc_text(const Value& v) {
    if (const auto* d = std::get_if<double>(&v)) return doc_number(*d);
    return toml_literal(v);
}

std::string KeySpec::shown(const Value& v) const {
    if (const auto* d = std::get_if<double>(&v)) return with_unit(format_number(*d), unit);
    if (const auto* i = std::get_if<std::int64_t>(&v)) return with_unit(std::to_string(*i), unit);
    return toml_literal(v);
}

std::string KeySpec::default_doc() const {
    if (default_value) return doc_text(*default_value);
    if (!default_text.empty()) return default_text;
    if (required) return "required";
    if (table == "species") {
        // Group the kinds that share a default: "1 (polar_rod), 0.2 (apolar_rod, bead)".
        std::vector<std::pair<std::string, std::string>> groups;
        for (const BodyKind kind : {BodyKind::polar_rod, BodyKind::apolar_rod, BodyKind::bead}) {
            const auto v = species_default(name, kind, 0.0);
            if (!v) continue;
            const std::string text = doc_text(*v);
            if (!groups.empty() && groups.back().first == text)
                groups.back().second += std::string(", ") + to_string(kind);
            else
                groups.emplace_back(text, to_string(kind));
        }
        std::string s;
        for (const auto& [value, kinds_text] : groups)
            s += (s.empty() ? "" : ", ") + value + " (" + kinds_text + ")";
        return s;
    }
    return "none";
}

const std::vector<TableSpec>& config_tables() {
    static const std::vector<TableSpec> tables = {
        {"box", false, "The square box, periodic in x and y (docs/model.md §1)."},
        {"drive", false,
         "The vibrating plates: base at A cos Ωt, lid at A cos Ωt + w, A = Γg/Ω² (docs/model.md "
         "§1)."},
        {"species", true,
         "One table per kind of body (docs/model.md §2), in the order the outputs use. Without any "
         "[[species]] the paper's main system is used: polar rods named \"polar\" at φ = 0.05 "
         "in apolar rods of ℓ_a = 2.5 mm (σ = 3.125) named \"medium\" at φ = 0.50. Give exactly "
         "one of area_fraction and count, and for an apolar rod exactly one of length and "
         "aspect_ratio; a key that does not apply to the kind is an error."},
        {"collisions", false, "Body–body collisions: the Stronge impulse of docs/model.md §3."},
        {"collisions.pair", true,
         "Optional, repeatable: coefficients for one pair of species, overriding [collisions]."},
        {"noise", false,
         "Rotational noise of polar rods at their collisions with the plates (docs/model.md §3)."},
        {"time", false, "The time step and the length of the run."},
        {"output", false, "How often the run writes frames, rows and checkpoints."},
        {"run", false, "Seed and threads."},
        {"initial", false,
         "The initial state: a random start (insertion, compression or a mosaic of domains, "
         "docs/builder.md) relaxed by Monte Carlo."},
        {"engine", false, "Advanced: the impulse solver."},
    };
    return tables;
}

const std::vector<KeySpec>& config_keys() {
    static const std::vector<KeySpec> keys = make_keys();
    return keys;
}

const TableSpec* find_table(std::string_view path) {
    for (const TableSpec& t : config_tables())
        if (t.path == path) return &t;
    return nullptr;
}

const KeySpec* find_key(std::string_view table, std::string_view name) {
    for (const KeySpec& k : config_keys())
        if (k.table == table && k.name == name) return &k;
    return nullptr;
}

std::vector<const KeySpec*> keys_of(std::string_view table) {
    std::vector<const KeySpec*> keys;
    for (const KeySpec& k : config_keys())
        if (k.table == table) keys.push_back(&k);
    return keys;
}

std::optional<Value> species_default(std::string_view key, BodyKind kind, double length_mm) {
    if (key == "name") return std::string(to_string(kind));
    if (key == "spheres") {
        switch (kind) {
            case BodyKind::polar_rod:
                return std::int64_t{PolarRodGeometry{}.sphere_count};
            case BodyKind::apolar_rod:
                return std::int64_t{ApolarRodGeometry::default_sphere_count(length_mm)};
            case BodyKind::bead:
                return std::int64_t{1};
        }
    }
    if (key == "mass") return kind == BodyKind::polar_rod ? kPolarRodMass : kMediumMass;
    if (key == "plate_friction" || key == "plate_restitution") {
        // The engine's species constructors hold Table S2 and the bead CHOICE; build each once.
        static const ContactCoefficients polar = polar_rod_species().plate;
        static const ContactCoefficients apolar = apolar_rod_species(2.5).plate;
        static const ContactCoefficients bead = bead_species().plate;
        const ContactCoefficients& c = kind == BodyKind::polar_rod    ? polar
                                       : kind == BodyKind::apolar_rod ? apolar
                                                                      : bead;
        return key == "plate_friction" ? c.friction : c.restitution;
    }
    return std::nullopt;
}

}  // namespace rodsea::config
