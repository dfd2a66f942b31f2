// The mean-field model against its closed forms: the steady |P| of the full system, the decay
// rate of the disordered state, the adiabatic (rho -> 0) Landau solution, RK4's fourth order,
// rotational invariance, the stability limit, and the command's refusals and CSV output.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "rodsea/error.hpp"
#include "rodsea/meanfield/mean_field.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

MeanFieldState along(double angle, double p0, double v0) {
    return {p0 * std::cos(angle), p0 * std::sin(angle), v0 * std::cos(angle), v0 * std::sin(angle)};
}

MeanFieldSample run_to(const MeanFieldParameters& p, const MeanFieldState& s, double dt, double t) {
    const auto steps = static_cast<long long>(std::llround(t / dt));
    return integrate_mean_field(p, s, dt, steps, steps).back();
}

// The InvalidParameter a command line throws (its name, or "" when nothing is thrown), and
// whether anything was printed before it.
struct Refusal {
    std::string name;
    std::string message;
    bool printed = false;
};

Refusal refusal_of(const std::vector<std::string>& args) {
    std::ostringstream out;
    Refusal r;
    try {
        meanfield_command(args, out);
    } catch (const InvalidParameter& e) {
        r.name = e.name();
        r.message = e.what();
    }
    r.printed = !out.str().empty();
    return r;
}

std::vector<std::string> split(const std::string& line, char sep) {
    std::vector<std::string> parts;
    std::stringstream s(line);
    std::string part;
    while (std::getline(s, part, sep))
        parts.push_back(part);
    return parts;
}

// The integrator reaches the closed-form steady |P| for several parameter sets, including a
// negative a (the paper's D_r -> 0 regime) and a heavy medium (rho/Gamma_f = 5 s, far from the
// adiabatic limit): at a fixed point v = alpha P / Gamma_f whatever rho is, so the formula is
// exact. RK4's fixed points are exactly the ODE's (all four stages vanish there). Each run
// grows from 0.01 at the linear rate, then relaxes at the steady relaxation rate for 40 e-folds,
// so only rounding is left: 1e-10 relative.
TEST(MeanField, IntegratorReachesClosedFormSteadyOrder) {
    MeanFieldParameters heavy;
    heavy.rho = 5.0;
    MeanFieldParameters negative_a;
    negative_a.a = -0.2;
    negative_a.alpha = 0.5;
    negative_a.b = 0.3;
    for (const MeanFieldParameters& p : {MeanFieldParameters{}, heavy, negative_a}) {
        ASSERT_GT(effective_growth_rate(p), 0.0);
        const double expected =
            std::sqrt((p.alpha * p.lambda - p.a * p.friction) / (p.b * p.friction));
        EXPECT_DOUBLE_EQ(steady_polar_order(p), expected);
        const double duration =
            std::log(expected / 0.01) / linear_growth_rate(p) + 40.0 / steady_relaxation_rate(p);
        const MeanFieldSample end = run_to(p, along(0.3, 0.01, 0.0), 1e-3, duration);
        EXPECT_NEAR(end.p, expected, 1e-10 * expected) << "rho = " << p.rho << ", a = " << p.a;
        EXPECT_NEAR(std::hypot(end.vx, end.vy), p.alpha / p.friction * expected,
                    1e-10 * p.alpha / p.friction * expected);
    }
}

// The relaxation rates tend to their adiabatic values 2c (ordered: the Landau equation
// linearised at P* gives -2c) and |c| (disordered) as rho -> 0, with a relative correction
// eps = lambda alpha rho / Gamma_f^2 = 6e-5 at rho = 1e-4: 2 eps relative is allowed. A heavy
// medium relaxes far more slowly than 2c (0.119 against 1 1/s), which is why the report prints
// the exact rate.
TEST(MeanField, SteadyRelaxationRateTendsToAdiabaticValue) {
    MeanFieldParameters p;
    p.rho = 1e-4;
    const double eps = p.lambda * p.alpha * p.rho / (p.friction * p.friction);
    const double c = effective_growth_rate(p);
    EXPECT_NEAR(steady_relaxation_rate(p), 2.0 * c, 2.0 * eps * 2.0 * c);
    EXPECT_NEAR(linear_growth_rate(p), c, 2.0 * eps * c);
    p.a = 1.0;
    EXPECT_NEAR(steady_relaxation_rate(p), -effective_growth_rate(p),
                2.0 * eps * -effective_growth_rate(p));
    MeanFieldParameters heavy;
    heavy.rho = 5.0;
    // Radial block at P* = 1/sqrt(2): [[-a - 3 b P*^2, lambda], [alpha/rho, -Gamma_f/rho]] =
    // [[-1.6, 0.15], [0.8, -0.2]], trace -1.8, determinant 0.2.
    EXPECT_NEAR(steady_relaxation_rate(heavy), (1.8 - std::sqrt(1.8 * 1.8 - 0.8)) / 2.0, 1e-12);
    MeanFieldParameters unsaturated;
    unsaturated.b = 0.0;
    EXPECT_EQ(steady_relaxation_rate(unsaturated), 0.0);
}

