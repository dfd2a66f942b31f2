#include "rodsea/meanfield/mean_field.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace {

constexpr double kDefaultP0 = 0.01;
constexpr double kDefaultDuration = 30.0;
constexpr double kDefaultDt = 1e-3;
constexpr long long kDefaultSamples = 30;
// A billion RK4 steps take tens of seconds; more is a typo rather than a wish.
constexpr long long kMaxSteps = 1'000'000'000;
// e^500 ~ 1e217: with b = 0 and c > 0 a longer run overflows long before it says anything.
constexpr double kMaxLinearGrowthExponent = 500.0;

std::string num(double v) {
    return format_number(v);
}

std::string fixed_width(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%13.6g", v);
    return text;
}

struct Eigenvalues {
    double larger = 0.0, smaller = 0.0;
};

// Eigenvalues of [[d, lambda], [alpha/rho, -Gamma_f/rho]]: the P-v block of the Jacobian for a
// mode whose P-diagonal entry is d. Real since lambda alpha >= 0. The small one is taken as
// det / large one: with rho -> 0 the direct formula would cancel catastrophically.
Eigenvalues block_eigenvalues(const MeanFieldParameters& p, double d) {
    const double g = p.friction / p.rho;
    const double trace = d - g;
    const double det = -d * g - p.lambda * p.alpha / p.rho;
    const double root = std::sqrt((d + g) * (d + g) + 4.0 * p.lambda * p.alpha / p.rho);
    const double big = 0.5 * (trace + std::copysign(root, trace));
    const double other = big != 0.0 ? det / big : 0.0;
    return {std::max(big, other), std::min(big, other)};
}

}  // namespace

// Bounds far beyond any physical rate (the paper's are of order 1/s), so that products such as
// α λ / Γ_f stay finite and a huge value is refused by name, not as an unstable --dt.
constexpr double kLargest = 1e12, kSmallest = 1e-12;

void check_mean_field_parameters(const MeanFieldParameters& p, const std::string& prefix) {
    require_in_closed_range(prefix + "a", p.a, -kLargest, kLargest, "1/s");
    require_in_closed_range(prefix + "lambda", p.lambda, 0.0, kLargest, "1/mm");
    require_in_closed_range(prefix + "b", p.b, 0.0, kLargest, "1/s");
    require_in_closed_range(prefix + "friction", p.friction, kSmallest, kLargest, "M mm^-2 s^-1");
    require_in_closed_range(prefix + "alpha", p.alpha, 0.0, kLargest, "M mm^-1 s^-2");
    require_in_closed_range(prefix + "rho", p.rho, kSmallest, kLargest, "M mm^-2");
}

double effective_growth_rate(const MeanFieldParameters& p) {
    return p.alpha * p.lambda / p.friction - p.a;
}

double steady_polar_order(const MeanFieldParameters& p) {
    const double numerator = p.alpha * p.lambda - p.a * p.friction;
    if (!(numerator > 0.0)) return 0.0;
    if (p.b == 0.0) return std::numeric_limits<double>::infinity();
    return std::sqrt(numerator / (p.b * p.friction));
}

double adiabatic_polar_order(const MeanFieldParameters& p, double p0, double t) {
    require_non_negative("p0", p0);
    require_non_negative("t", t, "s");
    const double c = effective_growth_rate(p);
    const double bp2 = p.b * p0 * p0;
    if (c > 0.0) {
        // Divided through by e^{ct} so that large ct underflows to the steady value instead of
        // overflowing to inf/inf.
        const double decay = std::exp(-2.0 * c * t);
        return p0 / std::sqrt(decay + bp2 * (-std::expm1(-2.0 * c * t)) / c);
    }
    // (e^{2ct} - 1)/c -> 2t continuously as c -> 0; expm1 keeps it accurate for small |c| t.
    const double growth = c == 0.0 ? 2.0 * t : std::expm1(2.0 * c * t) / c;
    return p0 * std::exp(c * t) / std::sqrt(1.0 + bp2 * growth);
}

double linear_growth_rate(const MeanFieldParameters& p) {
    return block_eigenvalues(p, -p.a).larger;
}

double steady_relaxation_rate(const MeanFieldParameters& p) {
    const double steady = steady_polar_order(p);
    if (!std::isfinite(steady)) return 0.0;
    return std::max(0.0, -block_eigenvalues(p, -p.a - 3.0 * p.b * steady * steady).larger);
}

