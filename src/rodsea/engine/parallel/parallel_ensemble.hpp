#pragma once
// The data-parallel step (kernels.hpp, contact_kernels.hpp, island_kernels.hpp) of many
// independent systems at once, run by an executor: the GPU backend with the CUDA executor, its
// host twin with HostExecutor. A phase diagram's dozens of small systems fill one device
// together; a lone run is an ensemble of one (parallel_backend.hpp). The state lives in the
// executor's memory; the host sees each system through bodies(), spheres() and contacts(), which
// copy it over when it changed.
//
// Steps come in runs: the host plans a run's contexts (the plates' motion, the step numbers),
// hands them over with the run, and reads back once at its end what each system's steps came to
// (system_run.hpp); in between a device takes step after step without waiting for the host. A
// step, in six launches (a launch's tail is the work of a few elements that needs all of its
// results, done by the launch's last block: HostExecutor::launch_then):
//   1 free flight per body (and the cell counts cleared); its tail decides whether to rebuild
//     the neighbour list;
//   2 sphere centres per sphere, each binned into its cell's slots when rebuilding;
//   3 contacts per sphere: its Verlet list rebuilt when due, its contacts with the partners it
//     touches and the plates written at places from a cursor, islands joined (union–find); the
//     tail counts them;
//   4 islands: each contact onto its island's list; each island copied out, put in the CPU's
//     order and swept by one thread;
//   5 per body: out of the plates, and polar bodies' noise kicks; the tail, per system: the
//     step's counts become its statistics, and a system past its blow-up bounds stops there for
//     the rest of the run.
// Where a device can, the launches of kGraphSteps steps are recorded once as a CUDA graph and
// replayed. Lists that outgrow their room (a sphere's partners, a cell's spheres, a step's
// contacts) say how much they needed: the state is put back as it was at the run's start and
// the run taken again with more room, so the room never shows in a trajectory.
//
// The contact list is the CPU's, contact for contact (in the order of its keys), and each island
// gets the CPU's impulses in the CPU's order: run by the host executor the step is the CPU
// backend's to the last bit. On a device only the rounding of the device's arithmetic can differ
// (nvcc may fuse a multiply and an add where the host rounds twice; the build asks it not to,
// -fmad=false). Nothing a system computes depends on the systems beside it, so each steps to the
// same bits as it does alone.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parallel/contact_kernels.hpp"
#include "rodsea/engine/parallel/island_kernels.hpp"
#include "rodsea/engine/parallel/kernels.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/stage_timer.hpp"
#include "rodsea/engine/step_backend.hpp"
#include "rodsea/neighbors/verlet_skin.hpp"

namespace rodsea::parallel {

// The spheres as the step starts from them (cpu::SphereTable's arrays).
struct InitialSpheres {
    std::vector<std::uint32_t> body;
    std::vector<double> radius;
    std::vector<Vec3> position;
    std::vector<std::uint32_t> first_of;
};

// One system of an ensemble: its species (which must outlive the ensemble), state and spheres.
struct EnsembleMember {
    const SpeciesTable* species = nullptr;
    BodyState bodies;
    InitialSpheres spheres;
};

// What Ensemble (ensemble.hpp) and the one-system backend need of an executor's ensemble.
class EnsembleStepper {
  public:
    virtual ~EnsembleStepper() = default;
    virtual std::size_t size() const = 0;
    // Steps every system `steps` times: system m's k-th step has contexts[k * size() + m]. A
    // system whose step crosses (*bounds)[m] stops after it (none: never) while the others go
    // on. done[m] says what system m's steps came to; each stage's time joins `profile`.
    virtual void run(const std::vector<StepContext>& contexts, std::uint64_t steps,
                     const std::vector<BlowUpBounds>* bounds, std::vector<StepsDone>& done,
                     StageProfile& profile) = 0;
    virtual const BodyState& bodies(std::size_t m) const = 0;
    virtual SphereView spheres(std::size_t m) const = 0;
    // The last step's contacts of system m, with its own body indices.
    virtual const std::vector<Contact>& contacts(std::size_t m) const = 0;
    virtual void set_threads(int threads) = 0;
    // Wait for each stage to time it (BackendOptions::time_stages).
    virtual void set_stage_timing(bool on) = 0;
    // How often the neighbour list was built.
    virtual std::uint64_t builds() const = 0;
};

// The room the lists start with; they grow to what a run needs (a sphere's partners: a handful
// in a monolayer; a step's contacts: a few per cent of the spheres).
struct Room {
    std::uint32_t slots = 16;      // partners per sphere
    std::uint32_t cell_room = 16;  // spheres per cell (cells are two radii and the skin wide)
    std::uint64_t contacts = 0;    // per step; 0: an eighth of the spheres, and 256
};

// `gross_overlap_fraction`: the depth over the smaller radius beyond which a contact counts as
// unresolvable (state_check.hpp's kGrossOverlapFraction, passed in: this header is compiled for
// a device too).
template <class Executor>
class ParallelEnsemble final : public EnsembleStepper {
  public:
    // Steps recorded in one graph; a run replays it as often as it fits, then steps singly.
    static constexpr std::uint64_t kGraphSteps = 16;