// alpha lambda < a Gamma_f: |P| -> 0. Once |P| is small the cubic term is negligible and
// log|P| falls linearly at the slow eigenvalue of the linear system, which is c/(1 + eps) to
// first order in eps = lambda alpha rho / Gamma_f^2 (= 0.002 here): the measured rate matches
// |c| within 2 eps relative and the exact eigenvalue within 1e-5 (the leftover cubic term,
// b |P|^2 < 3e-6 over the fit window, relative to |c| = 0.8).
TEST(MeanField, DisorderedStateDecaysAtRateC) {
    MeanFieldParameters p;
    p.a = 1.0;
    p.lambda = 0.1;
    p.alpha = 2.0;
    p.rho = 0.01;
    const double c = effective_growth_rate(p);
    ASSERT_DOUBLE_EQ(c, -0.8);
    EXPECT_EQ(steady_polar_order(p), 0.0);
    const double eps = p.lambda * p.alpha * p.rho / (p.friction * p.friction);
    const MeanFieldState start = along(0.0, 0.1, p.alpha / p.friction * 0.1);
    const MeanFieldSample at5 = run_to(p, start, 1e-3, 5.0);
    const MeanFieldSample at10 = run_to(p, start, 1e-3, 10.0);
    const double rate = std::log(at5.p / at10.p) / 5.0;
    EXPECT_NEAR(rate, -c, 2.0 * eps * -c);
    EXPECT_NEAR(rate, -linear_growth_rate(p), 1e-5 * -c);
    EXPECT_LT(at10.p, 0.1 * std::exp(c * 10.0) * 1.1);
}

// With a light medium v is slaved to P and |P|(t) follows the Landau closed form. To first
// order in eps = lambda alpha rho / Gamma_f^2, v = (alpha/Gamma_f)(P - (rho/Gamma_f) dP/dt), so
// the full dynamics is the Landau one slowed by 1 + eps: |P|(t) ~ P_L(t/(1 + eps)), an error of
// at most eps sup_t t |dP_L/dt| (plus O(eps^2)); the test allows 1.5 times that. The error is
// first order in rho, so a ten times lighter medium must shrink it about ten times; and with
// the time rescaled by 1 + eps what is left is second order, shrinking about a hundred times.
TEST(MeanField, SmallRhoFollowsAdiabaticLandauSolution) {
    struct Errors {
        double plain = 0.0, rescaled = 0.0, bound = 0.0;
    };
    const auto errors_for = [](double rho) {
        MeanFieldParameters p;
        p.rho = rho;
        const double p0 = 0.01;
        const double eps = p.lambda * p.alpha * p.rho / (p.friction * p.friction);
        const double c = effective_growth_rate(p);
        const std::vector<MeanFieldSample> samples =
            integrate_mean_field(p, along(0.0, p0, p.alpha / p.friction * p0), 1e-3, 20000, 100);
        Errors e;
        double sup_t_slope = 0.0;
        for (const MeanFieldSample& s : samples) {
            const double landau = adiabatic_polar_order(p, p0, s.t);
            e.plain = std::max(e.plain, std::abs(s.p - landau));
            e.rescaled = std::max(e.rescaled,
                                  std::abs(s.p - adiabatic_polar_order(p, p0, s.t / (1.0 + eps))));
            sup_t_slope =
                std::max(sup_t_slope, s.t * (c * landau - p.b * landau * landau * landau));
        }
        e.bound = 1.5 * eps * sup_t_slope;
        return e;
    };
    const Errors heavy = errors_for(0.01);  // eps = 0.006
    const Errors light = errors_for(0.001);
    EXPECT_LT(heavy.plain, heavy.bound);
    EXPECT_LT(light.plain, light.bound);
    EXPECT_GT(heavy.plain / light.plain, 7.0);
    EXPECT_LT(heavy.plain / light.plain, 13.0);
    EXPECT_GT(heavy.rescaled / light.rescaled, 50.0);
}

