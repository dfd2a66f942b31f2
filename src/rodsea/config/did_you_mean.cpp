#include "rodsea/config/did_you_mean.hpp"

#include <algorithm>
#include <cctype>

namespace rodsea::config {

namespace {
char lower(char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}
}  // namespace

size_t edit_distance(std::string_view a, std::string_view b) {
    const size_t n = a.size(), m = b.size();
    std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
    for (size_t i = 0; i <= n; ++i)
        d[i][0] = i;
    for (size_t j = 0; j <= m; ++j)
        d[0][j] = j;
    for (size_t i = 1; i <= n; ++i) {
        for (size_t j = 1; j <= m; ++j) {
            const size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
                lower(a[i - 2]) == lower(b[j - 1])) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}

std::optional<std::string> closest_match(std::string_view given,
                                         const std::vector<std::string>& candidates) {
    const size_t limit = given.size() <= 3 ? 1 : given.size() <= 8 ? 2 : 3;
    std::optional<std::string> best;
    size_t best_distance = limit + 1;
    for (const std::string& c : candidates) {
        const size_t d = edit_distance(given, c);
        // Replacing every letter is no typo ("b" is not a misspelt "a").
        if (d < best_distance && d < given.size()) {
            best_distance = d;
            best = c;
        }
    }
    if (best || given.size() < 3) return best;
    // A truncated word ("polar" for "polar_rod") is far in edits but plain to a reader.
    for (const std::string& c : candidates)
        if (c.size() > given.size() && edit_distance(given, c.substr(0, given.size())) == 0)
            return c;
    return best;
}

}  // namespace rodsea::config
