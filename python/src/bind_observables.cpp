// Observables as compute objects on numpy arrays, in freud's style: parameters in the
// constructor, compute(box, ...) (which accumulates over calls, one call per frame, and returns
// the object), results as array properties. They are the classes `rodsea analyze` runs, so the
// numbers are the CLI's. Boxes are (L_x, L_y) in mm; positions (N, 2 or 3) in mm; angles in rad.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <vector>

#include "array_arguments.hpp"
#include "bindings.hpp"
#include "rodsea/analysis/corotating_maps.hpp"
#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analysis/density_modes.hpp"
#include "rodsea/analysis/medium_velocity.hpp"
#include "rodsea/analysis/neighbor_query.hpp"
#include "rodsea/analysis/pair_correlation.hpp"
#include "rodsea/analysis/segregation.hpp"
#include "rodsea/analysis/time_correlation.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/error.hpp"

namespace py = pybind11;

namespace rodsea::python {

namespace {

// compute(box, positions, angles) of a group observable (PairCorrelation, CorotatingMaps).
template <class Observable>
Observable& compute_group(Observable& self, const py::sequence& box, const Doubles& positions,
                          const Doubles& angles) {
    const std::vector<Vec3> p = points_of(positions, "positions");
    const std::vector<double> a = values_of(angles, p.size(), "angles");
    self.compute(box_of(box), p, a);
    return self;
}

}  // namespace

void bind_observables(py::module_& m) {
    m.def(
        "order_parameter",
        [](const Doubles& angles, int m_fold) {
            return orientational_order(all_values_of(angles, "angles"), fold_of(m_fold));
        },
        py::arg("angles"), py::arg("m") = 1,
        "|⟨(cos mθ, sin mθ)⟩|: m = 1 the polar order P, m = 2 the nematic order S");
    m.def(
        "in_plane_angles",
        [](const Doubles& q) {
            if (q.ndim() != 2 || q.shape(1) != 4)
                throw InvalidParameter("quaternions", "another shape", "shape (N, 4)");
            const auto r = q.unchecked<2>();
            py::array_t<double> out(q.shape(0));
            auto w = out.mutable_unchecked<1>();
            for (py::ssize_t i = 0; i < q.shape(0); ++i) {
                const Quat qi{r(i, 0), r(i, 1), r(i, 2), r(i, 3)};
                // Unit within 10⁻³, as a trajectory's quaternions are checked.
                const double norm =
                    std::sqrt(qi.w * qi.w + qi.x * qi.x + qi.y * qi.y + qi.z * qi.z);
                if (!(std::abs(norm - 1.0) <= 1e-3))
                    throw InvalidParameter("quaternions[" + std::to_string(i) + "]",
                                           "of norm " + format_number(norm),
                                           "a unit quaternion (w, x, y, z), within 1e-3");
                w(i) = in_plane_angle(qi);
            }
            return out;
        },
        py::arg("quaternions"), "θ of each body's axis in the x-y plane (thick → thin), rad");

    py::class_<PairCorrelation>(m, "PairCorrelation",
                                "g(r), G(r) = ⟨cos Δθ⟩ and G₂(r) = ⟨cos 2Δθ⟩ of one group")
        .def(py::init([](double r_max, double bin) {
                 return PairCorrelation({.r_max = r_max, .bin = bin});
             }),
             py::arg("r_max") = 45.0, py::arg("bin") = 0.25)
        .def("compute", &compute_group<PairCorrelation>, py::arg("box"), py::arg("positions"),
             py::arg("angles"), py::return_value_policy::reference_internal)
        .def_property_readonly("bin_centers",
                               [](const PairCorrelation& s) { return array(s.bin_centres()); })
        .def_property_readonly("g",
                               [](const PairCorrelation& s) { return array(s.pair_density()); })
        .def_property_readonly(
            "G", [](const PairCorrelation& s) { return array(s.polar_correlation()); })
        .def_property_readonly(
            "G2", [](const PairCorrelation& s) { return array(s.nematic_correlation()); })
        .def_property_readonly("frames", &PairCorrelation::frames);

    py::class_<CorotatingMaps>(m, "CorotatingMaps",
                               "g(r,θ) and G(r,θ) in each rod's frame (θ from its axis)")
        .def(
            py::init([](double r_max, int r_bins, int theta_bins) {
                return CorotatingMaps({.r_max = r_max, .r_bins = r_bins, .theta_bins = theta_bins});
            }),
            py::arg("r_max") = 22.5, py::arg("r_bins") = 60, py::arg("theta_bins") = 72)
        .def("compute", &compute_group<CorotatingMaps>, py::arg("box"), py::arg("positions"),
             py::arg("angles"), py::return_value_policy::reference_internal)
        .def_property_readonly("r_edges",
                               [](const CorotatingMaps& s) { return array(s.r_edges()); })
        .def_property_readonly("theta_edges",
                               [](const CorotatingMaps& s) { return array(s.theta_edges()); })
        .def_property_readonly(
            "g",
            [](const CorotatingMaps& s) {
                return map_array(s.pair_density(), s.r_bins(), s.theta_bins());
            },
            "[r bin, θ bin]")
        .def_property_readonly(
            "G",
            [](const CorotatingMaps& s) {
                return map_array(s.polar_correlation(), s.r_bins(), s.theta_bins());
            },
            "[r bin, θ bin]")
        .def_property_readonly("frames", &CorotatingMaps::frames);

    m.def(
        "dbscan",
        [](const py::sequence& box, const Doubles& positions, double eps, int min_samples) {
            const std::vector<Vec3> p = points_of(positions, "positions");
            const std::vector<int> labels =
                dbscan(p, box_of(box), {.eps = eps, .min_samples = min_samples});
            return py::array_t<int>(static_cast<py::ssize_t>(labels.size()), labels.data());
        },
        py::arg("box"), py::arg("positions"), py::arg("eps") = 2.25, py::arg("min_samples") = 3,
        "DBSCAN flock labels (−1: in no flock), periodic in x and y, as sklearn's metric");

    m.def(
        "segregation",
        [](const py::sequence& box, const Doubles& positions,
           const py::array_t<bool, py::array::c_style | py::array::forcecast>& polar, double cell) {
            const PeriodicBox2D b = box_of(box);
            const std::vector<Vec3> p = points_of(positions, "positions");
            if (static_cast<std::size_t>(polar.size()) != p.size())
                throw InvalidParameter("is_polar", "another length",
                                       std::to_string(p.size()) + " flags");
            std::vector<std::uint8_t> flags(p.size());
            for (std::size_t i = 0; i < p.size(); ++i)
                flags[i] = polar.data()[i] ? 1 : 0;
            return segregation(b, segregation_grid(b, cell), p, flags);
        },
        py::arg("box"), py::arg("positions"), py::arg("is_polar"), py::arg("cell") = 9.0,
        "Σ of one frame over square cells of side `cell` (mm), without the random-mixing "
        "baseline (random_mixing_segregation gives it)");
    m.def(
        "random_mixing_segregation",
        [](const py::sequence& box, long long polar, long long others, double cell, int samples,
           std::uint64_t seed) {
            const PeriodicBox2D b = box_of(box);
            return random_mixing_segregation(polar, others, segregation_grid(b, cell), samples,
                                             seed);
        },
        py::arg("box"), py::arg("polar"), py::arg("others"), py::arg("cell") = 9.0,
        py::arg("samples") = 20, py::arg("seed") = 1);

    m.def(
        "bands",
        [](const py::sequence& box, const Doubles& positions, const Doubles& angles) {
            const std::vector<Vec3> p = points_of(positions, "positions");
            const std::vector<double> a = values_of(angles, p.size(), "angles");
            const double axis = director_angle(a);
            const BandAmplitudes b = band_amplitudes(box_of(box), p, axis);
            py::dict modes;
            for (std::size_t k = 0; k < kLongestModes.size(); ++k)
                modes[py::make_tuple(kLongestModes[k].mx, kLongestModes[k].my)] = b.modes[k];
            py::dict out;
            out["axis"] = axis;
            out["modes"] = modes;
            out["transverse"] = b.transverse;
            out["longitudinal"] = b.longitudinal;
            out["transverse_at"] = b.transverse_at;
            out["longitudinal_at"] = b.longitudinal_at;
            return out;
        },
        py::arg("box"), py::arg("positions"), py::arg("angles"),
        "the polar rods' longest density modes |ρ_k| of one frame ({(m_x, m_y): |ρ_k|}), their "
        "axis of motion (rad), the modes most nearly along it (transverse bands) and across it "
        "(longitudinal bands), and where those two peak along their k (mm), as the `bands` "
        "observable of rodsea analyze");

    py::class_<MediumVelocity>(m, "MediumVelocity",
                               "the medium's velocity around each polar rod, by distance")
        .def(py::init([](double d, double r_max, double bin) {
                 return MediumVelocity({.d = d, .r_max = r_max, .bin = bin});
             }),
             py::arg("d") = 100.0, py::arg("r_max") = 100.0, py::arg("bin") = 1.0)
        .def(
            "compute",
            [](MediumVelocity& self, const py::sequence& box, const Doubles& medium_positions,
               const Doubles& medium_velocities, const Doubles& rod_positions,
               const Doubles& rod_angles, const Doubles& rod_velocities) -> MediumVelocity& {
                const PeriodicBox2D b = box_of(box);
                const std::vector<Vec3> mp = points_of(medium_positions, "medium_positions");
                const std::vector<Vec3> mv = points_of(medium_velocities, "medium_velocities");
                const std::vector<Vec3> rp = points_of(rod_positions, "rod_positions");
                const std::vector<Vec3> rv = points_of(rod_velocities, "rod_velocities");
                const std::vector<double> ra = values_of(rod_angles, rp.size(), "rod_angles");
                require_rows(mv.size(), mp.size(), "medium_velocities", "medium_positions");
                require_rows(rv.size(), rp.size(), "rod_velocities", "rod_positions");
                self.compute(query_grid(b, mp), mv, rp, ra, rv);
                return self;
            },
            py::arg("box"), py::arg("medium_positions"), py::arg("medium_velocities"),
            py::arg("rod_positions"), py::arg("rod_angles"), py::arg("rod_velocities"),
            py::return_value_policy::reference_internal)
        .def_property_readonly("bin_centers",
                               [](const MediumVelocity& s) { return array(s.bin_centres()); })
        .def_property_readonly("pairs", [](const MediumVelocity& s) { return array(s.pairs()); })
        .def_property_readonly("along", [](const MediumVelocity& s) { return array(s.along()); })
        .def_property_readonly("across", [](const MediumVelocity& s) { return array(s.across()); })
        .def_property_readonly("speed", [](const MediumVelocity& s) { return array(s.speed()); })
        .def_property_readonly("relative_speed",
                               [](const MediumVelocity& s) { return array(s.relative_speed()); });

    m.def(
        "orientation_autocorrelation",
        [](const py::array_t<float, py::array::c_style | py::array::forcecast>& angles, int m_fold,
           std::size_t max_lag) {
            if (angles.ndim() != 2)
                throw InvalidParameter("angles", "another shape", "(frames, bodies), rad");
            const auto frames = static_cast<std::size_t>(angles.shape(0));
            const auto bodies = static_cast<std::size_t>(angles.shape(1));
            const std::span<const float> a(angles.data(), frames * bodies);
            for (std::size_t i = 0; i < a.size(); ++i)
                if (!std::isfinite(a[i]))
                    throw InvalidParameter("angles[" + std::to_string(i / bodies) + ", " +
                                               std::to_string(i % bodies) + "]",
                                           format_number(a[i]), "a finite angle, rad");
            return array(orientation_autocorrelation(a, frames, bodies, fold_of(m_fold), max_lag));
        },
        py::arg("angles"), py::arg("m") = 1, py::arg("max_lag"),
        "C(t) = ⟨cos m(θ(t₀+t) − θ(t₀))⟩ at lags 0 … max_lag frames (unwrapped angles)");
    m.def(
        "rotational_diffusion",
        [](const Doubles& c, double interval, int m_fold, double floor) {
            const std::vector<double> v = all_values_of(c, "c");
            require_positive("interval", interval, "s");
            if (!(floor > 0.0 && floor < 1.0))
                throw InvalidParameter("floor", format_number(floor), "(0, 1)");
            return rotational_diffusion_from(v, interval, fold_of(m_fold), floor,
                                             fit_lag_count(v, floor));
        },
        py::arg("c"), py::arg("interval"), py::arg("m") = 1, py::arg("floor") = 0.2,
        "D_r (rad²/s) from −ln C = m² D_r t over the lags where C ≥ floor");
}

}  // namespace rodsea::python