// The closed form solves dP/dt = c P - b P^3 for c > 0, c = 0 and c < 0: a central difference
// with h = 1e-4 s has truncation error h^2/6 |P'''| < 1e-9 for these rates, and rounding
// 1e-16/h ~ 1e-12, so 1e-8 is ample. It starts at p0 and is continuous through c = 0.
TEST(MeanField, AdiabaticClosedFormSolvesLandauEquation) {
    for (const double a : {0.1, 0.6, 1.5}) {  // c = 0.5, 0, -0.9
        MeanFieldParameters p;
        p.a = a;
        const double c = effective_growth_rate(p);
        const double p0 = 0.3;
        EXPECT_DOUBLE_EQ(adiabatic_polar_order(p, p0, 0.0), p0);
        for (const double t : {0.5, 2.0, 7.0}) {
            const double h = 1e-4;
            const double slope =
                (adiabatic_polar_order(p, p0, t + h) - adiabatic_polar_order(p, p0, t - h)) /
                (2 * h);
            const double x = adiabatic_polar_order(p, p0, t);
            EXPECT_NEAR(slope, c * x - p.b * x * x * x, 1e-8) << "a = " << a << ", t = " << t;
        }
    }
    MeanFieldParameters marginal;
    marginal.a = 0.6;
    MeanFieldParameters just_above = marginal, just_below = marginal;
    just_above.a -= 1e-9;
    just_below.a += 1e-9;
    const double at_zero = adiabatic_polar_order(marginal, 0.3, 5.0);
    EXPECT_DOUBLE_EQ(at_zero, 0.3 / std::sqrt(1.0 + 2.0 * 0.09 * 5.0));
    EXPECT_NEAR(adiabatic_polar_order(just_above, 0.3, 5.0), at_zero, 1e-8);
    EXPECT_NEAR(adiabatic_polar_order(just_below, 0.3, 5.0), at_zero, 1e-8);
}

// e^{2ct} overflows a double beyond ct ~ 355; the closed form must still give the steady value
// (ordered) or 0 (disordered) rather than inf/inf.
TEST(MeanField, AdiabaticClosedFormHasNoOverflow) {
    const MeanFieldParameters ordered;
    EXPECT_DOUBLE_EQ(adiabatic_polar_order(ordered, 0.01, 1e4), steady_polar_order(ordered));
    MeanFieldParameters disordered;
    disordered.a = 2.0;
    EXPECT_EQ(adiabatic_polar_order(disordered, 0.01, 1e4), 0.0);
    EXPECT_EQ(adiabatic_polar_order(ordered, 0.0, 50.0), 0.0);
}

// Classical RK4 is fourth order: halving dt divides the global error by 2^4 = 16. The run
// (dt x fastest rate <= 0.22) is in the asymptotic regime, where the next term changes the
// ratio by O(dt k), under 10 %, so each ratio must lie in [14, 18]. The reference uses dt/64,
// whose own error is 64^-4 ~ 6e-8 of the coarsest one.
TEST(MeanField, Rk4IsFourthOrder) {
    const MeanFieldParameters p;
    const MeanFieldState start = along(0.0, 0.1, 0.0);
    const double t_end = 4.0;
    const double dt = 0.02;
    ASSERT_LT(dt * fastest_rate(p, polar_order_bound(p, 0.1, 0.0)), 0.22);
    const MeanFieldSample reference = run_to(p, start, dt / 64.0, t_end);
    double errors[3];
    for (int i = 0; i < 3; ++i) {
        const MeanFieldSample s = run_to(p, start, dt / std::pow(2.0, i), t_end);
        errors[i] = std::hypot(s.px - reference.px, s.py - reference.py);
    }
    EXPECT_GT(errors[2], 1e-13);  // well above rounding, so the ratios mean something
    for (int i = 0; i < 2; ++i) {
        const double ratio = errors[i] / errors[i + 1];
        EXPECT_GT(ratio, 14.0) << "dt = " << dt / std::pow(2.0, i);
        EXPECT_LT(ratio, 18.0) << "dt = " << dt / std::pow(2.0, i);
    }
}

