#pragma once
// The data-parallel step (kernels.hpp) of many independent systems at once, run by an executor:
// the GPU backend with the CUDA executor, its host twin with HostExecutor. A phase diagram's
// dozens of small systems fill one device together; a lone run is an ensemble of one
// (parallel_backend.hpp). The state lives in the executor's memory; the host sees each system
// through bodies(), spheres() and contacts(), which copy it over when it changed.
//
// A step, with the executor's launches, scans, sorts and reductions:
//   1 free flight per body;  2 sphere centres per body;
//   3 contact search: spheres sorted by cell (each system's grid a block of one cell list,
//     rebuilt every step), contacts counted per sphere, placed by an exclusive scan and written:
//     the list is a function of the state;
//   4 resolution: contacts joined into islands (bodies linked by body–body contacts; union–find
//     with atomic hooks, whose result does not depend on their order), sorted by island, and
//     each island swept by one thread with the CPU's own sweep (physics/island_sweep.hpp) in
//     list order; the projection out of the plates per body;
//   5 noise per polar body, from its plate contacts' fastest approach.
// The contact list is the CPU's, contact for contact, and each island gets the CPU's impulses in
// the CPU's order: run by the host executor the step is the CPU backend's to the last bit. On a
// device only the rounding of the device's arithmetic can differ (nvcc may fuse a multiply and
// an add where the host rounds twice; the build asks it not to, -fmad=false). Nothing a system
// computes depends on the systems beside it, so each steps to the same bits as it does alone.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parallel/kernels.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/stage_timer.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea::parallel {

// How many bits a radix sort reads for keys below `distinct`.
inline int key_bits(std::uint64_t distinct) {
    int bits = 1;
    while (bits < 32 && (std::uint64_t{1} << bits) < distinct)
        ++bits;
    return bits;
}

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
    // Steps system m with contexts[m]; overwrites stats[m]; adds each stage's time to `profile`.
    virtual void step(const std::vector<StepContext>& contexts, std::vector<StepStatistics>& stats,
                      StageProfile& profile) = 0;
    virtual const BodyState& bodies(std::size_t m) const = 0;
    virtual SphereView spheres(std::size_t m) const = 0;
    // The last step's contacts of system m, with its own body indices.
    virtual const std::vector<Contact>& contacts(std::size_t m) const = 0;
    virtual void set_threads(int threads) = 0;
    virtual std::uint64_t steps() const = 0;
};

// `gross_overlap_fraction`: the depth over the smaller radius beyond which a contact counts as
// unresolvable (state_check.hpp's kGrossOverlapFraction, passed in: this header is compiled for
// a device too).
template <class Executor>
class ParallelEnsemble final : public EnsembleStepper {
  public:
    ParallelEnsemble(std::vector<EnsembleMember> members, double gross_overlap_fraction,
                     Executor executor)
        : gross_overlap_fraction_(gross_overlap_fraction),
          exec_(std::move(executor)),
          members_(std::move(members)) {
        if (members_.empty()) throw std::invalid_argument("rodsea: an ensemble of no systems");
        for (const EnsembleMember& m : members_)
            if (m.bodies.size() == 0 || m.spheres.body.empty() || m.species->size() == 0)
                throw std::invalid_argument("rodsea: a system of an ensemble without bodies");
        concatenate();
        const std::size_t n = host_body_count(), spheres = host_sphere_count();
        drift2_.resize(n);
        turn2_.resize(n);
        inv_mass_.resize(n);
        inv_inertia_.resize(n);
        last_changed_.resize(n);
        kicks_.resize(n);
        for (auto* a : {&parent_, &island_start_, &island_end_})
            a->resize(n);
        for (auto* a : {&cell_key_, &cell_sphere_, &body_count_, &plate_count_, &body_offset_,
                        &plate_offset_})
            a->resize(spheres);
        boundary_values_.resize(members_.size());
        host_grids_.resize(members_.size());
        bodies_stale_.assign(members_.size(), 0);
        spheres_stale_.assign(members_.size(), 0);
        contacts_stale_.assign(members_.size(), 0);
        host_contacts_.resize(members_.size());
        ranges_.resize(members_.size());
    }