double polar_order_bound(const MeanFieldParameters& p, double p0, double v0) {
    const double inf = std::numeric_limits<double>::infinity();
    const double v = std::abs(v0);
    if (p.b == 0.0 && effective_growth_rate(p) > 0.0) return inf;
    double pm = std::max(std::abs(p0), steady_polar_order(p));
    if (p.alpha > 0.0) pm = std::max(pm, p.friction * v / p.alpha);
    const auto face_rate = [&](double m) {
        const double vm = std::max(v, p.alpha * m / p.friction);
        return -p.a * m + p.lambda * vm - p.b * m * m * m;
    };
    // Only alpha = 0 with v0 != 0 can need growing: the v face then stays at |v0|.
    for (int i = 0; i < 4000 && face_rate(pm) > 0.0; ++i)
        pm = pm > 0.0 ? 1.25 * pm
                      : std::max(std::cbrt(p.lambda * v / std::max(p.b, 1e-300)), 1e-300);
    return face_rate(pm) > 0.0 ? inf : pm;
}

double fastest_rate(const MeanFieldParameters& p, double p_max) {
    // With b = 0 the system is linear and the Jacobian does not depend on P.
    const double cubic = p.b == 0.0 ? 0.0 : 3.0 * p.b * p_max * p_max;
    double fastest = 0.0;
    for (const double d : {-p.a, -p.a - cubic}) {
        const Eigenvalues e = block_eigenvalues(p, d);
        fastest = std::max({fastest, std::abs(e.larger), std::abs(e.smaller)});
    }
    return fastest;
}

double max_stable_time_step(const MeanFieldParameters& p, double p_max) {
    const double k = fastest_rate(p, p_max);
    return k > 0.0 ? kRk4StabilityLimit / k : std::numeric_limits<double>::infinity();
}

MeanFieldState mean_field_derivative(const MeanFieldParameters& p, const MeanFieldState& s) {
    const double damping = -p.a - p.b * (s.px * s.px + s.py * s.py);
    return {damping * s.px + p.lambda * s.vx, damping * s.py + p.lambda * s.vy,
            (-p.friction * s.vx + p.alpha * s.px) / p.rho,
            (-p.friction * s.vy + p.alpha * s.py) / p.rho};
}

MeanFieldState rk4_step(const MeanFieldParameters& p, const MeanFieldState& s, double dt) {
    const auto along = [](const MeanFieldState& x, const MeanFieldState& k, double h) {
        return MeanFieldState{x.px + h * k.px, x.py + h * k.py, x.vx + h * k.vx, x.vy + h * k.vy};
    };
    const MeanFieldState k1 = mean_field_derivative(p, s);
    const MeanFieldState k2 = mean_field_derivative(p, along(s, k1, 0.5 * dt));
    const MeanFieldState k3 = mean_field_derivative(p, along(s, k2, 0.5 * dt));
    const MeanFieldState k4 = mean_field_derivative(p, along(s, k3, dt));
    const double w = dt / 6.0;
    return {s.px + w * (k1.px + 2.0 * k2.px + 2.0 * k3.px + k4.px),
            s.py + w * (k1.py + 2.0 * k2.py + 2.0 * k3.py + k4.py),
            s.vx + w * (k1.vx + 2.0 * k2.vx + 2.0 * k3.vx + k4.vx),
            s.vy + w * (k1.vy + 2.0 * k2.vy + 2.0 * k3.vy + k4.vy)};
}

std::vector<MeanFieldSample> integrate_mean_field(const MeanFieldParameters& p,
                                                  const MeanFieldState& initial, double dt,
                                                  long long steps, long long sample_every) {
    check_mean_field_parameters(p);
    require_positive("dt", dt, "s");
    if (steps < 0) throw InvalidParameter("steps", std::to_string(steps), ">= 0");
    require_positive_count("sample_every", sample_every);
    std::vector<MeanFieldSample> samples;
    samples.reserve(static_cast<size_t>(steps / sample_every + 2));
    const auto record = [&](long long step, const MeanFieldState& s) {
        if (!std::isfinite(s.px) || !std::isfinite(s.py) || !std::isfinite(s.vx) ||
            !std::isfinite(s.vy)) {
            throw InvalidParameter(
                "dt", num(dt) + " s", "a smaller step",
                "the integration diverged by t = " + num(static_cast<double>(step) * dt) + " s");
        }
        samples.push_back(
            {static_cast<double>(step) * dt, s.px, s.py, s.vx, s.vy, std::hypot(s.px, s.py)});
    };
    MeanFieldState s = initial;
    record(0, s);
    for (long long step = 1; step <= steps; ++step) {
        s = rk4_step(p, s, dt);
        if (step % sample_every == 0 || step == steps) record(step, s);
    }
    return samples;
}

