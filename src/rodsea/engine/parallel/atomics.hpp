#pragma once
// The few words that elements of one launch share: a flag every writer sets to the same value,
// and the island forest that contacts hook into. Relaxed atomics on the host (OpenMP threads),
// volatile accesses and atomicCAS on a device: a reader sees the old or the new value, and the
// kernels are written so that the result does not depend on which.
#include <atomic>
#include <cstdint>

#include "rodsea/math/hostdevice.hpp"

namespace rodsea::parallel {

RODSEA_HD inline std::uint32_t load_shared(const std::uint32_t* p) {
#if defined(__CUDA_ARCH__)
    return *static_cast<const volatile std::uint32_t*>(p);
#else
    return std::atomic_ref<std::uint32_t>(*const_cast<std::uint32_t*>(p))
        .load(std::memory_order_relaxed);
#endif
}

RODSEA_HD inline void store_shared(std::uint32_t* p, std::uint32_t value) {
#if defined(__CUDA_ARCH__)
    *static_cast<volatile std::uint32_t*>(p) = value;
#else
    std::atomic_ref<std::uint32_t>(*p).store(value, std::memory_order_relaxed);
#endif
}

// Sets *p to `desired` if it holds `expected`; true when it did.
RODSEA_HD inline bool compare_and_swap(std::uint32_t* p, std::uint32_t expected,
                                       std::uint32_t desired) {
#if defined(__CUDA_ARCH__)
    return atomicCAS(reinterpret_cast<unsigned int*>(p), expected, desired) == expected;
#else
    return std::atomic_ref<std::uint32_t>(*p).compare_exchange_strong(expected, desired,
                                                                      std::memory_order_relaxed);
#endif
}

}  // namespace rodsea::parallel
