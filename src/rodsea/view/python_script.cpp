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

// An installed rodsea (share/rodsea beside its bin/) runs its own scripts and no others: never
// those of a checkout that has moved on or gone. The executable's own path, not the build's
// prefix, places the tree, so that `cmake --install --prefix` anywhere, or a moved tree, works.
std::filesystem::path scripts_folder() {
    if (const char* set = std::getenv("RODSEA_SCRIPTS_DIR"); set != nullptr && *set != '\0')
        return set;
    std::error_code ec;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::filesystem::path installed =
            (executable.parent_path() / RODSEA_INSTALLED_DATA_DIR).lexically_normal();
        if (std::filesystem::is_directory(installed, ec)) return installed / "scripts";
    }
    return RODSEA_SCRIPTS_DIR;
}

}  // namespace

PythonScriptLookup locate_python_script(const std::string& script_name, const std::string& needs) {
    const std::string python = environment_or("RODSEA_PYTHON", "/usr/bin/python3");
    const std::filesystem::path script = scripts_folder() / script_name;
    if (::access(python.c_str(), X_OK) != 0)
        return {std::nullopt, "the Python interpreter " + python +
                                  " is missing or not executable; install it with "
                                  "./scripts/install-deps.sh (Debian's " +
                                  needs + "), or set RODSEA_PYTHON to a Python 3 that has them"};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(script, ec))
        return {std::nullopt, "the script " + script.string() +
                                  " is missing; reinstall rodsea (cmake --install), or set "
                                  "RODSEA_SCRIPTS_DIR to the scripts/ folder of its source tree"};
    return {PythonScript{python, script.string()}, ""};
}

}  // namespace rodsea
