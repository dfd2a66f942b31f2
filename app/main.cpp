// rodsea: command-line entry. One table of commands drives dispatch, `rodsea --help`,
// `rodsea help COMMAND` and the message for an unknown command. Each command parses its words
// through cli/arguments.hpp, checks its whole input, says what it will do, then does it.
#include <csignal>

#include <iostream>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "rodsea/analyze/analyze_command.hpp"
#include "rodsea/calibration/calibrate_command.hpp"
#include "rodsea/campaign/campaign_command.hpp"
#include "rodsea/cli/arguments.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/config/config_command.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/error.hpp"
#include "rodsea/meanfield/mean_field.hpp"
#include "rodsea/run/run_command.hpp"
#include "rodsea/view/export_command.hpp"
#include "rodsea/view/movie_command.hpp"
#include "rodsea/view/plot_command.hpp"
#include "rodsea/view/render_command.hpp"

namespace {

using rodsea::CommandSpec;
using rodsea::ExitCode;

using CommandFunction = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

struct Command {
    const CommandSpec& (*spec)();
    CommandFunction run;
};

int meanfield(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    return rodsea::meanfield_command(words, out);
}

int analyze(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    return rodsea::analyze_command(words, out, out);
}

const std::vector<Command>& commands() {
    static const std::vector<Command> table{
        {rodsea::run_command_spec, rodsea::run_command},
        {rodsea::info_command_spec, rodsea::info_command},
        {rodsea::config_command_spec, rodsea::config_command},
        {rodsea::analyze_command_spec, analyze},
        {rodsea::meanfield_command_spec, meanfield},
        {rodsea::calibrate_command_spec, rodsea::calibrate_command},
        {rodsea::campaign_command_spec, rodsea::campaign_command},
        {rodsea::render_command_spec, rodsea::render_command},
        {rodsea::movie_command_spec, rodsea::movie_command},
        {rodsea::plot_command_spec, rodsea::plot_command},
        {rodsea::export_command_spec, rodsea::export_command},
    };
    return table;
}

const Command* find(std::string_view name) {
    for (const Command& c : commands())
        if (c.spec().name == name) return &c;
    return nullptr;
}

std::string usage() {
    std::string s =
        "rodsea — vibrated granular rods: polar rods in a sea of apolar rods or beads\n\n"
        "usage: rodsea COMMAND [OPTIONS]   (rodsea help COMMAND, or COMMAND --help, for each)\n\n";
    for (const Command& c : commands()) {
        const CommandSpec& spec = c.spec();
        s += "  " + spec.name + std::string(12 - std::min<std::size_t>(11, spec.name.size()), ' ') +
             spec.summary + "\n";
    }
    s += R"(  help        rodsea help COMMAND: that command's options
  --version   the version

Units everywhere: mm, s (and rad, Hz); masses in an arbitrary unit. Examples: examples/*.toml.
Exit codes: 0 done; 1 unexpected failure; 2 bad input (nothing done); 3 the simulation blew
up (a checkpoint of the last good frame; the message says what to change); 74 a file could not
be read or written (a run in progress keeps its last checkpoint; the message says what to do);
130/143 stopped by SIGINT/SIGTERM/SIGHUP (a checkpoint was written).
)";
    return s;
}

int unknown_command(std::string_view name) {
    std::vector<std::string> names;
    for (const Command& c : commands())
        names.push_back(c.spec().name);
    names.insert(names.end(), {"help", "--help", "--version"});
    std::string list;
    for (const std::string& n : names)
        list += (list.empty() ? "" : ", ") + n;
    std::cerr << "rodsea: unknown command '" << name << "' (commands: " << list;
    if (const auto match = rodsea::config::closest_match(name, names))
        std::cerr << "; did you mean '" << *match << "'?";
    std::cerr << ")\n";
    return ExitCode::kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
    // Output piped into `head` or a closed terminal must not kill a command halfway through a
    // file it is writing: a failed write to stdout is harmless, a half-written output is not.
    std::signal(SIGPIPE, SIG_IGN);
    const std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h") {
        std::cout << usage();
        return words.empty() ? ExitCode::kExitBadInput : ExitCode::kExitOk;
    }
    if (words[0] == "--version") {
        std::cout << "rodsea " << RODSEA_VERSION << "\n";
        return ExitCode::kExitOk;
    }
    if (words[0] == "help") {
        if (words.size() < 2) {
            std::cout << usage();
            return ExitCode::kExitOk;
        }
        const Command* c = find(words[1]);
        if (!c) return unknown_command(words[1]);
        std::cout << rodsea::help_text(c->spec());
        return ExitCode::kExitOk;
    }
    const Command* command = find(words[0]);
    if (!command) return unknown_command(words[0]);
    try {
        return command->run({words.begin() + 1, words.end()}, std::cout, std::cerr);
    } catch (const std::invalid_argument& e) {  // InvalidParameter, ConfigSyntaxError
        std::cerr << "rodsea: " << e.what() << "\n";
        return ExitCode::kExitBadInput;
    } catch (const rodsea::FileError& e) {
        std::cerr << "rodsea: " << e.what() << "\n";
        return ExitCode::kExitIoError;
    } catch (const std::bad_alloc&) {
        std::cerr << "rodsea: out of memory: this command needs more memory than the machine (or "
                     "the job's limit, ulimit -v) gives it; `rodsea info CONFIG` says what a run "
                     "needs\n";
        return ExitCode::kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "rodsea: " << e.what() << "\n";
        return ExitCode::kExitFailure;
    }
}