    ParallelEnsemble(std::vector<EnsembleMember> members, double gross_overlap_fraction,
                     Executor executor, Room room = {})
        : gross_overlap_fraction_(gross_overlap_fraction),
          exec_(std::move(executor)),
          members_(std::move(members)) {
        if (members_.empty()) throw std::invalid_argument("rodsea: an ensemble of no systems");
        for (const EnsembleMember& m : members_)
            if (m.bodies.size() == 0 || m.spheres.body.empty() || m.species->size() == 0)
                throw std::invalid_argument("rodsea: a system of an ensemble without bodies");
        concatenate();
        const std::size_t n = body_count(), spheres = sphere_count(), systems = members_.size();
        for (auto* a : {&parent_, &island_count_, &island_head_})
            a->resize(n);
        last_changed_.resize(n);
        plate_hit_.resize(n);
        inv_mass_.resize(n);
        inv_inertia_.resize(n);
        for (auto* a : {&snapshot_position_, &snapshot_velocity_, &snapshot_spin_})
            a->resize(n);
        snapshot_orientation_.resize(n);
        neighbour_count_.resize(spheres);
        exec_.fill(neighbour_count_, spheres, 0u);
        current_.resize(systems);
        runs_.resize(systems);
        step_counts_.resize(systems);
        exec_.fill(step_counts_, systems, StepCounts{});
        halt_.resize(systems);
        travel_.resize(systems);
        snapshot_travel_.resize(systems);
        exec_.fill(travel_, systems, 0.0);
        status_.resize(1);
        RunStatus first;
        first.force_rebuild = 1;
        exec_.upload(status_, std::vector<RunStatus>{first});
        planned_.resize(kPlannedSteps * systems);
        grow_neighbours(room.slots);
        cell_room_ = room.cell_room;
        grow_contacts(room.contacts > 0 ? room.contacts : spheres / 8 + 256);
        host_grids_.resize(systems);
        bodies_stale_.assign(systems, 0);
        spheres_stale_.assign(systems, 0);
        host_contacts_.resize(systems);
        const char* graphs = std::getenv("RODSEA_GPU_GRAPHS");
        graphs_wanted_ = graphs == nullptr || std::string(graphs) != "0";
    }

    std::size_t size() const override { return members_.size(); }
    void set_threads(int threads) override { exec_.set_threads(threads); }
    void set_stage_timing(bool on) override { time_stages_ = on; }
    std::uint64_t builds() const override { return host_status_.builds; }

    const BodyState& bodies(std::size_t m) const override {
        BodyState& b = members_[m].bodies;
        if (bodies_stale_[m]) {
            const std::size_t first = first_body_[m], n = b.size();
            exec_.download(position_, first, n, b.position);
            exec_.download(orientation_, first, n, b.orientation);
            exec_.download(velocity_, first, n, b.velocity);
            exec_.download(spin_, first, n, b.spin);
            bodies_stale_[m] = 0;
        }
        return b;
    }
    SphereView spheres(std::size_t m) const override {
        InitialSpheres& s = members_[m].spheres;
        if (spheres_stale_[m]) {
            exec_.download(sphere_position_, first_sphere_[m], s.body.size(), s.position);
            spheres_stale_[m] = 0;
        }
        return {s.body, s.radius, s.position, s.first_of};
    }
    const std::vector<Contact>& contacts(std::size_t m) const override {
        if (contacts_stale_) {
            // Every system's contacts at once (they come mixed), each system's in key order.
            for (std::vector<Contact>& c : host_contacts_)
                c.clear();
            std::vector<Contact> all;
            std::vector<std::uint64_t> keys;
            exec_.download(contacts_, host_status_.contacts, all);
            exec_.download(contact_key_, host_status_.contacts, keys);
            std::vector<std::uint32_t> order(all.size());
            std::iota(order.begin(), order.end(), 0u);
            std::sort(order.begin(), order.end(),
                      [&keys](std::uint32_t x, std::uint32_t y) { return keys[x] < keys[y]; });
            for (const std::uint32_t k : order) {
                Contact c = all[k];
                const auto system = static_cast<std::size_t>(
                    std::upper_bound(first_body_.begin(), first_body_.end(), c.a) -
                    first_body_.begin() - 1);
                const std::uint32_t own = first_body_[system];
                c.a -= own;
                if (!c.with_plate()) c.b -= own;
                host_contacts_[system].push_back(c);
            }
            contacts_stale_ = false;
        }
        return host_contacts_[m];
    }

