#include "rodsea/config/config_command.hpp"

#include <optional>
#include <ostream>

#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

const CommandSpec& config_command_spec() {
    static const CommandSpec spec{
        "config",
        "--defaults | --reference",
        "a complete default config, or the key reference",
        "",
        {{"--defaults", "",
          "print a complete config with every key at its default (commented with unit and "
          "allowed range): a starting point for your own"},
         {"--reference", "", "print the key reference in Markdown (this is docs/config.md)"}},
        ""};
    return spec;
}

int config_command(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    const std::optional<Arguments> parsed = arguments_or_help(words, config_command_spec(), out);
    if (!parsed) return kExitOk;
    const Arguments& a = *parsed;
    if (!a.positional.empty())
        throw InvalidParameter(a.positional[0], "an unexpected argument",
                               "--defaults or --reference");
    if (a.has("--defaults") == a.has("--reference"))
        throw InvalidParameter("rodsea config", a.has("--defaults") ? "both" : "neither",
                               "exactly one of --defaults and --reference");
    out << (a.has("--defaults") ? default_config_toml() : config_reference_markdown());
    return kExitOk;
}

}  // namespace rodsea
