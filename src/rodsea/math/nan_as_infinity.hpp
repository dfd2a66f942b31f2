#pragma once
// For a value that is reduced by a maximum: NaN made +∞. A NaN compares false, so one maximum
// (std::max) drops it and another (a device's reduction) may keep it; as +∞ every executor keeps
// it, and the step's blow-up check sees it.
#include <cmath>

#include "rodsea/math/hostdevice.hpp"

namespace rodsea {

RODSEA_HD inline double nan_as_infinity(double x) {
    return x == x ? x : HUGE_VAL;
}

}  // namespace rodsea