// The equations are invariant under rotations: with P0 and v0 along one direction every
// derivative stays along it, so P's direction never changes (up to rounding, ~1e-16 per step)
// and |P|(t) is the same for every direction (up to the rounding of cos and sin).
TEST(MeanField, DirectionOfPolarOrderStaysFixed) {
    const MeanFieldParameters p;
    const double angle = 2.4;
    const std::vector<MeanFieldSample> turned =
        integrate_mean_field(p, along(angle, 0.05, 0.1), 1e-3, 20000, 500);
    const std::vector<MeanFieldSample> straight =
        integrate_mean_field(p, along(0.0, 0.05, 0.1), 1e-3, 20000, 500);
    ASSERT_EQ(turned.size(), straight.size());
    for (size_t i = 0; i < turned.size(); ++i) {
        EXPECT_NEAR(std::atan2(turned[i].py, turned[i].px), angle, 1e-12) << "t = " << turned[i].t;
        EXPECT_NEAR(std::atan2(turned[i].vy, turned[i].vx), angle, 1e-12) << "t = " << turned[i].t;
        EXPECT_NEAR(turned[i].p, straight[i].p, 1e-13) << "t = " << turned[i].t;
        EXPECT_EQ(straight[i].py, 0.0);
    }
}

// The refused step is the real RK4 limit: in a linear decaying system (b = 0) the fast mode is
// amplified by |R(dt k)| per step, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, which exceeds 1 just
// beyond dt k = 2.785. At 0.98 of the limit the run stays bounded and decays; at 1.05 of it
// the fast mode grows ~1.2x per step and overflows within 4000 steps, which the integrator
// reports as a dt problem.
TEST(MeanField, StabilityLimitIsTheRk4Limit) {
    MeanFieldParameters p;
    p.b = 0.0;
    p.a = 1.0;  // c = -0.4: decaying
    p.rho = 0.01;
    const double limit = max_stable_time_step(p, 1.0);
    EXPECT_NEAR(limit * fastest_rate(p, 1.0), kRk4StabilityLimit, 1e-12);
    const MeanFieldState start = along(0.0, 0.1, 0.0);
    const std::vector<MeanFieldSample> stable =
        integrate_mean_field(p, start, 0.98 * limit, 20000, 20000);
    EXPECT_LT(stable.back().p, 0.1);
    try {
        integrate_mean_field(p, start, 1.05 * limit, 20000, 20000);
        ADD_FAILURE() << "dt beyond the RK4 limit did not diverge";
    } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.name(), "dt");
    }
}

// Every refusal names the option, says what is allowed, and comes before any output.
TEST(MeanField, CommandRejectsBadOptions) {
    const Refusal unknown = refusal_of({"--bogus", "1"});
    EXPECT_EQ(unknown.name, "--bogus");
    EXPECT_NE(unknown.message.find("--friction"), std::string::npos) << unknown.message;
    EXPECT_EQ(refusal_of({"stray"}).name, "stray");
    EXPECT_EQ(refusal_of({"--rho", "0"}).name, "--rho");
    EXPECT_EQ(refusal_of({"--friction", "-1"}).name, "--friction");
    EXPECT_EQ(refusal_of({"--b", "-0.5"}).name, "--b");
    EXPECT_EQ(refusal_of({"--alpha", "nan"}).name, "--alpha");
    EXPECT_EQ(refusal_of({"--dt", "abc"}).name, "--dt");
    EXPECT_EQ(refusal_of({"--dt"}).name, "--dt");
    EXPECT_EQ(refusal_of({"--dt", "0.01", "--dt", "0.02"}).name, "--dt");
    EXPECT_EQ(refusal_of({"--samples", "0"}).name, "--samples");
    EXPECT_EQ(refusal_of({"--samples", "2.5"}).name, "--samples");
    EXPECT_EQ(refusal_of({"--samples", "100", "--duration", "1", "--dt", "0.1"}).name, "--samples");
    EXPECT_EQ(refusal_of({"--p0", "-0.1"}).name, "--p0");
    EXPECT_EQ(refusal_of({"--csv", "/nonexistent-rodsea-dir/x.csv"}).name, "--csv");
    EXPECT_EQ(refusal_of({"--b", "0", "--duration", "2000"}).name, "--duration");

    // The default model's fastest rate is ~10.6 1/s, so dt = 1 s is far beyond the limit,
    // which the message gives.
    const MeanFieldParameters p;
    const double limit = max_stable_time_step(p, polar_order_bound(p, 0.01, 0.0));
    const Refusal unstable = refusal_of({"--dt", "1"});
    EXPECT_EQ(unstable.name, "--dt");
    EXPECT_NE(unstable.message.find(format_number(limit)), std::string::npos) << unstable.message;
    for (const auto& args :
         std::vector<std::vector<std::string>>{{"--bogus", "1"}, {"--rho", "0"}, {"--dt", "1"}})
        EXPECT_FALSE(refusal_of(args).printed) << args[0];
}