namespace {

struct MeanfieldOptions {
    MeanFieldParameters model;
    double p0 = kDefaultP0;
    double angle = 0.0;
    double v0 = 0.0;
    double duration = kDefaultDuration;
    double dt = kDefaultDt;
    long long samples = kDefaultSamples;
    std::optional<std::filesystem::path> csv;
    bool help = false;
};

}  // namespace

const CommandSpec& meanfield_command_spec() {
    static const CommandSpec spec = [] {
        const MeanfieldOptions d;  // the defaults, shown in the help
        const MeanFieldParameters& m = d.model;
        const auto def = [](double v) { return "; default " + format_number(v); };
        return CommandSpec{
            "meanfield",
            "[--a A] [--lambda L] [--b B] [--friction G] [--alpha AL] [--rho R] [--p0 P0] "
            "[--angle RAD] [--v0 V0] [--duration T] [--dt DT] [--samples N] [--csv FILE]",
            "the paper's mean-field model",
            "Integrates the paper's mean-field model (End Matter; docs/meanfield.md) with "
            "fixed-step RK4:\n"
            "dP/dt = -a P + lambda v - b |P|^2 P  (P: polar order, 2-D, dimensionless)\n"
            "rho dv/dt = -Gamma_f v + alpha P  (v: medium velocity, 2-D, mm/s)\n"
            "Prints the parameters, c = alpha lambda/Gamma_f - a and the closed-form steady "
            "|P| = sqrt((alpha lambda - a Gamma_f)/(b Gamma_f)) (0 when c <= 0), then the "
            "trajectory, then the steady |P| reached numerically against the closed form. M "
            "below is any mass unit.",
            {{"--a", "A",
              "relaxation rate of P, 1/s (about D_r at large noise; < 0 allowed)" + def(m.a)},
             {"--lambda", "L", "flow-induced ordering, 1/mm, >= 0" + def(m.lambda)},
             {"--b", "B", "saturation, 1/s, >= 0" + def(m.b)},
             {"--friction", "G", "Gamma_f, plate friction, M mm^-2 s^-1, > 0" + def(m.friction)},
             {"--alpha", "AL", "active forcing of the medium, M mm^-1 s^-2, >= 0" + def(m.alpha)},
             {"--rho", "R", "mass per area, M mm^-2, > 0" + def(m.rho)},
             {"--p0", "P0", "initial |P|, >= 0" + def(d.p0)},
             {"--angle", "RAD", "direction of P0 and v0, rad" + def(d.angle)},
             {"--v0", "V0", "initial v along that direction, mm/s" + def(d.v0)},
             {"--duration", "T", "simulated time, s, > 0" + def(d.duration)},
             {"--dt", "DT",
              "time step, s, > 0 and below the RK4 stability limit (printed)" + def(d.dt)},
             {"--samples", "N",
              "number of output intervals, 1 .. steps" + def(static_cast<double>(d.samples))},
             {"--csv", "FILE",
              "write the trajectory as CSV (t,Px,Py,vx,vy,P,P_adiabatic) instead of a table; the "
              "file appears complete or not at all"}},
            ""};
    }();
    return spec;
}