    void run(const std::vector<StepContext>& contexts, std::uint64_t steps,
             const std::vector<BlowUpBounds>* bounds, std::vector<StepsDone>& done,
             StageProfile& profile) override {
        const std::size_t systems = members_.size();
        if (contexts.size() != steps * systems)
            throw std::invalid_argument("rodsea: one step context per step and system");
        done.assign(systems, StepsDone{});
        if (steps == 0) return;
        if (steps > 0xffffffffULL) throw std::invalid_argument("rodsea: a run of 2^32 steps");
        set_halt_bounds(bounds);
        size_grids(contexts);
        if (planned_.size() < contexts.size()) {
            planned_.resize(contexts.size());
            ++layout_;
        }
        exec_.upload_into(planned_, contexts);
        std::vector<SystemRun> runs;
        {
            StageTimer whole(time_stages_ ? unused_ : profile.whole_steps);
            bool force = false;
            for (;;) {
                exec_.copy(snapshot_position_, position_, body_count());
                exec_.copy(snapshot_orientation_, orientation_, body_count());
                exec_.copy(snapshot_velocity_, velocity_, body_count());
                exec_.copy(snapshot_spin_, spin_, body_count());
                exec_.copy(snapshot_travel_, travel_, systems);
                exec_.launch(systems, BeginRun{current_.data(), planned_.data(), runs_.data(),
                                               step_counts_.data(), status_.data(),
                                               static_cast<std::uint32_t>(steps), force});
                take_steps(steps, profile);
                exec_.download(runs_, systems, runs);
                host_status_ = exec_.read(status_, 0);
                if (host_status_.needed_slots <= slot_capacity_ &&
                    host_status_.needed_contacts <= contact_capacity_ &&
                    host_status_.needed_cell_room <= cell_room_)
                    break;
                // Something did not fit: the run again from its start, with room for it.
                if (host_status_.needed_slots > slot_capacity_)
                    grow_neighbours(host_status_.needed_slots + host_status_.needed_slots / 4 + 2);
                if (host_status_.needed_contacts > contact_capacity_)
                    grow_contacts(host_status_.needed_contacts + host_status_.needed_contacts / 4 +
                                  256);
                if (host_status_.needed_cell_room > cell_room_)
                    grow_cells(static_cast<std::uint32_t>(host_status_.needed_cell_room +
                                                          host_status_.needed_cell_room / 4 + 2));
                exec_.copy(position_, snapshot_position_, body_count());
                exec_.copy(orientation_, snapshot_orientation_, body_count());
                exec_.copy(velocity_, snapshot_velocity_, body_count());
                exec_.copy(spin_, snapshot_spin_, body_count());
                exec_.copy(travel_, snapshot_travel_, systems);
                force = true;
            }
        }
        ++runs_taken_;
        for (std::size_t m = 0; m < systems; ++m) {
            done[m].steps = runs[m].steps;
            done[m].blew_up = runs[m].halted != 0;
            done[m].last = runs[m].last;
            done[m].tally = runs[m].tally;
        }
        std::fill(bodies_stale_.begin(), bodies_stale_.end(), 1);
        std::fill(spheres_stale_.begin(), spheres_stale_.end(), 1);
        contacts_stale_ = true;
    }

  private:
    template <class T>
    using Array = typename Executor::template Array<T>;

