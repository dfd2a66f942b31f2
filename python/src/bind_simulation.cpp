#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "bindings.hpp"
#include "config.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/run/checkpoint_checks.hpp"

namespace py = pybind11;

namespace rodsea::python {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Quat) == 4 * sizeof(double),
              "the zero-copy views read Vec3 and Quat as packed doubles");

// HOOMD's local snapshots: the engine's own arrays, read-only, with no copy: they follow the
// steps. Each view holds the engine it shows (a shared_ptr in its base capsule), so a view taken
// before set_state() stays valid and shows the state as it was then.
class PySimulation {
  public:
    PySimulation(const Config& config, std::optional<int> threads)
        : plan_(config.plan), sim_(make(plan_, threads)) {}
    PySimulation(RunPlan plan, BodyState bodies, std::uint64_t step, int threads)
        : plan_(std::move(plan)),
          sim_(std::make_shared<Simulation>(
              Simulation::resume(plan_.engine, std::move(bodies), step,
                                 {.threads = threads, .backend = plan_.control.backend}))) {}

    // Steps without the GIL: other Python threads run meanwhile, but none of them may use this
    // Simulation until run() returns (sim() refuses them). Exactly one of steps and seconds
    // (rounded to whole steps of dt), at most time.duration's largest value of simulated time.
    std::uint64_t run(std::optional<long long> steps, std::optional<double> seconds) {
        if (steps.has_value() == seconds.has_value())
            throw InvalidParameter("run", "steps and seconds", "exactly one of them");
        const double most_steps = kMostSeconds / plan_.engine.dt;
        long long n = 0;
        if (steps) {
            if (*steps < 0 || static_cast<double>(*steps) > most_steps)
                throw InvalidParameter("steps", std::to_string(*steps),
                                       "[0, " + format_number(std::floor(most_steps)) + "]",
                                       "at most " + format_number(kMostSeconds) + " s of dt " +
                                           format_number(plan_.engine.dt) + " s");
            n = *steps;
        } else {
            if (!std::isfinite(*seconds) || *seconds < 0.0 || *seconds > kMostSeconds)
                throw InvalidParameter("seconds", format_number(*seconds) + " s",
                                       "[0, " + format_number(kMostSeconds) + "] s");
            n = std::llround(*seconds / plan_.engine.dt);
        }
        const Busy busy(*this);
        const std::shared_ptr<Simulation> sim = sim_;
        // In chunks: between them the GIL is taken back for a moment, so that Ctrl-C
        // (KeyboardInterrupt) stops a long run within a few milliseconds.
        constexpr long long kChunk = 1024;
        for (long long done = 0; done < n;) {
            const long long chunk = std::min(kChunk, n - done);
            {
                py::gil_scoped_release free_the_interpreter;
                for (long long i = 0; i < chunk; ++i)
                    sim->step();
            }
            done += chunk;
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        }
        return static_cast<std::uint64_t>(n);
    }

    // Every use of the engine but run()'s own goes through here: while run() steps it in
    // another thread, reading it would give a state half stepped, and replacing it would pull it
    // from under the stepping thread.
    const Simulation& sim() const {
        if (busy_)
            throw std::runtime_error(
                "this Simulation is running in another thread: use it once run() has returned "
                "(a Simulation takes one call at a time)");
        return *sim_;
    }
    const std::shared_ptr<Simulation>& shared() const {
        sim();
        return sim_;
    }
    const RunPlan& plan() const { return plan_; }

    // Replaces the state (arrays as numpy gives them), checked as a resumed state is, the
    // overlaps between bodies included.
    void set_state(const BodyState& bodies) {
        const Simulation& now = sim();
        if (const auto p = find_gross_overlap(plan_.engine, bodies))
            throw InvalidParameter("bodies[" + std::to_string(p->body) + "]." + p->field, p->value,
                                   p->allowed, p->detail);
        sim_ = std::make_shared<Simulation>(
            Simulation::resume(plan_.engine, bodies, now.step_count(), now.options()));
    }

  private:
    // time.duration's range: what one call may ask for, so that seconds / dt stays a step count.
    static constexpr double kMostSeconds = 1e6;

