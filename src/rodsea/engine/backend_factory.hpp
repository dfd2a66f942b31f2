#pragma once
// Makes the backend a Simulation asks for, and says whether this build and machine can run the
// GPU backend at all, before any work (`rodsea info`, config validation).
#include <memory>
#include <string>

#include <utility>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea {

namespace parallel {
class EnsembleStepper;
struct EnsembleMember;
}  // namespace parallel

struct GpuAvailability {
    bool usable = false;
    // The device that would run ("NVIDIA H100 80GB HBM3, sm_90, 79.1 GiB"), or why none can:
    // a build without CUDA (and how to build one), or no usable device (and the driver's reason).
    std::string description;
};
GpuAvailability gpu_availability();

// Throws InvalidParameter naming `key` when `backend` cannot run on this build and machine (the
// GPU where there is none), saying why: for commands to check before any work.
void require_usable_backend(BackendKind backend, const std::string& key);

// Reads "cpu" or "gpu" (what users may ask for) into `kind`; false for anything else.
bool parse_backend(const std::string& text, BackendKind& kind);
// The same for a command-line flag: throws InvalidParameter naming `flag` for anything else.
BackendKind backend_flag(const std::string& flag, const std::string& text);

// `species` must outlive the backend. Throws InvalidParameter naming "backend" when the GPU is
// asked for and gpu_availability() says it cannot be used.
std::unique_ptr<StepBackend> make_backend(const SpeciesTable& species, BodyState bodies,
                                          const BackendOptions& options);

// A system as the data-parallel step takes it: its species (which must outlive it), state and
// sphere centres.
parallel::EnsembleMember ensemble_member(const SpeciesTable& species, BodyState bodies);

// The data-parallel step of many systems (gpu or gpu_on_host), each given as its species (which
// must outlive the stepper) and state. Throws InvalidParameter as make_backend does.
std::unique_ptr<parallel::EnsembleStepper> make_ensemble_stepper(
    const std::vector<std::pair<const SpeciesTable*, BodyState>>& systems,
    const BackendOptions& options);

}  // namespace rodsea
