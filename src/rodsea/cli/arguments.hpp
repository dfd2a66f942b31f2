#pragma once
// The one command-line parser of rodsea (CLI11 underneath). Each command declares its options in
// a CommandSpec; parse_arguments splits the words by it and help_text prints it, so the flags a
// command accepts and the help that lists them cannot drift apart. Anything parse_arguments
// cannot take is an error that names the word and lists the accepted flags: a typo never
// silently changes what a command does.
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rodsea {

struct OptionSpec {
    std::string flags;     // "--frame", or "-o,--output": the last is the name it is known by
    std::string value;     // what it takes, shown in the help ("N", "FILE"); empty: a switch
    std::string help;      // what it does; a new line in it continues under the first
    bool repeats = false;  // may be given several times, every value kept (--param K=V)
};

struct CommandSpec {
    std::string name;         // "render"
    std::string usage;        // what follows `rodsea render` in the synopsis
    std::string summary;      // one line, for `rodsea --help`
    std::string description;  // what it does, before the options
    std::vector<OptionSpec> options;
    std::string footer;  // after the options: files written, exit codes, ...
};

struct Arguments {
    std::vector<std::string> positional;
    std::vector<std::pair<std::string, std::string>> values;  // --flag VALUE, in order given
    std::vector<std::string> switches;                        // --flag
    bool help = false;                                        // --help was given

    // Whether `flag` was given, as a switch or with a value.
    bool has(std::string_view flag) const;
    // The value given for `flag` (parse_arguments refuses a flag given twice unless it repeats).
    std::optional<std::string> value(std::string_view flag) const;
    // Every value given for a flag that repeats.
    std::vector<std::string> values_of(std::string_view flag) const;
};

// `words` are the words after the command name; a flag is known by its long name ("--output"
// for -o). With --help among them nothing else is checked. Throws InvalidParameter for an
// unknown flag (naming the command's flags) or a flag without its value.
Arguments parse_arguments(const std::vector<std::string>& words, const CommandSpec& spec);

// The command's help: synopsis, description, options, footer.
std::string help_text(const CommandSpec& spec);

// parse_arguments for a command's function: with --help among the words, prints the help to
// `out` and returns none (the command then exits with 0).
std::optional<Arguments> arguments_or_help(const std::vector<std::string>& words,
                                           const CommandSpec& spec, std::ostream& out);

// A number given to `flag`, checked to lie in [lo, hi] (infinite bounds: any finite number); the
// message names the flag, the text and the range with its unit.
double parse_number(std::string_view flag, const std::string& text, double lo, double hi,
                    const std::string& unit = "");
// A whole number in [lo, hi].
long long parse_count(std::string_view flag, const std::string& text, long long lo, long long hi);
// 'text', for messages.
std::string quoted(const std::string& text);

}  // namespace rodsea
