#include "rodsea/config/config_file.hpp"
#include "rodsea/text_file.hpp"

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
    return load_config_string(read_text_file(path), path.string(), epsilon);
}

RunPlan load_config_string(std::string_view toml, std::string_view source_name,
                           const EpsilonLookup& epsilon) {
    config::ConfigValues values = config::read_toml(toml, source_name);
    RunPlan plan = config::resolve(values, epsilon);
    plan.config_toml = config::write_toml(values);
    plan.choices = config::list_choices(values, plan);
    return plan;
}

namespace {

// The stored config `toml` with one table's entries edited, resolved and validated again.
RunPlan replanned(std::string_view toml, std::string_view source_name, std::string_view table,
                  const std::function<void(config::TableValues&)>& edit) {
    config::ConfigValues values = config::read_toml(toml, source_name);
    std::vector<config::TableValues>& t = values.all(table);
    if (t.empty()) t.push_back({std::string(table), 0, {}});
    edit(t.front());
    RunPlan plan = config::resolve(values, {});
    plan.config_toml = config::write_toml(values);
    plan.choices = config::list_choices(values, plan);
    return plan;
}

}  // namespace

RunPlan with_run_length(std::string_view toml, std::string_view source_name,
                        std::optional<double> duration, std::optional<long long> steady_samples) {
    return replanned(toml, source_name, "time", [&](config::TableValues& time) {
        if (duration) {
            time.entries.erase("periods");
            time.entries["duration"] = {*duration, 0};
        }
        if (steady_samples)
            time.entries["steady_samples"] = {static_cast<std::int64_t>(*steady_samples), 0};
    });
}

RunPlan with_threads(std::string_view toml, std::string_view source_name, int threads) {
    return replanned(toml, source_name, "run", [&](config::TableValues& run) {
        run.entries["threads"] = {std::int64_t{threads}, 0};
    });
}

RunPlan with_backend(std::string_view toml, std::string_view source_name, BackendKind backend) {
    return replanned(toml, source_name, "run", [&](config::TableValues& run) {
        run.entries["backend"] = {std::string(to_string(backend)), 0};
    });
}

std::string config_without_seed(std::string_view toml) {
    return replanned(toml, "stored config", "run",
                     [](config::TableValues& run) {
                         run.entries["seed"] = {std::int64_t{0}, 0};
                     })
        .config_toml;
}

std::string default_config_toml() {
    // The resolved empty config is every key at its default, commented.
    return load_config_string("", "defaults").config_toml;
}

}  // namespace rodsea
