#pragma once
// TOML text → ConfigValues, checking each key on its own: that it exists where it is written,
// its type and its range. Checks across keys are resolve.hpp's.
#include <string_view>

#include "rodsea/config/config_values.hpp"

namespace rodsea::config {

// Throws ConfigSyntaxError for bad TOML and InvalidParameter for an unknown key (with a
// suggestion), a wrong type or a value out of range.
ConfigValues read_toml(std::string_view text, std::string_view source_name);

}  // namespace rodsea::config
