#include "rodsea/engine/backend_factory.hpp"

#include "rodsea/engine/cpu/coasting_backend.hpp"
#include "rodsea/engine/cpu/cpu_backend.hpp"
#include "rodsea/engine/parallel/host_executor.hpp"
#include "rodsea/engine/parallel/parallel_backend.hpp"
#include "rodsea/engine/parallel/parallel_ensemble.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"

#if defined(RODSEA_HAVE_CUDA)
#include "rodsea/engine/cuda/gpu_backend.hpp"
#endif

namespace rodsea {

const char* to_string(BackendKind kind) {
    switch (kind) {
        case BackendKind::cpu:
            return "cpu";
        case BackendKind::gpu:
            return "gpu";
        case BackendKind::gpu_on_host:
            return "gpu-on-host";
    }
    return "?";
}

bool parse_backend(const std::string& text, BackendKind& kind) {
    if (text == "cpu") {
        kind = BackendKind::cpu;
        return true;
    }
    if (text == "gpu") {
        kind = BackendKind::gpu;
        return true;
    }
    return false;
}

BackendKind backend_flag(const std::string& flag, const std::string& text) {
    BackendKind kind{};
    if (!parse_backend(text, kind)) throw InvalidParameter(flag, text, "cpu or gpu");
    return kind;
}

GpuAvailability gpu_availability() {
#if defined(RODSEA_HAVE_CUDA)
    return cuda::probe_device();
#else
    return {false,
            "this rodsea was built without CUDA (no nvcc when it was configured): install the "
            "CUDA toolkit, set CUDA_HOME to it and configure with -DRODSEA_CUDA=ON"};
#endif
}

void require_usable_backend(BackendKind backend, const std::string& key) {
    if (backend != BackendKind::gpu) return;
    const GpuAvailability gpu = gpu_availability();
    if (!gpu.usable) throw InvalidParameter(key, "gpu", "cpu on this machine", gpu.description);
}

parallel::EnsembleMember ensemble_member(const SpeciesTable& species, BodyState bodies) {
    cpu::SphereTable table;
    table.assign(bodies.species, species);
    table.update_positions(bodies.view(), species, 1);
    return {&species,
            std::move(bodies),
            {std::move(table.body), std::move(table.radius), std::move(table.position),
             std::move(table.first_of)}};
}

std::unique_ptr<parallel::EnsembleStepper> make_ensemble_stepper(
    const std::vector<std::pair<const SpeciesTable*, BodyState>>& systems,
    const BackendOptions& options) {
    std::vector<parallel::EnsembleMember> members;
    for (const auto& [species, bodies] : systems)
        members.push_back(ensemble_member(*species, bodies));
    std::unique_ptr<parallel::EnsembleStepper> stepper;
    switch (options.backend) {
        case BackendKind::gpu_on_host:
            stepper = std::make_unique<parallel::ParallelEnsemble<parallel::HostExecutor>>(
                std::move(members), kGrossOverlapFraction, parallel::HostExecutor(options.threads));
            break;
        case BackendKind::gpu: {
            const GpuAvailability gpu = gpu_availability();
            if (!gpu.usable)
                throw InvalidParameter("backend", "\"gpu\"", "\"cpu\" here", gpu.description);
#if defined(RODSEA_HAVE_CUDA)
            stepper = cuda::make_gpu_ensemble(std::move(members), kGrossOverlapFraction);
#endif
            break;
        }
        case BackendKind::cpu:
            break;
    }
    if (stepper) {
        stepper->set_stage_timing(options.time_stages);
        return stepper;
    }
    throw InvalidParameter("backend", to_string(options.backend), "\"gpu\"",
                           "the data-parallel step runs the GPU backend's algorithm");
}

std::unique_ptr<StepBackend> make_backend(const SpeciesTable& species, BodyState bodies,
                                          const BackendOptions& options) {
    if (options.backend == BackendKind::cpu && options.coasting)
        return std::make_unique<cpu::CoastingBackend>(species, std::move(bodies), options.threads);
    if (options.backend == BackendKind::cpu)
        return std::make_unique<cpu::CpuBackend>(species, std::move(bodies), options.threads);
    std::vector<std::pair<const SpeciesTable*, BodyState>> one;
    one.emplace_back(&species, std::move(bodies));
    return std::make_unique<parallel::OneSystemBackend>(to_string(options.backend),
                                                        make_ensemble_stepper(one, options));
}

}  // namespace rodsea
