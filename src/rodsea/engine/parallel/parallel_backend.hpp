#pragma once
// The data-parallel step (kernels.hpp) run by an executor: the GPU backend with the CUDA
// executor, its host twin with HostExecutor. The state lives in the executor's memory; the host
// sees it through bodies(), spheres() and contacts(), which copy it over when it changed.
//
// A step, with the executor's launches, scans, sorts and reductions:
//   1 free flight per body;  2 sphere centres per body;
//   3 contact search: spheres sorted by cell (a cell list rebuilt every step), contacts counted
//     per sphere, placed by an exclusive scan and written: the list is a function of the state;
//   4 resolution: contacts coloured (Jones–Plassmann) so that no two of a colour share a body,
//     then swept colour by colour until a sweep gives no impulse or the sweep cap is reached
//     (the CPU's stopping rule); the projection out of the plates per body;
//   5 noise per polar body, from its plate contacts' fastest approach.
// What differs from the CPU backend is the order of the impulses (colour order instead of list
// order within an island): the same physics and stopping rule, statistically equal trajectories,
// not equal bits.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parallel/contact_colouring.hpp"
#include "rodsea/engine/parallel/kernels.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/stage_timer.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea::parallel {

// The spheres as the step starts from them (cpu::SphereTable's arrays).
struct InitialSpheres {
    std::vector<std::uint32_t> body;
    std::vector<double> radius;
    std::vector<Vec3> position;
    std::vector<std::uint32_t> first_of;
};

// `gross_overlap_fraction`: the depth over the smaller radius beyond which a contact counts as
// unresolvable (state_check.hpp's kGrossOverlapFraction, passed in: this header is compiled for
// a device too).
template <class Executor>
class ParallelBackend final : public StepBackend {
  public:
    ParallelBackend(const char* name, const SpeciesTable& species, BodyState bodies,
                    InitialSpheres spheres, double gross_overlap_fraction, Executor executor)
        : name_(name),
          gross_overlap_fraction_(gross_overlap_fraction),
          exec_(std::move(executor)),
          host_bodies_(std::move(bodies)),
          host_spheres_(std::move(spheres)) {
        upload_species(species);
        exec_.upload(body_species_, host_bodies_.species);
        exec_.upload(position_, host_bodies_.position);
        exec_.upload(orientation_, host_bodies_.orientation);
        exec_.upload(velocity_, host_bodies_.velocity);
        exec_.upload(spin_, host_bodies_.spin);
        exec_.upload(sphere_body_, host_spheres_.body);
        exec_.upload(sphere_radius_, host_spheres_.radius);
        exec_.upload(sphere_position_, host_spheres_.position);
        exec_.upload(first_of_, host_spheres_.first_of);
        const double widest =
            2.0 * *std::max_element(species.sphere_radius.begin(), species.sphere_radius.end());
        contact_reach_ = widest;
        const std::size_t n = host_bodies_.size(), s = host_spheres_.body.size();
        for (auto* a : {&drift2_, &turn2_, &inv_mass_})
            a->resize(n);
        inv_inertia_.resize(n);
        last_changed_.resize(n);
        kicks_.resize(n);
        for (auto* a : {&cell_key_, &cell_sphere_, &body_count_, &plate_count_, &body_offset_,
                        &plate_offset_})
            a->resize(s);
        flag_.resize(1);
    }

    const char* name() const override { return name_; }
    void set_threads(int threads) override { exec_.set_threads(threads); }
    std::uint64_t pair_list_builds() const override { return steps_; }  // a cell list per step

    const BodyState& bodies() const override {
        if (bodies_stale_) {
            exec_.download(position_, host_bodies_.size(), host_bodies_.position);
            exec_.download(orientation_, host_bodies_.size(), host_bodies_.orientation);
            exec_.download(velocity_, host_bodies_.size(), host_bodies_.velocity);
            exec_.download(spin_, host_bodies_.size(), host_bodies_.spin);
            bodies_stale_ = false;
        }
        return host_bodies_;
    }
    SphereView spheres() const override {
        if (spheres_stale_) {
            exec_.download(sphere_position_, host_spheres_.body.size(), host_spheres_.position);
            spheres_stale_ = false;
        }
        return {host_spheres_.body, host_spheres_.radius, host_spheres_.position,
                host_spheres_.first_of};
    }
    const std::vector<Contact>& contacts() const override {
        if (contacts_stale_) {
            exec_.download(contacts_, contact_count_, host_contacts_);
            contacts_stale_ = false;
        }
        return host_contacts_;
    }