namespace {

// A finite number (its range is the model's to check, with the model's words).
double finite_number(const Arguments& a, const char* flag, double fallback,
                     const std::string& unit) {
    const auto text = a.value(flag);
    return text ? parse_number(flag, *text, -std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity(), unit)
                : fallback;
}

MeanfieldOptions parse_options(const std::vector<std::string>& args) {
    MeanfieldOptions o;
    const Arguments a = parse_arguments(args, meanfield_command_spec());
    if (a.help) {
        o.help = true;
        return o;
    }
    if (!a.positional.empty())
        throw InvalidParameter(a.positional[0], "an unexpected argument",
                               "only options (see rodsea meanfield --help)");
    MeanFieldParameters& m = o.model;
    m.a = finite_number(a, "--a", m.a, "1/s");
    m.lambda = finite_number(a, "--lambda", m.lambda, "1/mm");
    m.b = finite_number(a, "--b", m.b, "1/s");
    m.friction = finite_number(a, "--friction", m.friction, "M mm^-2 s^-1");
    m.alpha = finite_number(a, "--alpha", m.alpha, "M mm^-1 s^-2");
    m.rho = finite_number(a, "--rho", m.rho, "M mm^-2");
    o.p0 = finite_number(a, "--p0", o.p0, "");
    o.angle = finite_number(a, "--angle", o.angle, "rad");
    o.v0 = finite_number(a, "--v0", o.v0, "mm/s");
    o.duration = finite_number(a, "--duration", o.duration, "s");
    o.dt = finite_number(a, "--dt", o.dt, "s");
    if (const auto text = a.value("--samples"))
        o.samples = parse_count("--samples", *text, 1, std::numeric_limits<long long>::max());
    if (const auto text = a.value("--csv")) {
        if (text->empty()) throw InvalidParameter("--csv", "''", "a file name");
        o.csv = std::filesystem::path(*text);
    }
    return o;
}

// Everything the run needs, derived from checked options: computed before anything is run so
// that every refusal happens first.
struct MeanfieldPlan {
    MeanfieldOptions options;
    double c = 0.0;
    double linear_rate = 0.0;
    double steady = 0.0;
    double p_max = 0.0;
    double fastest = 0.0;
    double dt_limit = 0.0;
    long long steps = 0;
    long long sample_every = 1;
};

MeanfieldPlan make_plan(const MeanfieldOptions& o) {
    check_mean_field_parameters(o.model, "--");
    require_in_closed_range("--p0", o.p0, 0.0, kLargest);
    require_in_closed_range("--v0", o.v0, -kLargest, kLargest, "mm/s");
    require_positive("--duration", o.duration, "s");
    require_positive("--dt", o.dt, "s");
    MeanfieldPlan plan;
    plan.options = o;
    const MeanFieldParameters& m = o.model;
    plan.c = effective_growth_rate(m);
    plan.linear_rate = linear_growth_rate(m);
    plan.steady = steady_polar_order(m);
    plan.p_max = polar_order_bound(m, o.p0, o.v0);
    plan.fastest = fastest_rate(m, plan.p_max);
    plan.dt_limit = max_stable_time_step(m, plan.p_max);
    if (!(o.dt < plan.dt_limit)) {
        throw InvalidParameter("--dt", num(o.dt) + " s", "< " + num(plan.dt_limit) + " s",
                               "RK4 is unstable when dt times the fastest rate, " +
                                   num(plan.fastest) + " 1/s here (|P| up to " + num(plan.p_max) +
                                   "), exceeds " + num(kRk4StabilityLimit) +
                                   "; for accuracy take a tenth of the limit or less");
    }
    if (o.dt > o.duration)
        throw InvalidParameter("--dt", num(o.dt) + " s",
                               "<= --duration = " + num(o.duration) + " s");
    const double steps = std::round(o.duration / o.dt);
    if (steps > static_cast<double>(kMaxSteps)) {
        throw InvalidParameter("--dt", num(o.dt) + " s",
                               ">= duration / " + std::to_string(kMaxSteps) + " = " +
                                   num(o.duration / static_cast<double>(kMaxSteps)) + " s",
                               "more steps would take minutes to hours");
    }
    plan.steps = std::max(1LL, static_cast<long long>(steps));
    if (m.b == 0.0 && plan.linear_rate * o.duration > kMaxLinearGrowthExponent) {
        throw InvalidParameter("--duration", num(o.duration) + " s",
                               "<= " + num(kMaxLinearGrowthExponent / plan.linear_rate) + " s",
                               "with b = 0 nothing saturates |P|: it grows as e^{" +
                                   num(plan.linear_rate) + " t} and would overflow");
    }
    if (o.samples > plan.steps) {
        throw InvalidParameter("--samples", std::to_string(o.samples),
                               "[1, " + std::to_string(plan.steps) + "] (the number of steps)");
    }
    plan.sample_every = (plan.steps + o.samples - 1) / o.samples;
    if (o.csv) {
        const std::filesystem::path parent =
            o.csv->parent_path().empty() ? std::filesystem::path(".") : o.csv->parent_path();
        std::error_code ec;
        if (!std::filesystem::is_directory(parent, ec))
            throw InvalidParameter("--csv", o.csv->string(), "a file in an existing directory");
        if (std::filesystem::is_directory(*o.csv, ec))
            throw InvalidParameter("--csv", o.csv->string(), "a file name, not a directory");
    }
    return plan;
}

void describe(const MeanfieldPlan& plan, std::ostream& out) {
    const MeanfieldOptions& o = plan.options;
    const MeanFieldParameters& m = o.model;
    out << "rodsea meanfield: the paper's mean-field model (End Matter), RK4 with a fixed step\n"
        << "  dP/dt = -a P + lambda v - b |P|^2 P,   rho dv/dt = -Gamma_f v + alpha P\n"
        << "parameters (M: any mass unit)\n"
        << "  a        = " << num(m.a) << " 1/s (relaxation of P, ~ D_r at large noise)\n"
        << "  lambda   = " << num(m.lambda) << " 1/mm (flow-induced ordering)\n"
        << "  b        = " << num(m.b) << " 1/s (saturation)\n"
        << "  Gamma_f  = " << num(m.friction) << " M mm^-2 s^-1 (plate friction)\n"
        << "  alpha    = " << num(m.alpha) << " M mm^-1 s^-2 (active forcing)\n"
        << "  rho      = " << num(m.rho) << " M mm^-2 (mass per area)\n"
        << "derived\n"
        << "  alpha/Gamma_f = " << num(m.alpha / m.friction)
        << " mm/s (slaved velocity per unit P)\n"
        << "  rho/Gamma_f   = " << num(m.rho / m.friction) << " s (velocity relaxation time)\n"
        << "  c = alpha lambda/Gamma_f - a = " << num(plan.c)
        << " 1/s (with the lag of v: " << num(plan.linear_rate) << " 1/s)\n";
    if (plan.c > 0.0 && !std::isfinite(plan.steady)) {
        out << "  no steady |P|: b = 0 and c > 0, nothing saturates the growth\n";
    } else if (plan.c > 0.0) {
        out << "  steady |P| = sqrt((alpha lambda - a Gamma_f)/(b Gamma_f)) = " << num(plan.steady)
            << ": ordered\n    small |P| grows at " << num(plan.linear_rate) << " 1/s, settles at "
            << num(steady_relaxation_rate(o.model)) << " 1/s (2c = " << num(2.0 * plan.c)
            << " as rho -> 0)\n";
        if (o.p0 == 0.0 && o.v0 == 0.0)
            out << "  note: P0 = 0 and v0 = 0 is an (unstable) fixed point; nothing will move\n";
    } else if (plan.c < 0.0) {
        out << "  steady |P| = 0: disordered (alpha lambda < a Gamma_f), small |P| decays at rate "
            << num(-plan.linear_rate) << " 1/s\n";
    } else {
        out << "  steady |P| = 0: marginal (alpha lambda = a Gamma_f), |P| ~ 1/sqrt(2 b t)\n";
    }
    out << "initial  |P0| = " << num(o.p0) << " at angle " << num(o.angle)
        << " rad, v0 = " << num(o.v0) << " mm/s along it\n"
        << "run      " << num(static_cast<double>(plan.steps) * o.dt) << " s in " << plan.steps
        << " steps of dt = " << num(o.dt) << " s\n"
        << "         RK4 stable below dt = " << num(plan.dt_limit) << " s (fastest rate "
        << num(plan.fastest) << " 1/s; dt x rate = " << num(o.dt * plan.fastest) << ")\n"
        << "output   " << (o.csv ? o.csv->string() : std::string("table below")) << ", every "
        << num(static_cast<double>(plan.sample_every) * o.dt) << " s\n";
}

std::string csv_text(const MeanfieldPlan& plan, const std::vector<MeanFieldSample>& samples) {
    const MeanFieldParameters& m = plan.options.model;
    const MeanfieldOptions& o = plan.options;
    std::string s = std::string("# rodsea ") + RODSEA_VERSION +
                    " meanfield; units: t [s] Px [1] Py [1] vx [mm/s] vy [mm/s] P [1] "
                    "P_adiabatic [1]; a=" +
                    exact_number(m.a) + " lambda=" + exact_number(m.lambda) +
                    " b=" + exact_number(m.b) + " friction=" + exact_number(m.friction) +
                    " alpha=" + exact_number(m.alpha) + " rho=" + exact_number(m.rho) +
                    " p0=" + exact_number(o.p0) + " angle=" + exact_number(o.angle) +
                    " v0=" + exact_number(o.v0) + " dt=" + exact_number(o.dt) +
                    "\nt,Px,Py,vx,vy,P,P_adiabatic\n";
    for (const MeanFieldSample& x : samples) {
        s += exact_number(x.t) + ',' + exact_number(x.px) + ',' + exact_number(x.py) + ',' +
             exact_number(x.vx) + ',' + exact_number(x.vy) + ',' + exact_number(x.p) + ',' +
             exact_number(adiabatic_polar_order(m, o.p0, x.t)) + '\n';
    }
    return s;
}

void print_table(const MeanfieldPlan& plan, const std::vector<MeanFieldSample>& samples,
                 std::ostream& out) {
    out << "          t/s            Px            Py     vx/(mm/s)     vy/(mm/s)           |P|"
           "  |P| rho->0\n";
    for (const MeanFieldSample& x : samples) {
        out << fixed_width(x.t) << ' ' << fixed_width(x.px) << ' ' << fixed_width(x.py) << ' '
            << fixed_width(x.vx) << ' ' << fixed_width(x.vy) << ' ' << fixed_width(x.p) << ' '
            << fixed_width(adiabatic_polar_order(plan.options.model, plan.options.p0, x.t)) << '\n';
    }
}

void report_result(const MeanfieldPlan& plan, const std::vector<MeanFieldSample>& samples,
                   std::ostream& out) {
    const MeanFieldSample& last = samples.back();
    out << "result   |P|(" << num(last.t) << " s) = " << num(last.p)
        << ", closed-form steady |P| = " << num(plan.steady);
    if (plan.c > 0.0 && std::isfinite(plan.steady)) {
        const double relative = std::abs(last.p - plan.steady) / plan.steady;
        out << " (relative difference " << num(relative) << ")\n";
        const double relax = steady_relaxation_rate(plan.options.model);
        if (relative > 1e-4 && relax > 0.0 && last.p > 0.0) {
            // Growth from small |P| at the linear rate, then the approach at the relaxation
            // rate down to 1e-6: a rough estimate that says how much longer to run.
            double more = std::log(std::min(relative, 0.5) / 1e-6) / relax;
            if (last.p < 0.5 * plan.steady)
                more += std::log(0.5 * plan.steady / last.p) / plan.linear_rate;
            out << "         not steady yet: about " << num(more)
                << " s more to reach 1e-6 (--duration " << num(last.t + more) << ")\n";
        }
    } else {
        out << "\n";
        if (plan.c < 0.0 && samples.size() >= 2) {
            const MeanFieldSample& before = samples[samples.size() - 2];
            if (before.p > 0.0 && last.p > 0.0 && last.t > before.t) {
                out << "         decay rate over the last interval "
                    << num(std::log(before.p / last.p) / (last.t - before.t))
                    << " 1/s (|c| = " << num(-plan.c) << ", with the lag of v "
                    << num(-plan.linear_rate) << ")\n";
            }
        }
    }
}

}  // namespace

int meanfield_command(const std::vector<std::string>& args, std::ostream& out) {
    const MeanfieldOptions options = parse_options(args);
    if (options.help) {
        out << help_text(meanfield_command_spec());
        return 0;
    }
    const MeanfieldPlan plan = make_plan(options);
    describe(plan, out);
    const MeanFieldState initial{
        options.p0 * std::cos(options.angle), options.p0 * std::sin(options.angle),
        options.v0 * std::cos(options.angle), options.v0 * std::sin(options.angle)};
    const std::vector<MeanFieldSample> samples =
        integrate_mean_field(options.model, initial, options.dt, plan.steps, plan.sample_every);
    if (options.csv) {
        write_file_atomically(*options.csv, csv_text(plan, samples));
        out << "wrote    " << samples.size() << " rows to " << options.csv->string() << "\n";
    } else {
        print_table(plan, samples, out);
    }
    report_result(plan, samples, out);
    return 0;
}

}  // namespace rodsea