    // Marks the Simulation as stepping for the life of a run() call. Set and cleared with the
    // GIL held, as every other call checks it, so that no second call slips in between.
    class Busy {
      public:
        explicit Busy(PySimulation& s) : s_(s) {
            s_.sim();  // a second run() from another thread is refused like any other call
            s_.busy_ = true;
        }
        ~Busy() { s_.busy_ = false; }
        Busy(const Busy&) = delete;
        Busy& operator=(const Busy&) = delete;

      private:
        PySimulation& s_;
    };

    static std::shared_ptr<Simulation> make(const RunPlan& plan, std::optional<int> threads) {
        const PackingCheck packing = check_packing(plan.engine, plan.counts);
        if (!packing.ok)
            throw InvalidParameter("species", "these counts", "a packing that fits",
                                   packing.message);
        BodyState bodies =
            build_initial_state(plan.engine, plan.counts, plan.builder, plan.engine.seed);
        require_usable_backend(plan.control.backend, "run.backend");
        return std::make_shared<Simulation>(plan.engine, std::move(bodies),
                                            BackendOptions{
                                                .threads = threads.value_or(plan.control.threads),
                                                .backend = plan.control.backend,
                                            });
    }
    RunPlan plan_;
    std::shared_ptr<Simulation> sim_;
    bool busy_ = false;
};

// The base of a view: a capsule owning a reference to the engine whose memory it shows.
py::capsule keep_alive(const std::shared_ptr<Simulation>& sim) {
    auto* held = new std::shared_ptr<Simulation>(sim);
    return py::capsule(held, [](void* p) { delete static_cast<std::shared_ptr<Simulation>*>(p); });
}

template <class T>
py::array view(const PySimulation& self, const std::vector<T>& data, std::size_t width) {
    const std::size_t n = data.size();
    py::array a(py::dtype::of<double>(), {n, width},
                {static_cast<py::ssize_t>(sizeof(T)), static_cast<py::ssize_t>(sizeof(double))},
                reinterpret_cast<const double*>(data.data()), keep_alive(self.shared()));
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

std::vector<Vec3> vectors(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                          std::size_t n, const char* name) {
    if (a.ndim() != 2 || a.shape(0) != static_cast<py::ssize_t>(n) || a.shape(1) != 3)
        throw InvalidParameter(
            name, "an array of shape (" + std::to_string(a.ndim() > 0 ? a.shape(0) : 0) + ", …)",
            "shape (" + std::to_string(n) + ", 3)");
    std::vector<Vec3> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = {a.at(i, 0), a.at(i, 1), a.at(i, 2)};
    return v;
}

}  // namespace

