#include "rodsea/view/python_script.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace rodsea {

namespace {

std::string environment_or(const char* name, const char* fallback) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0' ? std::string(value) : std::string(fallback);
}

}  // namespace

PythonScriptLookup locate_python_script(const std::string& script_name, const std::string& needs) {
    const std::string python = environment_or("RODSEA_PYTHON", "/usr/bin/python3");
    const std::filesystem::path script =
        std::filesystem::path(environment_or("RODSEA_SCRIPTS_DIR", RODSEA_SCRIPTS_DIR)) /
        script_name;
    if (::access(python.c_str(), X_OK) != 0)
        return {std::nullopt, "the Python interpreter " + python +
                                  " is missing or not executable; install it with "
                                  "./scripts/install-deps.sh (Debian's " +
                                  needs + "), or set RODSEA_PYTHON to a Python 3 that has them"};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(script, ec))
        return {std::nullopt, "the script " + script.string() +
                                  " is missing; set RODSEA_SCRIPTS_DIR to the scripts/ folder of "
                                  "the rodsea source tree"};
    return {PythonScript{python, script.string()}, ""};
}

}  // namespace rodsea
