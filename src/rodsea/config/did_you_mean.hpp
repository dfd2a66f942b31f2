#pragma once
// Suggestions for misspelt keys and values ("gamm" → "gamma", "lenght" → "length").
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rodsea::config {

// Optimal-string-alignment distance (Levenshtein plus transposition of neighbours), ignoring
// ASCII case.
size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `given`, if it is close enough to be a plausible typo: at most one
// edit for words of up to 3 letters, two up to 8, three beyond. Ties go to the earlier one.
// Failing that, a candidate that starts with `given` (3 letters or more).
std::optional<std::string> closest_match(std::string_view given,
                                         const std::vector<std::string>& candidates);

}  // namespace rodsea::config