    void step(const StepContext& context, StepStatistics& stats, StageProfile& profile) override {
        bodies_stale_ = spheres_stale_ = contacts_stale_ = true;
        ++steps_;
        const BodyArrays bodies = body_arrays();
        const SpeciesArrays species = species_arrays();
        const std::uint32_t n = bodies.count;
        double fastest = 0.0;
        {
            StageTimer t(profile.free_flight);
            exec_.launch(n, FlyBodies{bodies, species, context, drift2_.data(), turn2_.data()});
            fastest = std::sqrt(exec_.max_of(drift2_, n)) + std::sqrt(exec_.max_of(turn2_, n));
            exec_.finish();
        }
        {
            StageTimer t(profile.sphere_update);
            exec_.launch(n, PlaceSpheres{bodies, species, sphere_arrays()});
            exec_.finish();
        }
        {
            StageTimer t(profile.contact_search);
            find_contacts(context, stats);
            exec_.finish();
        }
        {
            StageTimer t(profile.resolution);
            resolve(context, stats);
            exec_.launch(n, ProjectOutOfPlates{bodies, sphere_arrays(), context.plates});
            exec_.finish();
        }
        {
            StageTimer t(profile.noise);
            stats.noise_kicks = 0;
            if (context.noise_epsilon != 0.0 && contact_count_ > 0) {
                exec_.launch(
                    n, KickPolarBodies{bodies, species, contacts_.data(), colouring_.incidence(),
                                       hit_speed_.data(), context, kicks_.data()});
                stats.noise_kicks = exec_.sum_of(kicks_, 0, n);
            }
            exec_.finish();
        }
        stats.max_planar_speed = fastest;
    }

  private:
    template <class T>
    using Array = typename Executor::template Array<T>;

    void upload_species(const SpeciesTable& s) {
        exec_.upload(inverse_mass_, s.inverse_mass);
        exec_.upload(inverse_inertia_, s.inverse_inertia);
        exec_.upload(rotor_, s.rotor);
        exec_.upload(reach2_, s.reach2);
        exec_.upload(sphere_axis_, s.sphere_axis);
        exec_.upload(first_sphere_, s.first_sphere);
        exec_.upload(sphere_offset_, s.sphere_offset);
        exec_.upload(plate_coefficients_, s.plate);
        exec_.upload(pair_coefficients_, s.pair);
        exec_.upload(polar_, s.polar);
        species_count_ = static_cast<std::uint32_t>(s.size());
    }

    BodyArrays body_arrays() {
        return {body_species_.data(), position_.data(),
                orientation_.data(),  velocity_.data(),
                spin_.data(),         static_cast<std::uint32_t>(host_bodies_.size())};
    }
    SpeciesArrays species_arrays() const {
        return {inverse_mass_.data(),
                inverse_inertia_.data(),
                rotor_.data(),
                reach2_.data(),
                sphere_axis_.data(),
                first_sphere_.data(),
                sphere_offset_.data(),
                plate_coefficients_.data(),
                pair_coefficients_.data(),
                polar_.data(),
                species_count_};
    }
    SphereArrays sphere_arrays() {
        return {sphere_body_.data(), sphere_radius_.data(), sphere_position_.data(),
                first_of_.data(), static_cast<std::uint32_t>(host_spheres_.body.size())};
    }

    // Cells no narrower than the widest contact reach; no more cells than a few per sphere (a
    // huge box of few spheres would otherwise sweep an empty grid every step).
    void size_grid(const PeriodicBox2D& box) {
        const auto across = [this](double side) {
            return std::max<std::uint32_t>(
                1, static_cast<std::uint32_t>(std::floor(side / contact_reach_)));
        };
        CellGrid g{across(box.lx), across(box.ly), 0.0, 0.0};
        const std::size_t cap = 4 * host_spheres_.body.size() + 64;
        while (std::size_t{g.nx} * g.ny > cap) {
            g.nx = std::max<std::uint32_t>(1, g.nx / 2);
            g.ny = std::max<std::uint32_t>(1, g.ny / 2);
        }
        g.width_x = box.lx / g.nx;
        g.width_y = box.ly / g.ny;
        if (g.nx != grid_.nx || g.ny != grid_.ny || g.width_x != grid_.width_x ||
            g.width_y != grid_.width_y) {
            grid_ = g;
            cell_start_.resize(grid_.cells());
            cell_end_.resize(grid_.cells());
            key_bits_ = key_bits(grid_.cells());
        }
    }

