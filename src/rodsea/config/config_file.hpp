#pragma once
// Reading a run's TOML config into a validated RunPlan. The key table in schema.cpp is the one
// source of every key's type, unit, default, range and documentation: parsing, the resolved
// TOML, the commented default config and docs/config.md are all generated from it.
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rodsea/config/run_plan.hpp"

namespace rodsea {

// A config that is not valid TOML. Derives from std::invalid_argument like InvalidParameter:
// both are bad input, not a failure of the program.
class ConfigSyntaxError : public std::invalid_argument {
  public:
    ConfigSyntaxError(const std::string& source, long line, long column,
                      const std::string& description);
    const std::string& source() const { return source_; }
    long line() const { return line_; }
    long column() const { return column_; }

  private:
    std::string source_;
    long line_;
    long column_;
};

// Turns the paper's D_r (rad²/s) into ε (1/mm) for a run at this gap (mm), dt (s) and noise mode
// through the calibration table at `table`: what noise.rotational_diffusion needs. The config layer
// reads no calibration tables itself; calibration_table_lookup() (calibration/) is the one that
// does.
using EpsilonLookup =
    std::function<double(const std::filesystem::path& table, double gap, double dt,
                         physics::NoiseMode mode, double rotational_diffusion)>;

// Throws FileError when the file is missing or unreadable, otherwise as load_config_string.
RunPlan load_config_file(const std::filesystem::path& path, const EpsilonLookup& epsilon = {});

// Parses and validates the whole config before returning: ConfigSyntaxError for bad TOML,
// InvalidParameter (named by the key's full path, e.g. "species[1].length") for anything else.
// `source_name` only labels error messages; it does not enter the plan. A config that gives
// noise.rotational_diffusion needs `epsilon`; a resolved config (which holds ε) never does.
RunPlan load_config_string(std::string_view toml, std::string_view source_name,
                           const EpsilonLookup& epsilon = {});

// The config `toml` (a resolved one, as a run stores it) with a new run length: time.duration
// (s; time.periods dropped) and time.steady_samples, each only if given; validated as any config
// (InvalidParameter named time.duration or time.steady_samples).
RunPlan with_run_length(std::string_view toml, std::string_view source_name,
                        std::optional<double> duration, std::optional<long long> steady_samples);

// The config `toml` run on `threads` threads (run.threads; InvalidParameter outside its range).
RunPlan with_threads(std::string_view toml, std::string_view source_name, int threads);
// The config `toml` stepped by `backend` (run.backend).
RunPlan with_backend(std::string_view toml, std::string_view source_name, BackendKind backend);

// The resolved config `toml` with run.seed set to 0: equal for two runs exactly when their
// configs differ at most in the seed (replicates of one state point).
std::string config_without_seed(std::string_view toml);

// A complete config with every key at its default, each commented with its unit and range.
std::string default_config_toml();

// The content of docs/config.md: one table per section of the config.
std::string config_reference_markdown();

}  // namespace rodsea
