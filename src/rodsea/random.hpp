#pragma once
// Random numbers whose values are fixed by this file alone (std:: distributions differ between
// standard libraries, which would break bit-for-bit reproducibility across machines).
#include <cstdint>

#include "rodsea/math/hostdevice.hpp"

namespace rodsea {

RODSEA_HD constexpr std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

class SplitMix64 {
  public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() { return splitmix64(state_++); }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    std::uint64_t state() const { return state_; }

  private:
    std::uint64_t state_;
};

}  // namespace rodsea
