#pragma once
// The resolved config as TOML: every key in force with its value, each commented with its
// description, unit, range and default, so that the file documents itself and reloads into the
// same plan.
#include <string>

#include "rodsea/config/config_values.hpp"

namespace rodsea::config {

// `values` must be resolved (resolve.hpp): complete, with the equivalents of the alternatives.
std::string write_toml(const ConfigValues& values);

// Wraps `text` into comment lines ("# ...") of at most 100 columns.
std::string comment_lines(const std::string& text);

}  // namespace rodsea::config
