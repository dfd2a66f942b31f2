#pragma once
// The paper's minimal mean-field model (End Matter, eqs. P_eom and v_eom; docs/model.md §5): the
// spatially averaged polar order P of the motile rods and the mean medium velocity v,
//   dP/dt     = -a P + lambda v - b |P|^2 P
//   rho dv/dt = -Gamma_f v + alpha P
// It is the paper's explanation of segregation-induced disorder (stronger segregation lowers
// alpha), so rodsea ships it next to the particle simulation to compare the two. docs/meanfield.md
// has the closed forms, the units and how a and alpha relate to measured quantities.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

// Units: time in s, P dimensionless, v in mm/s, M any mass unit (the simulator's masses are in
// an arbitrary unit too; only rho/Gamma_f and alpha/Gamma_f enter the dynamics, in s and mm/s).
// Physical sign conventions of the paper: lambda, alpha >= 0 (the flow aligns P with v, the
// rods push the medium along P); a may be negative (collision-induced alignment at D_r -> 0).
// The defaults are ordered: c = alpha lambda/Gamma_f - a = 0.5 1/s, steady |P| = 1/sqrt(2), and v
// relaxes ten times faster than P (rho/Gamma_f = 0.1 s against 1/(2c) = 1 s).
struct MeanFieldParameters {
    double a = 0.1;        // 1/s: relaxation rate of P by angular noise (about D_r when dilute)
    double lambda = 0.15;  // 1/mm (= (1/s) per (mm/s)): flow-induced ordering
    double b = 1.0;        // 1/s: cubic saturation of |P|
    double friction =
        1.0;             // Gamma_f, M mm^-2 s^-1: friction with the plates (not the drive's Gamma)
    double alpha = 4.0;  // M mm^-1 s^-2 (force per area): active forcing of the medium by the rods
    double rho = 0.1;    // M mm^-2: mass per area of the medium
};

// Throws InvalidParameter (named prefix + field, e.g. "--rho") unless every field is finite,
// lambda >= 0, b >= 0, friction > 0, alpha >= 0 and rho > 0.
void check_mean_field_parameters(const MeanFieldParameters& p, const std::string& prefix = "");

// c = alpha lambda / Gamma_f - a: the growth rate of small P once v is slaved to P (1/s).
double effective_growth_rate(const MeanFieldParameters& p);

// sqrt((alpha lambda - a Gamma_f)/(b Gamma_f)) when that is positive, else 0 (also at c = 0, where
// |P| decays algebraically; with b = 0 and c = 0 every |P| is steady and 0 is returned). +inf when
// b = 0 and c > 0: nothing saturates the growth. Exact for the full system too: at a fixed point
// v = alpha P / Gamma_f whatever rho is.
double steady_polar_order(const MeanFieldParameters& p);

// |P|(t) of the adiabatic (rho -> 0) Landau equation dP/dt = c P - b |P|^2 P from |P|(0) = p0 >= 0,
// t >= 0: p0 e^{ct} / sqrt(1 + b p0^2 (e^{2ct} - 1)/c), which is p0 / sqrt(1 + 2 b p0^2 t) at c =
// 0. Evaluated without overflow for any t.
double adiabatic_polar_order(const MeanFieldParameters& p, double p0, double t);

// The exact eigenvalue of the linearised full system at P = 0 that tends to c as rho -> 0: the
// growth (> 0) or decay (< 0) rate of small P including the lag of v (1/s).
double linear_growth_rate(const MeanFieldParameters& p);

// The rate (1/s) at which |P| settles onto its steady value: minus the slow eigenvalue of the
// radial P-v block linearised at the fixed point. 2c/(1 + eps) when ordered and |c|/(1 + eps)
// when disordered, to first order in eps = lambda alpha rho / Gamma_f^2; 0 at c = 0 (algebraic
// approach) and when b = 0 and c > 0 (no fixed point). The tangential block has a zero
// eigenvalue at an ordered fixed point: the direction of P is free (rotational invariance).
double steady_relaxation_rate(const MeanFieldParameters& p);

// An upper bound on |P| along every trajectory from |P0| = p0, |v0| = v0 (b > 0): the box
// |P| <= Pm, |v| <= alpha Pm / Gamma_f with Pm >= max(p0, steady |P|) and large enough to contain
// v0 cannot be left (on its faces d|P|/dt <= Pm (c - b Pm^2) <= 0 and d|v|/dt <= 0). +inf when
// b = 0 and the linear system grows.
double polar_order_bound(const MeanFieldParameters& p, double p0, double v0);

// The largest |eigenvalue| of the Jacobian over states with |P| <= p_max (1/s): the rate that
// limits the explicit time step. The Jacobian splits into a radial and a tangential 2x2 block;
// their eigenvalues are monotonic in the P-diagonal entry, so the extremes of |P| bound them.
double fastest_rate(const MeanFieldParameters& p, double p_max);

// RK4 is stable for a decaying mode of rate k when dt k < 2.785 (its stability interval on the
// negative real axis; every eigenvalue here is real since lambda alpha >= 0).
constexpr double kRk4StabilityLimit = 2.785;
double max_stable_time_step(const MeanFieldParameters& p, double p_max);

struct MeanFieldState {
    double px = 0.0, py = 0.0;  // P, dimensionless
    double vx = 0.0, vy = 0.0;  // v, mm/s
};

struct MeanFieldSample {
    double t = 0.0;  // s
    double px = 0.0, py = 0.0, vx = 0.0, vy = 0.0;
    double p = 0.0;  // |P|
};

// d(state)/dt of the full four-component system.
MeanFieldState mean_field_derivative(const MeanFieldParameters& p, const MeanFieldState& s);

// One classical fourth-order Runge-Kutta step of length dt.
MeanFieldState rk4_step(const MeanFieldParameters& p, const MeanFieldState& s, double dt);

// `steps` RK4 steps of fixed length dt from `initial`; a sample at step 0, every `sample_every`
// steps and at the last step, with t = step * dt (not accumulated, so no rounding drift).
// Throws InvalidParameter naming "dt" when the state stops being finite (dt beyond stability).
std::vector<MeanFieldSample> integrate_mean_field(const MeanFieldParameters& p,
                                                  const MeanFieldState& initial, double dt,
                                                  long long steps, long long sample_every);

// `rodsea meanfield [options]`: args are everything after "meanfield". Prints the plan, the
// trajectory (or writes it to --csv) and the numerical steady |P| against the closed form.
// Throws InvalidParameter for an unknown option or a bad value before computing anything, and
// FileError when the CSV cannot be written. Returns 0.
int meanfield_command(const std::vector<std::string>& args, std::ostream& out);

const CommandSpec& meanfield_command_spec();

}  // namespace rodsea