    void find_contacts(const StepContext& step, StepStatistics& stats) {
        const std::uint32_t spheres = static_cast<std::uint32_t>(host_spheres_.body.size());
        size_grid(step.box);
        exec_.launch(spheres, KeySpheresByCell{sphere_arrays(), grid_, step.box, cell_key_.data(),
                                               cell_sphere_.data()});
        exec_.sort_by_key(cell_key_, cell_sphere_, spheres, key_bits_);
        exec_.fill(cell_start_, grid_.cells(), 0u);
        exec_.fill(cell_end_, grid_.cells(), 0u);
        exec_.launch(spheres,
                     MarkRuns{cell_key_.data(), spheres, cell_start_.data(), cell_end_.data()});
        const CellList cells{grid_, cell_sphere_.data(), cell_start_.data(), cell_end_.data()};
        exec_.launch(spheres, CountContacts{sphere_arrays(), body_arrays(), cells, step,
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
        if (contacts_.size() < contact_count_) {
            const std::size_t room = contact_count_ + contact_count_ / 4 + 64;
            contacts_.resize(room);
            depth_.resize(room);
            for (auto* a : {&impulses_, &collisions_, &approaching_})
                a->resize(room);
            hit_speed_.resize(room);
        }
        exec_.launch(spheres, WriteContacts{sphere_arrays(), body_arrays(), species_arrays(), cells,
                                            step, body_offset_.data(), plate_offset_.data(),
                                            body_contact_count_, contacts_.data(), depth_.data()});
        stats.body_contacts = body_contacts;
        stats.plate_contacts = plate_contacts;
        stats.max_overlap_fraction = exec_.max_of(depth_, contact_count_);
        gross_ = 0;
        if (stats.max_overlap_fraction > gross_overlap_fraction_) count_gross();
    }

    // Rare (a blow-up): counted on the host.
    void count_gross() {
        std::vector<double> depth;
        exec_.download(depth_, contact_count_, depth);
        gross_ = static_cast<std::size_t>(std::count_if(
            depth.begin(), depth.end(), [this](double d) { return d > gross_overlap_fraction_; }));
    }

    void resolve(const StepContext& step, StepStatistics& stats) {
        stats.sweeps = 0;
        stats.impulses = stats.body_collisions = stats.plate_collisions = 0;
        stats.unresolved = gross_;
        const std::uint32_t c = contact_count_, n = static_cast<std::uint32_t>(host_bodies_.size());
        if (c == 0) return;
        const BodyArrays bodies = body_arrays();
        exec_.launch(n, WorldInverseInertia{bodies, species_arrays(), inv_mass_.data(),
                                            inv_inertia_.data()});
        colouring_.colour(exec_, contacts_, c, body_contact_count_, n);
        exec_.fill(last_changed_, n, 0);
        exec_.fill(impulses_, c, 0u);
        exec_.fill(collisions_, c, 0u);
        exec_.fill(hit_speed_, c, 0.0);
        const ContactTallies tallies{impulses_.data(), collisions_.data(), hit_speed_.data()};
        bool any_impulse = true;
        while (any_impulse && stats.sweeps < step.max_sweeps) {
            ++stats.sweeps;
            exec_.write(flag_, 0, 0);
            for (int colour = 0; colour < colouring_.colours(); ++colour) {
                const auto r = colouring_.range(colour);
                exec_.launch(r.count,
                             SweepColour{contacts_.data(), colouring_.order(), r.first, bodies,
                                         inv_mass_.data(), inv_inertia_.data(), step, stats.sweeps,
                                         last_changed_.data(), tallies, flag_.data()});
            }
            any_impulse = exec_.read(flag_, 0) != 0;
        }
        stats.impulses = exec_.sum_of(impulses_, 0, c);
        stats.body_collisions = exec_.sum_of(collisions_, 0, body_contact_count_);
        stats.plate_collisions = exec_.sum_of(collisions_, body_contact_count_, c);
        if (any_impulse) {
            exec_.launch(c, FlagApproaching{contacts_.data(), bodies, step, approaching_.data()});
            stats.unresolved += exec_.sum_of(approaching_, 0, c);
        }
    }

    const char* name_;
    double gross_overlap_fraction_;
    mutable Executor exec_;

    // The species (SpeciesTable's arrays).
    Array<double> inverse_mass_, reach2_;
    Array<Vec3> inverse_inertia_, sphere_offset_;
    Array<physics::Rotor> rotor_;
    Array<int> sphere_axis_;
    Array<std::uint32_t> first_sphere_;
    Array<ContactCoefficients> plate_coefficients_, pair_coefficients_;
    Array<std::uint8_t> polar_;
    std::uint32_t species_count_ = 0;

    // The state.
    Array<std::uint32_t> body_species_;
    Array<Vec3> position_, velocity_, spin_;
    Array<Quat> orientation_;
    Array<std::uint32_t> sphere_body_, first_of_;
    Array<double> sphere_radius_;
    Array<Vec3> sphere_position_;

    // Scratch of the stages, reused every step.
    Array<double> drift2_, turn2_;
    double contact_reach_ = 0.0;
    CellGrid grid_{0, 0, 0.0, 0.0};
    int key_bits_ = 1;
    Array<std::uint32_t> cell_key_, cell_sphere_, cell_start_, cell_end_;
    Array<std::uint32_t> body_count_, plate_count_, body_offset_, plate_offset_;
    Array<Contact> contacts_;
    Array<double> depth_;
    std::uint32_t contact_count_ = 0, body_contact_count_ = 0;
    std::size_t gross_ = 0;
    Array<double> inv_mass_;
    Array<Mat3> inv_inertia_;
    ContactColouring<Executor> colouring_;
    Array<int> flag_, last_changed_;
    Array<std::uint32_t> impulses_, collisions_, approaching_, kicks_;
    Array<double> hit_speed_;
    std::uint64_t steps_ = 0;

    // The host's copies, refreshed when read after a step.
    mutable BodyState host_bodies_;
    mutable InitialSpheres host_spheres_;
    mutable std::vector<Contact> host_contacts_;
    mutable bool bodies_stale_ = false, spheres_stale_ = false, contacts_stale_ = false;
};

}  // namespace rodsea::parallel
