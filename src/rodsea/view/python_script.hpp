#pragma once
// The Python programs rodsea runs (rodsea plot's figures, rodsea export's GSD writer): Debian's
// /usr/bin/python3 (env RODSEA_PYTHON overrides) on a script in the scripts' folder: env
// RODSEA_SCRIPTS_DIR, else an installed rodsea's share/rodsea/scripts beside its bin/, else the
// source tree's scripts/ that it was built from.
#include <optional>
#include <string>

namespace rodsea {

struct PythonScript {
    std::string python;
    std::string script;
};

// The interpreter and the script, or the reason they cannot run (a missing interpreter names
// the Debian packages `needs` lists and the install script).
struct PythonScriptLookup {
    std::optional<PythonScript> found;
    std::string problem;
};
PythonScriptLookup locate_python_script(const std::string& script_name, const std::string& needs);

}  // namespace rodsea
