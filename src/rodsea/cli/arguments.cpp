#include "rodsea/cli/arguments.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "rodsea/error.hpp"

namespace rodsea {

// Built by appending: GCC 12 at -O3 warns falsely (-Wrestrict) on "literal" + std::string.
std::string quoted(const std::string& text) {
    std::string q(1, '\'');
    q += text;
    q += '\'';
    return q;
}

bool Arguments::has(std::string_view flag) const {
    return std::find(switches.begin(), switches.end(), flag) != switches.end();
}

std::optional<std::string> Arguments::value(std::string_view flag) const {
    std::optional<std::string> found;
    for (const auto& [name, v] : values)
        if (name == flag) found = v;
    return found;
}

std::vector<std::string> Arguments::all_values(std::string_view flag) const {
    std::vector<std::string> found;
    for (const auto& [name, v] : values)
        if (name == flag) found.push_back(v);
    return found;
}

Arguments parse_arguments(const std::vector<std::string>& words,
                          const std::vector<std::string>& valued,
                          const std::vector<std::string>& switches, std::string_view command) {
    Arguments a;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& word = words[i];
        // Flags are --name or -o (short for --output); "-" and negative numbers are values.
        if (word.rfind("--", 0) != 0 && word != "-o") {
            a.positional.push_back(word);
            continue;
        }
        const std::string flag = word == "-o" ? "--output" : word;
        if (std::find(valued.begin(), valued.end(), flag) != valued.end()) {
            if (i + 1 >= words.size()) throw InvalidParameter(word, "nothing", "a value after it");
            a.values.emplace_back(flag, words[++i]);
        } else if (std::find(switches.begin(), switches.end(), flag) != switches.end()) {
            a.switches.push_back(flag);
        } else {
            std::string allowed;
            for (const auto& f : valued) {
                if (!allowed.empty()) allowed += ' ';
                allowed += f;
            }
            for (const auto& f : switches) {
                if (!allowed.empty()) allowed += ' ';
                allowed += f;
            }
            std::string what = "an unknown option of '";
            what += command;
            what += "'";
            throw InvalidParameter(word, what, allowed);
        }
    }
    return a;
}

double parse_number(std::string_view flag, const std::string& text, double lo, double hi,
                    const std::string& unit) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v) || v < lo || v > hi) {
        std::string allowed("a number in [");
        allowed += format_number(lo);
        allowed += ", ";
        allowed += format_number(hi);
        allowed += ']';
        if (!unit.empty()) allowed.append(" ").append(unit);
        throw InvalidParameter(std::string(flag), quoted(text), allowed);
    }
    return v;
}

long long parse_count(std::string_view flag, const std::string& text, long long lo, long long hi) {
    long long v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || ptr != end || v < lo || v > hi)
        throw InvalidParameter(
            std::string(flag), quoted(text),
            "a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
}

}  // namespace rodsea