void bind_simulation(py::module_& m) {
    using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
    py::class_<PySimulation>(m, "Simulation",
                             "The engine on a config's initial state (as `rodsea run` builds it). "
                             "Arrays are read-only views of the engine's state, in mm, mm/s, "
                             "rad/s; they follow the simulation as it steps (on the GPU backend, "
                             "run.backend = \"gpu\", they are the host's copy as of when the "
                             "property was read).")
        .def(py::init<const Config&, std::optional<int>>(), py::arg("config"),
             py::arg("threads") = py::none())
        .def("run", &PySimulation::run, py::arg("steps") = py::none(),
             py::arg("seconds") = py::none(),
             "Steps `steps` times, or `seconds` of simulated time; releases the GIL. Returns the "
             "steps taken. Raises BlowUpError when a step blows up.")
        .def_property_readonly("step", [](const PySimulation& s) { return s.sim().step_count(); })
        .def_property_readonly(
            "time", [](const PySimulation& s) { return s.sim().time(); }, "s")
        .def_property_readonly(
            "backend", [](const PySimulation& s) { return std::string(s.sim().backend_name()); })
        .def_property_readonly("threads",
                               [](const PySimulation& s) { return s.sim().options().threads; })
        .def_property_readonly(
            "positions",
            [](const PySimulation& s) { return view(s, s.sim().bodies().position, 3); },
            "(N, 3) centres of mass, mm; x, y in [0, L)")
        .def_property_readonly(
            "quaternions",
            [](const PySimulation& s) { return view(s, s.sim().bodies().orientation, 4); },
            "(N, 4) unit quaternions (w, x, y, z), body frame → lab")
        .def_property_readonly(
            "velocities",
            [](const PySimulation& s) { return view(s, s.sim().bodies().velocity, 3); },
            "(N, 3) mm/s")
        .def_property_readonly(
            "spins", [](const PySimulation& s) { return view(s, s.sim().bodies().spin, 3); },
            "(N, 3) angular velocities, lab frame, rad/s")
        .def_property_readonly(
            "species",
            [](const PySimulation& s) {
                const auto& sp = s.sim().bodies().species;
                py::array a(py::dtype::of<std::uint32_t>(), {sp.size()}, {sizeof(std::uint32_t)},
                            sp.data(), keep_alive(s.shared()));
                a.attr("setflags")(py::arg("write") = false);
                return a;
            },
            "(N,) species index of each body")
        .def(
            "set_state",
            [](PySimulation& s, std::optional<Array> positions, std::optional<Array> quaternions,
               std::optional<Array> velocities, std::optional<Array> spins) {
                BodyState b = s.sim().bodies();
                const std::size_t n = b.size();
                if (positions) b.position = vectors(*positions, n, "positions");
                if (velocities) b.velocity = vectors(*velocities, n, "velocities");
                if (spins) b.spin = vectors(*spins, n, "spins");
                if (quaternions) {
                    const Array& q = *quaternions;
                    if (q.ndim() != 2 || q.shape(0) != static_cast<py::ssize_t>(n) ||
                        q.shape(1) != 4)
                        throw InvalidParameter("quaternions", "another shape",
                                               "shape (" + std::to_string(n) + ", 4)");
                    for (std::size_t i = 0; i < n; ++i)
                        b.orientation[i] = {q.at(i, 0), q.at(i, 1), q.at(i, 2), q.at(i, 3)};
                }
                s.set_state(b);
            },
            py::arg("positions") = py::none(), py::arg("quaternions") = py::none(),
            py::arg("velocities") = py::none(), py::arg("spins") = py::none(),
            "Replaces parts of the state; checked as a resumed state is (rodsea.InvalidParameter "
            "names the body and the value).")
        .def(
            "timings",
            [](const PySimulation& s) {
                const StageProfile& p = s.sim().profile();
                py::dict d;
                d["free_flight"] = p.free_flight;
                d["sphere_update"] = p.sphere_update;
                d["contact_search"] = p.contact_search;
                d["resolution"] = p.resolution;
                d["noise"] = p.noise;
                d["whole_steps"] = p.whole_steps;
                d["total"] = p.total();
                return d;
            },
            "wall seconds spent in each stage of the step since construction (on the GPU, "
            "'whole_steps': runs of steps queued together, whose stages overlap)")
        .def(
            "state_hash", [](const PySimulation& s) { return s.sim().state_hash(); },
            "FNV-1a over every bit of the state: `rodsea run` prints the same")
        .def(
            "kinetic_energy", [](const PySimulation& s) { return s.sim().kinetic_energy(); },
            "mass unit mm² s⁻²")
        .def(
            "save_checkpoint",
            [](const PySimulation& s, const std::string& path) {
                Checkpoint c;
                c.config_toml = s.plan().config_toml;
                c.step = s.sim().step_count();
                c.bodies = s.sim().bodies();
                write_checkpoint(path, c);
            },
            py::arg("path"), "the state, atomically, as an HDF5 checkpoint")
        .def_static(
            "from_checkpoint",
            [](const std::string& path, std::optional<int> threads) {
                Checkpoint c = read_checkpoint(path);
                RunPlan plan = load_config_string(c.config_toml, path + " [config]");
                // What `rodsea run --continue` checks of a checkpoint's state.
                check_checkpoint_bodies(c, plan, path);
                check_checkpoint_state(c, plan, path);
                const int t = threads.value_or(plan.control.threads);
                return PySimulation(std::move(plan), std::move(c.bodies), c.step, t);
            },
            py::arg("path"), py::arg("threads") = py::none(),
            "Continues from a checkpoint: one saved by save_checkpoint, or a run directory's "
            "checkpoint.h5; bit for bit the run that wrote it.");
}

}  // namespace rodsea::python
