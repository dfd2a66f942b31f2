#pragma once
// The one cap on the bins of a histogram or grid that an observable holds in memory, checked by
// each compute object before it allocates (so `rodsea analyze` and Python's objects alike refuse
// a zero or tiny bin instead of asking for the memory of billions): bins beyond 10⁷ (80 MB each)
// resolve nothing a frame of 10⁵ bodies can fill.
#include <cmath>
#include <string>

#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

inline constexpr double kMaxHistogramBins = 1e7;

// `bins` (a double: a ratio of lengths may be anything, NaN included) from `from`, e.g.
// "pair.r_max / pair.bin"; InvalidParameter named `key` with the `given` value beyond the cap.
inline void require_bins(const std::string& key, const std::string& given, double bins,
                         const std::string& from) {
    if (bins <= kMaxHistogramBins) return;
    throw InvalidParameter(key, given, "at most " + format_number(kMaxHistogramBins) + " bins",
                           (std::isfinite(bins) ? format_number(std::ceil(bins)) : "unbounded") +
                               " bins from " + from);
}

}  // namespace rodsea
