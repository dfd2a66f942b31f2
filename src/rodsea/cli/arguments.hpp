#pragma once
// Command-line words split by the flags a command accepts. Anything else is an error that names
// the word and lists the accepted flags, so a typo never silently changes what a command does.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rodsea {

struct Arguments {
    std::vector<std::string> positional;
    std::vector<std::pair<std::string, std::string>> values;  // --flag VALUE, in order given
    std::vector<std::string> switches;                        // --flag

    bool has(std::string_view flag) const;
    // The last value given for `flag` (a later flag overrides an earlier one).
    std::optional<std::string> value(std::string_view flag) const;
    // Every value given for a flag that may repeat (--param K=V --param K2=V2).
    std::vector<std::string> all_values(std::string_view flag) const;
};

// `words` are the words after the command name. Throws InvalidParameter for an unknown flag or
// a valued flag without its value.
Arguments parse_arguments(const std::vector<std::string>& words,
                          const std::vector<std::string>& valued,
                          const std::vector<std::string>& switches, std::string_view command);

// A number given to `flag`, checked to lie in [lo, hi]; the message names the flag, the text
// and the range with its unit.
double parse_number(std::string_view flag, const std::string& text, double lo, double hi,
                    const std::string& unit = "");
// 'text', for messages.
std::string quoted(const std::string& text);

// A whole number in [lo, hi].
long long parse_count(std::string_view flag, const std::string& text, long long lo, long long hi);

}  // namespace rodsea
