#pragma once
// One system stepped by an executor's ensemble (parallel_ensemble.hpp): the GPU backend, and its
// host twin, as the StepBackend a Simulation holds.
#include <memory>
#include <vector>

#include "rodsea/engine/parallel/parallel_ensemble.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea::parallel {

class OneSystemBackend final : public StepBackend {
  public:
    OneSystemBackend(const char* name, std::unique_ptr<EnsembleStepper> ensemble)
        : name_(name), ensemble_(std::move(ensemble)), contexts_(1) {}

    const char* name() const override { return name_; }
    void step(const StepContext& context, StepStatistics& stats, StageProfile& profile) override {
        contexts_[0] = context;
        ensemble_->step(contexts_, stats_, profile);
        stats = stats_[0];
    }
    const BodyState& bodies() const override { return ensemble_->bodies(0); }
    SphereView spheres() const override { return ensemble_->spheres(0); }
    const std::vector<Contact>& contacts() const override { return ensemble_->contacts(0); }
    std::uint64_t pair_list_builds() const override { return ensemble_->steps(); }  // per step
    void set_threads(int threads) override { ensemble_->set_threads(threads); }

  private:
    const char* name_;
    std::unique_ptr<EnsembleStepper> ensemble_;
    std::vector<StepContext> contexts_;
    std::vector<StepStatistics> stats_;
};

}  // namespace rodsea::parallel
