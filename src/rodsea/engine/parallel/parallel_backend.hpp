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
        : name_(name), ensemble_(std::move(ensemble)) {}

    const char* name() const override { return name_; }
    void step(const StepContext& context, StepStatistics& stats, StageProfile& profile) override {
        stats = run_steps({&context, 1}, nullptr, profile).last;
    }
    StepsDone run_steps(std::span<const StepContext> contexts, const BlowUpBounds* bounds,
                        StageProfile& profile) override {
        contexts_.assign(contexts.begin(), contexts.end());
        if (bounds != nullptr) bounds_.assign(1, *bounds);
        ensemble_->run(contexts_, contexts_.size(), bounds != nullptr ? &bounds_ : nullptr, done_,
                       profile);
        return done_[0];
    }
    const BodyState& bodies() const override { return ensemble_->bodies(0); }
    SphereView spheres() const override { return ensemble_->spheres(0); }
    const std::vector<Contact>& contacts() const override { return ensemble_->contacts(0); }
    std::uint64_t pair_list_builds() const override { return ensemble_->builds(); }
    void set_threads(int threads) override { ensemble_->set_threads(threads); }

  private:
    const char* name_;
    std::unique_ptr<EnsembleStepper> ensemble_;
    std::vector<StepContext> contexts_;
    std::vector<BlowUpBounds> bounds_;
    std::vector<StepsDone> done_;
};

}  // namespace rodsea::parallel