    // Simulation::kStepsPerRun (the engine's runs): the contexts of that many steps have their
    // place from the start, so that a graph recorded once keeps its pointers.
    static constexpr std::size_t kPlannedSteps = 1024;

    std::size_t body_count() const { return first_body_.back(); }
    std::size_t sphere_count() const { return first_sphere_.back(); }

    void grow_neighbours(std::uint64_t capacity) {
        slot_capacity_ = static_cast<std::uint32_t>(capacity);
        neighbour_slots_.resize(std::size_t{slot_capacity_} * sphere_count());
        ++layout_;
    }
    void grow_contacts(std::uint64_t capacity) {
        contact_capacity_ =
            static_cast<std::uint32_t>(std::min<std::uint64_t>(capacity, 0x7fffffffULL));
        for (auto* a : {&next_in_island_, &island_order_})
            a->resize(contact_capacity_);
        contacts_.resize(contact_capacity_);
        contact_key_.resize(contact_capacity_);
        ++layout_;
    }
    void grow_cells(std::uint32_t room) {
        cell_room_ = room;
        cell_sphere_.resize(std::size_t{cell_room_} * cells_);
        ++layout_;
    }

    void set_halt_bounds(const std::vector<BlowUpBounds>* bounds) {
        std::vector<HaltBounds> halt(members_.size());
        if (bounds != nullptr) {
            if (bounds->size() != members_.size())
                throw std::invalid_argument("rodsea: one set of blow-up bounds per system");
            for (std::size_t m = 0; m < halt.size(); ++m)
                halt[m] = {(*bounds)[m], 1u};
        }
        const auto same = [](const HaltBounds& a, const HaltBounds& b) {
            return a.active == b.active && a.bounds.planar_speed == b.bounds.planar_speed &&
                   a.bounds.overlap_fraction == b.bounds.overlap_fraction &&
                   a.bounds.unresolved == b.bounds.unresolved;
        };
        if (host_halt_.size() == halt.size() &&
            std::equal(halt.begin(), halt.end(), host_halt_.begin(), same))
            return;
        exec_.upload_into(halt_, halt);
        host_halt_ = halt;
    }

    // Steps the run's `steps` steps: replays of the recorded graph, then single steps.
    void take_steps(std::uint64_t steps, StageProfile& profile) {
        std::uint64_t taken = 0;
        if (!time_stages_ && graphs_wanted_ && runs_taken_ > 0 && steps >= kGraphSteps) {
            if (graph_layout_ != layout_) record_graph(profile);
            if (graph_layout_ == layout_)
                for (; taken + kGraphSteps <= steps; taken += kGraphSteps)
                    exec_.replay(graph_);
        }
        for (; taken < steps; ++taken)
            step_once(profile);
    }

    void record_graph(StageProfile& profile) {
        if (!exec_.begin_capture()) {
            graphs_wanted_ = false;
            return;
        }
        for (std::uint64_t k = 0; k < kGraphSteps; ++k)
            step_once(profile);
        if (exec_.end_capture(graph_))
            graph_layout_ = layout_;
        else
            graphs_wanted_ = false;  // the device cannot: every step is launched singly
    }

