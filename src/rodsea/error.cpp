#include "rodsea/error.hpp"

#include <sstream>

namespace rodsea {

namespace {
std::string with_unit(double v, const std::string& unit) {
    return unit.empty() ? format_number(v) : format_number(v) + " " + unit;
}
}  // namespace

InvalidParameter::InvalidParameter(const std::string& name, const std::string& value,
                                   const std::string& allowed, const std::string& why)
    : std::invalid_argument("invalid " + name + " = " + value + ": allowed " + allowed +
                            (why.empty() ? "" : " (" + why + ")")),
      name_(name) {}

InvalidParameter InvalidParameter::in_context(const std::string& context) const {
    return {Message{}, name_, std::string(what()) + " [" + context + "]"};
}

std::string format_number(double value) {
    std::ostringstream s;
    s.precision(6);
    s << value;
    return s.str();
}

void require_finite(const std::string& name, double value, const std::string& unit) {
    if (!std::isfinite(value))
        throw InvalidParameter(name, with_unit(value, unit), "a finite number");
}

void require_positive(const std::string& name, double value, const std::string& unit) {
    require_finite(name, value, unit);
    if (!(value > 0.0)) throw InvalidParameter(name, with_unit(value, unit), "> 0");
}

void require_non_negative(const std::string& name, double value, const std::string& unit) {
    require_finite(name, value, unit);
    if (!(value >= 0.0)) throw InvalidParameter(name, with_unit(value, unit), ">= 0");
}

void require_in_closed_range(const std::string& name, double value, double lo, double hi,
                             const std::string& unit) {
    require_finite(name, value, unit);
    if (!(value >= lo && value <= hi)) {
        throw InvalidParameter(name, with_unit(value, unit),
                               "[" + with_unit(lo, unit) + ", " + with_unit(hi, unit) + "]");
    }
}

void require_positive_count(const std::string& name, long long value) {
    if (value <= 0) throw InvalidParameter(name, std::to_string(value), "an integer >= 1");
}

}  // namespace rodsea
