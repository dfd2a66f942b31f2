// The GPU backend: the data-parallel ensemble step (engine/parallel/) instantiated with the CUDA
// executor.
// The only translation unit nvcc compiles for the engine.
#include <cuda_runtime.h>

#include <cstdio>
#include <memory>
#include <string>

#include "rodsea/engine/cuda/cuda_executor.cuh"
#include "rodsea/engine/cuda/gpu_backend.hpp"
#include "rodsea/engine/parallel/parallel_ensemble.hpp"

namespace rodsea::cuda {

GpuAvailability probe_device() {
    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess)
        return {false, std::string("no usable CUDA device: ") + cudaGetErrorString(status)};
    if (count == 0) return {false, "no CUDA device on this machine"};
    cudaDeviceProp p{};
    if (cudaGetDeviceProperties(&p, 0) != cudaSuccess)
        return {false, "the CUDA device did not answer"};
    char text[256];
    std::snprintf(text, sizeof text, "%s, sm_%d%d, %.1f GiB", p.name, p.major, p.minor,
                  static_cast<double>(p.totalGlobalMem) / (1024.0 * 1024.0 * 1024.0));
    // Whether the build's code runs there (sm_90 and compute_90 PTX by default): one of its
    // kernels asked for its attributes.
    cudaFuncAttributes attributes{};
    const cudaError_t image = cudaFuncGetAttributes(&attributes, run_kernel<parallel::ListIslands>);
    if (image != cudaSuccess) {
        cudaGetLastError();  // clear it: the device is still usable by others
        char advice[160];
        std::snprintf(advice, sizeof advice,
                      ": this rodsea has no code it can run (%s); configure with "
                      "-DCMAKE_CUDA_ARCHITECTURES=%d%d",
                      cudaGetErrorString(image), p.major, p.minor);
        return {false, std::string(text) + advice};
    }
    return {true, text};
}

std::unique_ptr<parallel::EnsembleStepper> make_gpu_ensemble(
    std::vector<parallel::EnsembleMember> members, double gross_overlap_fraction) {
    return std::make_unique<parallel::ParallelEnsemble<CudaExecutor>>(
        std::move(members), gross_overlap_fraction, CudaExecutor());
}

}  // namespace rodsea::cuda
