#include "rodsea/number_text.hpp"

#include <charconv>

namespace rodsea {

std::string exact_number(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace rodsea