    // One step's launches. With time_stages_ each stage is waited for and timed.
    void step_once(StageProfile& profile) {
        const auto n = static_cast<std::uint32_t>(body_count());
        const auto s = static_cast<std::uint32_t>(sphere_count());
        const auto systems = static_cast<std::uint32_t>(members_.size());
        const BodyArrays bodies = body_arrays();
        const SpeciesArrays species = species_arrays();
        const Systems sys = system_arrays();
        const CellList cells = cell_list();
        const NeighbourList neighbours{neighbour_slots_.data(), neighbour_count_.data(),
                                       slot_capacity_, s, kVerletSkin};
        RunStatus* status = status_.data();
        const auto stage = [this](double& sink, auto&& launches) {
            if (!time_stages_) {
                launches();
                return;
            }
            StageTimer t(sink);
            launches();
            exec_.finish();
        };
        stage(profile.free_flight, [&] {
            exec_.launch_then(n,
                              FlyBodies{bodies,
                                        species,
                                        sys,
                                        {parent_.data(), island_count_.data(), island_head_.data(),
                                         last_changed_.data(), inv_mass_.data(),
                                         inv_inertia_.data(), plate_hit_.data()},
                                        cells},
                              1, DecideRebuild{sys, travel_.data(), status, 0.5 * kVerletSkin});
        });
        stage(profile.sphere_update, [&] {
            exec_.launch(s, PlaceSpheres{bodies, species, sphere_arrays(), sys, cells, status});
        });
        stage(profile.contact_search, [&] {
            exec_.launch_then(s,
                              FindContacts{sphere_arrays(), bodies, species, sys, cells, neighbours,
                                           contacts_.data(), contact_key_.data(), contact_capacity_,
                                           parent_.data(), gross_overlap_fraction_, status},
                              1, CloseContactList{status, contact_capacity_});
        });
        stage(profile.resolution, [&] {
            exec_.launch_counted(contact_capacity_, &status->contacts,
                                 ListIslands{contacts_.data(), parent_.data(), island_count_.data(),
                                             island_head_.data(), next_in_island_.data()});
            exec_.launch(
                n, SweepIslands{contacts_.data(), contact_key_.data(), island_count_.data(),
                                island_head_.data(), next_in_island_.data(), island_order_.data(),
                                IslandBodies{bodies, inv_mass_.data(), inv_inertia_.data()}, sys,
                                last_changed_.data(), plate_hit_.data(), status});
            // The noise and the step's end (the tail) are part of this launch.
            exec_.launch_then(
                n, ProjectAndKick{bodies, species, sphere_arrays(), sys, plate_hit_.data()},
                systems,
                EndStep{runs_.data(), step_counts_.data(), halt_.data(), current_.data(),
                        planned_.data(), status, systems});
        });
    }

    // One state of all systems: bodies, spheres and species one after another, each system's
    // species indices, body indices and sphere ranges shifted by what comes before it.
    void concatenate() {
        BodyState all;
        InitialSpheres spheres;
        SpeciesTable species;
        std::vector<std::uint32_t> system_of_body, first_body_of_system;
        first_body_.assign(1, 0);
        first_sphere_.assign(1, 0);
        std::vector<std::uint32_t> pair_row, local_index;
        std::size_t species_first = 0;
        for (std::size_t s = 0; s < members_.size(); ++s) {
            const EnsembleMember& m = members_[s];
            const SpeciesTable& t = *m.species;
            const auto body_shift = static_cast<std::uint32_t>(all.size());
            const auto sphere_shift = static_cast<std::uint32_t>(spheres.body.size());
            const auto offset_shift = static_cast<std::uint32_t>(species.sphere_offset.size());
            const auto outline_shift = static_cast<std::uint32_t>(species.outline_along.size());
            first_body_of_system.push_back(body_shift);
            for (std::size_t b = 0; b < m.bodies.size(); ++b) {
                all.add(static_cast<std::uint32_t>(m.bodies.species[b] + species_first),
                        m.bodies.position[b], m.bodies.orientation[b], m.bodies.velocity[b],
                        m.bodies.spin[b]);
                system_of_body.push_back(static_cast<std::uint32_t>(s));
            }
            for (std::size_t i = 0; i < m.spheres.body.size(); ++i) {
                spheres.body.push_back(m.spheres.body[i] + body_shift);
                spheres.radius.push_back(m.spheres.radius[i]);
                spheres.position.push_back(m.spheres.position[i]);
            }
            for (std::size_t b = 0; b + 1 < m.spheres.first_of.size(); ++b)
                spheres.first_of.push_back(m.spheres.first_of[b] + sphere_shift);
            const auto append = [](auto& to, const auto& from) {
                to.insert(to.end(), from.begin(), from.end());
            };
            append(species.inverse_mass, t.inverse_mass);
            append(species.inverse_inertia, t.inverse_inertia);
            append(species.rotor, t.rotor);
            append(species.reach2, t.reach2);
            append(species.sphere_axis, t.sphere_axis);
            append(species.sphere_offset, t.sphere_offset);
            append(species.sphere_radius, t.sphere_radius);
            append(species.plate, t.plate);
            append(species.polar, t.polar);
            append(species.outline_along, t.outline_along);
            append(species.outline_radius, t.outline_radius);
            for (std::size_t k = 0; k < t.size(); ++k) {
                species.first_sphere.push_back(t.first_sphere[k] + offset_shift);
                species.first_outline.push_back(t.first_outline[k] + outline_shift);
            }
            for (std::size_t a = 0; a < t.size(); ++a) {  // this system's block of pairs
                pair_row.push_back(static_cast<std::uint32_t>(species.pair.size() + a * t.size()));
                local_index.push_back(static_cast<std::uint32_t>(a));
            }
            append(species.pair, t.pair);
            species_first += t.size();
            first_body_.push_back(static_cast<std::uint32_t>(all.size()));
            first_sphere_.push_back(static_cast<std::uint32_t>(spheres.body.size()));
            widest_reach_.push_back(
                2.0 * *std::max_element(t.sphere_radius.begin(), t.sphere_radius.end()) +
                kVerletSkin);
        }
        species.first_sphere.push_back(static_cast<std::uint32_t>(species.sphere_offset.size()));
        species.first_outline.push_back(static_cast<std::uint32_t>(species.outline_along.size()));
        spheres.first_of.push_back(static_cast<std::uint32_t>(spheres.body.size()));
        species_count_ = static_cast<std::uint32_t>(species_first);

        exec_.upload(inverse_mass_, species.inverse_mass);
        exec_.upload(inverse_inertia_, species.inverse_inertia);
        exec_.upload(rotor_, species.rotor);
        exec_.upload(reach2_, species.reach2);
        exec_.upload(sphere_axis_, species.sphere_axis);
        exec_.upload(species_first_sphere_, species.first_sphere);
        exec_.upload(sphere_offset_, species.sphere_offset);
        exec_.upload(plate_coefficients_, species.plate);
        exec_.upload(pair_coefficients_, species.pair);
        exec_.upload(pair_row_, pair_row);
        exec_.upload(local_index_, local_index);
        exec_.upload(polar_, species.polar);
        exec_.upload(body_species_, all.species);
        exec_.upload(position_, all.position);
        exec_.upload(orientation_, all.orientation);
        exec_.upload(velocity_, all.velocity);
        exec_.upload(spin_, all.spin);
        exec_.upload(sphere_body_, spheres.body);
        exec_.upload(sphere_radius_, spheres.radius);
        exec_.upload(sphere_position_, spheres.position);
        exec_.upload(first_of_, spheres.first_of);
        exec_.upload(system_of_body_, system_of_body);
        exec_.upload(first_body_of_system_, first_body_of_system);
    }