    std::size_t size() const override { return members_.size(); }
    void set_threads(int threads) override { exec_.set_threads(threads); }
    std::uint64_t steps() const override { return steps_; }

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
        std::vector<Contact>& out = host_contacts_[m];
        if (contacts_stale_[m]) {
            out.clear();
            if (contact_count_ > 0) {
                const ContactRange& r = ranges_[m];
                std::vector<Contact> part;
                exec_.download(contacts_, r.body_first, r.body_count, out);
                exec_.download(contacts_, r.plate_first, plate_count_of(m), part);
                out.insert(out.end(), part.begin(), part.end());
                const auto own = static_cast<std::uint32_t>(first_body_[m]);
                for (Contact& c : out) {
                    c.a -= own;
                    if (!c.with_plate()) c.b -= own;
                }
            }
            contacts_stale_[m] = 0;
        }
        return out;
    }

    void step(const std::vector<StepContext>& contexts, std::vector<StepStatistics>& stats,
              StageProfile& profile) override {
        const std::size_t systems = members_.size();
        if (contexts.size() != systems)
            throw std::invalid_argument("rodsea: one step context per system of the ensemble");
        stats.assign(systems, StepStatistics{});
        std::fill(bodies_stale_.begin(), bodies_stale_.end(), 1);
        std::fill(spheres_stale_.begin(), spheres_stale_.end(), 1);
        std::fill(contacts_stale_.begin(), contacts_stale_.end(), 1);
        ++steps_;
        exec_.upload(contexts_, contexts);
        size_grids(contexts);
        const BodyArrays bodies = body_arrays();
        const SpeciesArrays species = species_arrays();
        const auto n = static_cast<std::uint32_t>(host_body_count());
        {
            StageTimer t(profile.free_flight);
            exec_.launch(
                n, FlyBodies{bodies, species, system_arrays(), drift2_.data(), turn2_.data()});
            std::vector<double> drift2, turn2;
            exec_.segmented_max(drift2_, first_body_, drift2);
            exec_.segmented_max(turn2_, first_body_, turn2);
            for (std::size_t m = 0; m < systems; ++m)
                stats[m].max_planar_speed = std::sqrt(drift2[m]) + std::sqrt(turn2[m]);
            exec_.finish();
        }
        {
            StageTimer t(profile.sphere_update);
            exec_.launch(n, PlaceSpheres{bodies, species, sphere_arrays()});
            exec_.finish();
        }
        {
            StageTimer t(profile.contact_search);
            find_contacts(stats);
            exec_.finish();
        }
        {
            StageTimer t(profile.resolution);
            resolve(stats);
            exec_.launch(n, ProjectOutOfPlates{bodies, sphere_arrays(), system_arrays()});
            exec_.finish();
        }
        {
            StageTimer t(profile.noise);
            const bool noisy =
                std::any_of(contexts.begin(), contexts.end(),
                            [](const StepContext& c) { return c.noise_epsilon != 0.0; });
            if (noisy && contact_count_ > 0) {
                exec_.launch(
                    n, KickPolarBodies{bodies, species, sphere_arrays(), contacts_.data(),
                                       plate_offset_.data(), body_contact_count_, contact_count_,
                                       hit_speed_.data(), system_arrays(), kicks_.data()});
                std::vector<std::uint64_t> kicks;
                exec_.segmented_sum(kicks_, first_body_, kicks);
                for (std::size_t m = 0; m < systems; ++m)
                    stats[m].noise_kicks = kicks[m];
            }
            exec_.finish();
        }
    }

  private:
    template <class T>
    using Array = typename Executor::template Array<T>;

    std::size_t host_body_count() const { return first_body_.back(); }
    std::size_t host_sphere_count() const { return first_sphere_.back(); }
    std::uint32_t plate_count_of(std::size_t m) const {
        const std::uint32_t end =
            m + 1 < ranges_.size() ? ranges_[m + 1].plate_first : contact_count_;
        return end - ranges_[m].plate_first;
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
                2.0 * *std::max_element(t.sphere_radius.begin(), t.sphere_radius.end()));
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
        std::vector<std::uint32_t> boundary(first_sphere_.begin(), first_sphere_.end() - 1);
        exec_.upload(system_first_sphere_, boundary);
    }

    BodyArrays body_arrays() {
        return {body_species_.data(), position_.data(),
                orientation_.data(),  velocity_.data(),
                spin_.data(),         static_cast<std::uint32_t>(host_body_count())};
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
                first_of_.data(), static_cast<std::uint32_t>(host_sphere_count())};
    }
    Systems system_arrays() const {
        return {contexts_.data(), system_of_body_.data(), first_body_of_system_.data(),
                grids_.data(), static_cast<std::uint32_t>(size())};
    }

    // Each system's cells no narrower than its widest contact reach and no more than a few per
    // sphere (a huge box of few spheres would otherwise sweep an empty grid every step); the
    // systems' grids one after another.
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
        cell_start_.resize(cells_);
        cell_end_.resize(cells_);
        cell_key_bits_ = key_bits(cells_);
    }

    // The values of an exclusive scan where each system's spheres begin, plus its total.
    std::vector<std::uint32_t> at_system_starts(const Array<std::uint32_t>& scanned,
                                                std::uint64_t total) {
        exec_.launch(members_.size(), GatherAt{scanned.data(), system_first_sphere_.data(),
                                               boundary_values_.data()});
        std::vector<std::uint32_t> values;
        exec_.download(boundary_values_, members_.size(), values);
        values.push_back(static_cast<std::uint32_t>(total));
        return values;
    }

    void find_contacts(std::vector<StepStatistics>& stats) {
        const auto spheres = static_cast<std::uint32_t>(host_sphere_count());
        const std::size_t systems = members_.size();
        exec_.launch(spheres, KeySpheresByCell{sphere_arrays(), system_arrays(), cell_key_.data(),
                                               cell_sphere_.data()});
        exec_.sort_by_key(cell_key_, cell_sphere_, spheres, cell_key_bits_);
        exec_.fill(cell_start_, cells_, 0u);
        exec_.fill(cell_end_, cells_, 0u);
        exec_.launch(spheres,
                     MarkRuns{cell_key_.data(), spheres, cell_start_.data(), cell_end_.data()});
        const CellList cells{cell_sphere_.data(), cell_start_.data(), cell_end_.data()};
        exec_.launch(spheres, CountContacts{sphere_arrays(), body_arrays(), cells, system_arrays(),
                                            body_count_.data(), plate_count_.data()});
        const std::uint64_t body_contacts =
            exec_.exclusive_scan(body_count_, body_offset_, spheres);
        const std::uint64_t plate_contacts =
            exec_.exclusive_scan(plate_count_, plate_offset_, spheres);
        const std::uint64_t total = body_contacts + plate_contacts;
        if (total > 0x7fffffffULL)
            throw std::length_error("rodsea: more than 2^31 contacts in one step");
        contact_count_ = static_cast<std::uint32_t>(total);
        body_contact_count_ = static_cast<std::uint32_t>(body_contacts);
        // Where each system's contacts are: segment m of `segments_` its body contacts, segment
        // systems + m its plate contacts (contiguous: body contacts of every system come first).
        const std::vector<std::uint32_t> body_at = at_system_starts(body_offset_, body_contacts);
        const std::vector<std::uint32_t> plate_at = at_system_starts(plate_offset_, plate_contacts);
        segments_.assign(body_at.begin(), body_at.end());
        for (std::size_t m = 1; m <= systems; ++m)
            segments_.push_back(body_contact_count_ + plate_at[m]);
        for (std::size_t m = 0; m < systems; ++m)
            ranges_[m] = {body_at[m], body_at[m + 1] - body_at[m],
                          body_contact_count_ + plate_at[m]};
        if (contacts_.size() < contact_count_) {
            const std::size_t room = contact_count_ + contact_count_ / 4 + 64;
            contacts_.resize(room);
            depth_.resize(room);
            for (auto* a : {&impulses_, &body_collisions_, &plate_collisions_, &unresolved_,
                            &island_key_, &island_order_, &partner_})
                a->resize(room);
            hit_speed_.resize(room);
            island_sweeps_.resize(room);
        }
        exec_.launch(spheres, WriteContacts{sphere_arrays(), body_arrays(), species_arrays(), cells,
                                            system_arrays(), body_offset_.data(),
                                            plate_offset_.data(), body_contact_count_,
                                            contacts_.data(), depth_.data(), partner_.data()});
        std::vector<double> deepest;
        exec_.segmented_max(depth_, segments_, deepest);
        gross_.assign(systems, 0);
        for (std::size_t m = 0; m < systems; ++m) {
            stats[m].body_contacts = ranges_[m].body_count;
            stats[m].plate_contacts = plate_count_of(m);
            stats[m].max_overlap_fraction = std::max(deepest[m], deepest[systems + m]);
            if (stats[m].max_overlap_fraction > gross_overlap_fraction_) count_gross(m);
        }
    }

    // Rare (a blow-up): counted on the host.
    void count_gross(std::size_t m) {
        std::vector<double> depth, plate;
        exec_.download(depth_, ranges_[m].body_first, ranges_[m].body_count, depth);
        exec_.download(depth_, ranges_[m].plate_first, plate_count_of(m), plate);
        depth.insert(depth.end(), plate.begin(), plate.end());
        gross_[m] = static_cast<std::size_t>(std::count_if(
            depth.begin(), depth.end(), [this](double d) { return d > gross_overlap_fraction_; }));
    }

    void resolve(std::vector<StepStatistics>& stats) {
        const std::size_t systems = members_.size();
        for (std::size_t m = 0; m < systems; ++m)
            stats[m].unresolved = gross_[m];
        const std::uint32_t c = contact_count_;
        const auto n = static_cast<std::uint32_t>(host_body_count());
        if (c == 0) return;
        const BodyArrays bodies = body_arrays();
        exec_.launch(n, WorldInverseInertia{bodies, species_arrays(), inv_mass_.data(),
                                            inv_inertia_.data()});
        exec_.launch(n, InitIslands{parent_.data()});
        exec_.launch(body_contact_count_, HookIslands{contacts_.data(), parent_.data()});
        exec_.launch(n, CompressIslands{parent_.data()});
        exec_.launch(c, KeyContactsByIsland{contacts_.data(), parent_.data(), island_key_.data(),
                                            island_order_.data()});
        exec_.sort_by_key(island_key_, island_order_, c, key_bits(n));
        exec_.fill(island_start_, n, 0u);
        exec_.fill(island_end_, n, 0u);
        exec_.launch(c, MarkRuns{island_key_.data(), c, island_start_.data(), island_end_.data()});
        exec_.fill(last_changed_, n, 0);
        exec_.fill(island_sweeps_, c, 0.0);
        for (auto* a : {&impulses_, &body_collisions_, &plate_collisions_, &unresolved_})
            exec_.fill(*a, c, 0u);
        exec_.fill(hit_speed_, c, 0.0);
        const IslandTallies tallies{island_sweeps_.data(),   impulses_.data(),
                                    body_collisions_.data(), plate_collisions_.data(),
                                    unresolved_.data(),      hit_speed_.data()};
        exec_.launch(c, SweepIslands{contacts_.data(), island_key_.data(), island_order_.data(),
                                     island_end_.data(),
                                     IslandBodies{bodies, inv_mass_.data(), inv_inertia_.data()},
                                     system_arrays(), last_changed_.data(), tallies});
        std::vector<double> sweeps;
        std::vector<std::uint64_t> impulses, body_collisions, plate_collisions, unresolved;
        exec_.segmented_max(island_sweeps_, segments_, sweeps);
        exec_.segmented_sum(impulses_, segments_, impulses);
        exec_.segmented_sum(body_collisions_, segments_, body_collisions);
        exec_.segmented_sum(plate_collisions_, segments_, plate_collisions);
        exec_.segmented_sum(unresolved_, segments_, unresolved);
        for (std::size_t m = 0; m < systems; ++m) {
            const std::size_t p = systems + m;  // the system's plate-contact segment
            stats[m].sweeps = static_cast<int>(std::max(sweeps[m], sweeps[p]));
            stats[m].impulses = impulses[m] + impulses[p];
            stats[m].body_collisions = body_collisions[m] + body_collisions[p];
            stats[m].plate_collisions = plate_collisions[m] + plate_collisions[p];
            stats[m].unresolved += unresolved[m] + unresolved[p];
        }
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

    // The systems.
    Array<StepContext> contexts_;
    Array<std::uint32_t> system_of_body_, first_body_of_system_, system_first_sphere_;
    Array<SystemGrid> grids_;
    std::vector<SystemGrid> host_grids_;
    std::vector<ContactRange> ranges_;
    std::vector<std::uint32_t> segments_;  // body then plate contact ranges, 2 × systems
    std::vector<std::size_t> gross_;

    // Scratch of the stages, reused every step.
    Array<double> drift2_, turn2_;
    std::uint32_t cells_ = 0;
    int cell_key_bits_ = 1;
    Array<std::uint32_t> cell_key_, cell_sphere_, cell_start_, cell_end_;
    Array<std::uint32_t> body_count_, plate_count_, body_offset_, plate_offset_;
    Array<std::uint32_t> boundary_values_;
    Array<Contact> contacts_;
    Array<double> depth_;
    std::uint32_t contact_count_ = 0, body_contact_count_ = 0;
    Array<std::uint32_t> partner_;
    Array<double> inv_mass_;
    Array<Mat3> inv_inertia_;
    Array<std::uint32_t> parent_, island_key_, island_order_, island_start_, island_end_;
    Array<int> last_changed_;
    Array<double> island_sweeps_;
    Array<std::uint32_t> impulses_, body_collisions_, plate_collisions_, unresolved_, kicks_;
    Array<double> hit_speed_;
    std::uint64_t steps_ = 0;

    // The host's copies are refreshed when read after a step.
    mutable std::vector<std::vector<Contact>> host_contacts_;
    mutable std::vector<char> bodies_stale_, spheres_stale_, contacts_stale_;
};

}  // namespace rodsea::parallel
