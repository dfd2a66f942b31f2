#pragma once
// The GPU backend's entry points, compiled by nvcc (gpu_backend.cu) where CUDA is built; this
// header has nothing of CUDA, so the host's code calls them as any function.
#include <memory>

#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/parallel/parallel_backend.hpp"

namespace rodsea::cuda {

// The first CUDA device, or why there is none.
GpuAvailability probe_device();

std::unique_ptr<StepBackend> make_gpu_backend(const SpeciesTable& species, BodyState bodies,
                                              parallel::InitialSpheres spheres,
                                              double gross_overlap_fraction);

}  // namespace rodsea::cuda