    BodyArrays body_arrays() {
        return {body_species_.data(), position_.data(), orientation_.data(),
                velocity_.data(),     spin_.data(),     static_cast<std::uint32_t>(body_count())};
    }
    SpeciesArrays species_arrays() const {
        return {inverse_mass_.data(),  inverse_inertia_.data(),    rotor_.data(),
                reach2_.data(),        sphere_axis_.data(),        species_first_sphere_.data(),
                sphere_offset_.data(), plate_coefficients_.data(), pair_coefficients_.data(),
                pair_row_.data(),      local_index_.data(),        polar_.data(),
                species_count_};
    }
    SphereArrays sphere_arrays() {
        return {sphere_body_.data(), sphere_radius_.data(), sphere_position_.data(),
                first_of_.data(), static_cast<std::uint32_t>(sphere_count())};
    }
    Systems system_arrays() {
        return {current_.data(),
                system_of_body_.data(),
                first_body_of_system_.data(),
                grids_.data(),
                runs_.data(),
                step_counts_.data(),
                static_cast<std::uint32_t>(size())};
    }
    CellList cell_list() { return {cell_count_.data(), cell_sphere_.data(), cell_room_, cells_}; }

    // Each system's cells no narrower than the neighbour list's widest reach and no more than a
    // few per sphere (a huge box of few spheres would otherwise sweep an empty grid at each
    // rebuild); the systems' grids one after another. From the run's first contexts (a
    // system's box does not change).
    void size_grids(const std::vector<StepContext>& contexts) {
        bool changed = false;
        std::uint32_t first_cell = 0;
        for (std::size_t m = 0; m < members_.size(); ++m) {
            const PeriodicBox2D& box = contexts[m].box;
            const double reach = widest_reach_[m];
            const auto across = [reach](double side) {
                return std::max<std::uint32_t>(
                    1, static_cast<std::uint32_t>(std::floor(side / reach)));
            };
            CellGrid g{across(box.lx), across(box.ly), 0.0, 0.0};
            const std::size_t cap = 4 * (first_sphere_[m + 1] - first_sphere_[m]) + 64;
            while (std::size_t{g.nx} * g.ny > cap) {
                g.nx = std::max<std::uint32_t>(1, g.nx / 2);
                g.ny = std::max<std::uint32_t>(1, g.ny / 2);
            }
            g.width_x = box.lx / g.nx;
            g.width_y = box.ly / g.ny;
            const SystemGrid sg{g, first_cell};
            const SystemGrid& old = host_grids_[m];
            if (old.first_cell != sg.first_cell || old.grid.nx != g.nx || old.grid.ny != g.ny ||
                old.grid.width_x != g.width_x || old.grid.width_y != g.width_y) {
                host_grids_[m] = sg;
                changed = true;
            }
            first_cell += g.cells();
        }
        if (!changed) return;
        cells_ = first_cell;
        exec_.upload(grids_, host_grids_);
        cell_count_.resize(cells_);
        exec_.fill(cell_count_, cells_, 0u);
        grow_cells(cell_room_);
        exec_.upload_into(status_, std::vector<RunStatus>{with_forced_rebuild()});
        ++layout_;
    }
    RunStatus with_forced_rebuild() const {
        RunStatus s = host_status_;
        s.force_rebuild = 1;
        return s;
    }

