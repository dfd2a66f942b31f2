#pragma once
// The few words that elements of one launch share: a flag every writer sets to the same value,
// the island forest that contacts hook into, the cursors that hand out places in a list, the
// islands' lists of contacts, and the counts and maxima a step's elements add to
// their system's tally. Relaxed atomics on the host (OpenMP threads), volatile accesses and
// atomic instructions on a device. Only integers are summed and only maxima are taken, so the
// result does not depend on the order in which the elements run: no floating-point sum is ever
// formed by atomics (that order would change the bits from run to run). Where the order does
// show (the place a cursor hands out, a list's order), the reader sorts what it reads.
#include <atomic>
#include <bit>
#include <cstdint>

#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/nan_as_infinity.hpp"

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

// *p += v; returns the old value (a rank among the elements that add to *p: which element gets
// which rank varies from run to run, so a caller sorts what it places by rank).
RODSEA_HD inline std::uint32_t atomic_add(std::uint32_t* p, std::uint32_t v) {
#if defined(__CUDA_ARCH__)
    return atomicAdd(reinterpret_cast<unsigned int*>(p), v);
#else
    return std::atomic_ref<std::uint32_t>(*p).fetch_add(v, std::memory_order_relaxed);
#endif
}

// *p = v; returns the old value (a list's head pushed onto: the order varies from run to run, so
// a caller sorts what it reads from such a list).
RODSEA_HD inline std::uint32_t atomic_exchange(std::uint32_t* p, std::uint32_t v) {
#if defined(__CUDA_ARCH__)
    return atomicExch(reinterpret_cast<unsigned int*>(p), v);
#else
    return std::atomic_ref<std::uint32_t>(*p).exchange(v, std::memory_order_relaxed);
#endif
}

RODSEA_HD inline void atomic_add(std::uint64_t* p, std::uint64_t v) {
#if defined(__CUDA_ARCH__)
    atomicAdd(reinterpret_cast<unsigned long long*>(p), static_cast<unsigned long long>(v));
#else
    std::atomic_ref<std::uint64_t>(*p).fetch_add(v, std::memory_order_relaxed);
#endif
}

RODSEA_HD inline void atomic_max(std::uint64_t* p, std::uint64_t v) {
#if defined(__CUDA_ARCH__)
    atomicMax(reinterpret_cast<unsigned long long*>(p), static_cast<unsigned long long>(v));
#else
    std::atomic_ref<std::uint64_t> a(*p);
    std::uint64_t seen = a.load(std::memory_order_relaxed);
    while (seen < v && !a.compare_exchange_weak(seen, v, std::memory_order_relaxed)) {
    }
#endif
}

// The bits of a double >= +0 order as the doubles do: the maximum of such values is the maximum
// of their bits as unsigned integers. NaN counts as +infinity (as every backend's maxima do),
// and anything below +0 (−0 included, whose sign bit would sort it last) as +0.
RODSEA_HD inline std::uint64_t ordered_bits(double v) {
    v = nan_as_infinity(v);
    v = v > 0.0 ? v : 0.0;
#if defined(__CUDA_ARCH__)
    return static_cast<std::uint64_t>(__double_as_longlong(v));
#else
    return std::bit_cast<std::uint64_t>(v);
#endif
}
RODSEA_HD inline double from_ordered_bits(std::uint64_t bits) {
#if defined(__CUDA_ARCH__)
    return __longlong_as_double(static_cast<long long>(bits));
#else
    return std::bit_cast<double>(bits);
#endif
}

// *max_bits = the largest of it and v (as ordered_bits). On a device the lanes of a full warp
// that share the target take their maximum among themselves first, so that one element in 32
// touches the word: every body of a system adds its speed to one word each step.
RODSEA_HD inline void atomic_max_of(std::uint64_t* max_bits, double v) {
    std::uint64_t bits = ordered_bits(v);
#if defined(__CUDA_ARCH__)
    const unsigned mask = __activemask();
    const auto target = reinterpret_cast<unsigned long long>(max_bits);
    if (mask == 0xffffffffu && __match_any_sync(mask, target) == mask) {
        for (int lane = 16; lane > 0; lane >>= 1) {
            const auto other = static_cast<std::uint64_t>(
                __shfl_xor_sync(mask, static_cast<unsigned long long>(bits), lane));
            bits = other > bits ? other : bits;
        }
        if ((threadIdx.x & 31u) != 0) return;
    }
#endif
    atomic_max(max_bits, bits);
}

}  // namespace rodsea::parallel
