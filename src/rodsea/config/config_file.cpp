#include "rodsea/config/config_file.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include "rodsea/config/detail/choices.hpp"
#include "rodsea/config/detail/read_toml.hpp"
#include "rodsea/config/detail/resolve.hpp"
#include "rodsea/config/detail/write_toml.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

ConfigSyntaxError::ConfigSyntaxError(const std::string& source, long line, long column,
                                     const std::string& description)
    : std::invalid_argument(source + " line " + std::to_string(line) + ", column " +
                            std::to_string(column) + ": TOML syntax error: " + description),
      source_(source),
      line_(line),
      column_(column) {}

RunPlan load_config_file(const std::filesystem::path& path, const EpsilonLookup& epsilon) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw FileError(path.string(), "no such file");
    if (std::filesystem::is_directory(path, ec))
        throw FileError(path.string(), "is a directory, not a config file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path.string(), "cannot be opened for reading");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw FileError(path.string(), "read failed");
    return load_config_string(text.str(), path.string(), epsilon);
}

RunPlan load_config_string(std::string_view toml, std::string_view source_name,
                           const EpsilonLookup& epsilon) {
    config::ConfigValues values = config::read_toml(toml, source_name);
    RunPlan plan = config::resolve(values, epsilon);
    plan.config_toml = config::write_toml(values);
    plan.choices = config::list_choices(values, plan);
    return plan;
}

RunPlan with_run_length(std::string_view toml, std::string_view source_name,
                        std::optional<double> duration, std::optional<long long> steady_samples) {
    config::ConfigValues values = config::read_toml(toml, source_name);
    std::vector<config::TableValues>& time = values.all("time");
    if (time.empty()) time.push_back({"time", 0, {}});
    if (duration) {
        time.front().entries.erase("periods");
        time.front().entries["duration"] = {*duration, 0};
    }
    if (steady_samples)
        time.front().entries["steady_samples"] = {static_cast<std::int64_t>(*steady_samples), 0};
    RunPlan plan = config::resolve(values, {});
    plan.config_toml = config::write_toml(values);
    plan.choices = config::list_choices(values, plan);
    return plan;
}

std::string config_without_seed(std::string_view toml) {
    config::ConfigValues values = config::read_toml(toml, "stored config");
    std::vector<config::TableValues>& run = values.all("run");
    if (run.empty()) run.push_back({"run", 0, {}});
    run.front().entries["seed"] = {std::int64_t{0}, 0};
    config::resolve(values, {});
    return config::write_toml(values);
}

std::string default_config_toml() {
    // The resolved empty config is every key at its default, commented.
    return load_config_string("", "defaults").config_toml;
}

}  // namespace rodsea