    double gross_overlap_fraction_;
    mutable Executor exec_;
    mutable std::vector<EnsembleMember> members_;           // the host's copies of each system
    std::vector<std::uint32_t> first_body_, first_sphere_;  // per system, plus the total
    std::vector<double> widest_reach_;                      // per system, mm

    // The species of every system (SpeciesTable's arrays, concatenated).
    Array<double> inverse_mass_, reach2_;
    Array<Vec3> inverse_inertia_, sphere_offset_;
    Array<physics::Rotor> rotor_;
    Array<int> sphere_axis_;
    Array<std::uint32_t> species_first_sphere_;
    Array<ContactCoefficients> plate_coefficients_, pair_coefficients_;
    Array<std::uint32_t> pair_row_, local_index_;
    Array<std::uint8_t> polar_;
    std::uint32_t species_count_ = 0;

    // The state.
    Array<std::uint32_t> body_species_;
    Array<Vec3> position_, velocity_, spin_;
    Array<Quat> orientation_;
    Array<std::uint32_t> sphere_body_, first_of_;
    Array<double> sphere_radius_;
    Array<Vec3> sphere_position_;

    // The systems and the run.
    Array<StepContext> planned_, current_;
    Array<std::uint32_t> system_of_body_, first_body_of_system_;
    Array<SystemGrid> grids_;
    std::vector<SystemGrid> host_grids_;
    Array<SystemRun> runs_;
    Array<StepCounts> step_counts_;
    Array<HaltBounds> halt_;
    std::vector<HaltBounds> host_halt_;
    Array<double> travel_;
    Array<RunStatus> status_;
    RunStatus host_status_;

    // What a run that needs more room starts again from.
    Array<Vec3> snapshot_position_, snapshot_velocity_, snapshot_spin_;
    Array<Quat> snapshot_orientation_;
    Array<double> snapshot_travel_;

    // The cell list and the neighbour list.
    std::uint32_t cells_ = 0;
    Array<std::uint32_t> cell_count_, cell_sphere_;
    std::uint32_t cell_room_ = 0;
    Array<std::uint32_t> neighbour_slots_, neighbour_count_;
    std::uint32_t slot_capacity_ = 0;

    // The contacts and the islands.
    Array<Contact> contacts_;
    Array<std::uint64_t> contact_key_;
    std::uint32_t contact_capacity_ = 0;
    Array<std::uint32_t> next_in_island_, island_order_;
    Array<std::uint32_t> parent_, island_count_, island_head_;
    Array<int> last_changed_;
    Array<double> inv_mass_;
    Array<Mat3> inv_inertia_;
    Array<PlateHits> plate_hit_;

    // Timing and graphs.
    bool time_stages_ = false;
    double unused_ = 0.0;
    bool graphs_wanted_ = true;
    std::uint64_t runs_taken_ = 0;
    std::uint64_t layout_ = 0;  // counts changes of any array a recorded graph points into
    std::uint64_t graph_layout_ = ~std::uint64_t{0};
    typename Executor::Graph graph_;

    // The host's copies are refreshed when read after a run.
    mutable std::vector<std::vector<Contact>> host_contacts_;
    mutable std::vector<char> bodies_stale_, spheres_stale_;
    mutable bool contacts_stale_ = false;
};

}  // namespace rodsea::parallel
