#pragma once
// The few words that kernels of one launch share: a flag every writer sets to the same value,
// and colouring marks that one element writes while its neighbours read them. Relaxed atomics on
// the host (OpenMP threads), volatile accesses on a device: either way a reader sees the old or
// the new value, and the kernels are written so that both give the same result.
#include <atomic>

#include "rodsea/math/hostdevice.hpp"

namespace rodsea::parallel {

RODSEA_HD inline int load_shared(const int* p) {
#if defined(__CUDA_ARCH__)
    return *static_cast<const volatile int*>(p);
#else
    // atomic_ref<const int> is C++26: the load writes nothing.
    return std::atomic_ref<int>(*const_cast<int*>(p)).load(std::memory_order_relaxed);
#endif
}

RODSEA_HD inline void store_shared(int* p, int value) {
#if defined(__CUDA_ARCH__)
    *static_cast<volatile int*>(p) = value;
#else
    std::atomic_ref<int>(*p).store(value, std::memory_order_relaxed);
#endif
}

}  // namespace rodsea::parallel