// The report states the regime and ends with the numerical steady |P| next to the closed form.
TEST(MeanField, CommandReportsRegimeAndSteadyValue) {
    std::ostringstream ordered;
    EXPECT_EQ(meanfield_command({"--duration", "40", "--dt", "0.01", "--samples", "4"}, ordered),
              0);
    EXPECT_NE(ordered.str().find("ordered"), std::string::npos) << ordered.str();
    EXPECT_NE(ordered.str().find("0.707107"), std::string::npos) << ordered.str();
    EXPECT_NE(ordered.str().find("closed-form steady |P| = 0.707107"), std::string::npos);

    std::ostringstream disordered;
    EXPECT_EQ(meanfield_command({"--a", "1", "--duration", "10", "--samples", "2"}, disordered), 0);
    EXPECT_NE(disordered.str().find("disordered"), std::string::npos) << disordered.str();

    std::ostringstream help;
    EXPECT_EQ(meanfield_command({"--help"}, help), 0);
    EXPECT_EQ(help.str(), help_text(meanfield_command_spec()));
}

// The CSV holds every sample as the shortest text that reads back as the same double, so it
// parses back to the very numbers the integrator produces; P_adiabatic is the closed form.
TEST(MeanField, CsvParsesBackToTheTrajectory) {
    const ScratchDir dir("meanfield-csv");
    const auto path = dir.path() / "traj.csv";
    std::ostringstream out;
    ASSERT_EQ(meanfield_command(
                  {"--rho", "0.05", "--p0", "0.2", "--angle", "1.1", "--v0", "0.3", "--duration",
                   "5", "--dt", "0.002", "--samples", "10", "--csv", path.string()},
                  out),
              0);
    MeanFieldParameters p;
    p.rho = 0.05;
    const std::vector<MeanFieldSample> expected =
        integrate_mean_field(p, along(1.1, 0.2, 0.3), 0.002, 2500, 250);

    std::ifstream in(path);
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line.rfind("# rodsea", 0), 0u) << line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line, "t,Px,Py,vx,vy,P,P_adiabatic");
    size_t row = 0;
    while (std::getline(in, line)) {
        ASSERT_LT(row, expected.size());
        const std::vector<std::string> f = split(line, ',');
        ASSERT_EQ(f.size(), 7u) << line;
        const MeanFieldSample& e = expected[row];
        EXPECT_EQ(std::stod(f[0]), e.t);
        EXPECT_EQ(std::stod(f[1]), e.px);
        EXPECT_EQ(std::stod(f[2]), e.py);
        EXPECT_EQ(std::stod(f[3]), e.vx);
        EXPECT_EQ(std::stod(f[4]), e.vy);
        EXPECT_EQ(std::stod(f[5]), e.p);
        EXPECT_EQ(std::stod(f[6]), adiabatic_polar_order(p, 0.2, e.t));
        ++row;
    }
    EXPECT_EQ(row, expected.size());
    EXPECT_EQ(row, 11u);
    EXPECT_NE(out.str().find("wrote    11 rows"), std::string::npos) << out.str();
    // Only the CSV is left in the directory: the temporary file was renamed onto it.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                            std::filesystem::directory_iterator()),
              1);
}

}  // namespace
}  // namespace rodsea
