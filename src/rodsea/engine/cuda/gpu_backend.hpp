#pragma once
// The GPU backend's entry points, compiled by nvcc (gpu_backend.cu) where CUDA is built; this
// header has nothing of CUDA, so the host's code calls them as any function.
#include <memory>
#include <vector>

#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/parallel/parallel_ensemble.hpp"

namespace rodsea::cuda {

// The first CUDA device, or why there is none.
GpuAvailability probe_device();

// The systems stepped together on the first CUDA device.
std::unique_ptr<parallel::EnsembleStepper> make_gpu_ensemble(
    std::vector<parallel::EnsembleMember> members, double gross_overlap_fraction);

}  // namespace rodsea::cuda
