#pragma once
// The CPU executor of the step: each stage an OpenMP loop over the state in host memory, calling
// the per-element physics of engine/physics/. Every stage splits its work into contiguous chunks
// in index order (or into independent islands of contacts) and writes each result where the
// serial loop would: the trajectory is the same, bit for bit, on any number of threads.
#include <vector>

#include "rodsea/engine/cpu/contact_response.hpp"
#include "rodsea/engine/cpu/contact_search.hpp"
#include "rodsea/engine/cpu/sphere_table.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea::cpu {

class CpuBackend final : public StepBackend {
  public:
    // `species` must outlive the backend. threads >= 1 (checked by Simulation).
    CpuBackend(const SpeciesTable& species, BodyState bodies, int threads);

    const char* name() const override { return "cpu"; }
    void step(const StepContext& context, StepStatistics& stats, StageProfile& profile) override;
    const BodyState& bodies() const override { return bodies_; }
    SphereView spheres() const override { return spheres_.view(); }
    const std::vector<Contact>& contacts() const override { return contacts_; }
    void set_threads(int threads) override { threads_ = threads; }
    std::uint64_t pair_list_builds() const override { return finder_.pair_list_builds(); }

  private:
    const SpeciesTable& species_;
    BodyState bodies_;
    int threads_;

    // Scratch reused every step: no allocation in the steady state.
    SphereTable spheres_;
    ContactFinder finder_;
    std::vector<Contact> contacts_;
    ContactResponse response_;
};

}  // namespace rodsea::cpu
