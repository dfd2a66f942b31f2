#pragma once
// Running another program (Python for `rodsea plot`, sbatch and squeue for `rodsea campaign
// submit`): no shell, its standard output and error passed to two streams as they come.
#include <iosfwd>
#include <string>
#include <vector>

namespace rodsea {

// Runs `argv` (argv[0] a path, or a name looked up on PATH) and returns its exit code, or
// 128 + the signal that ended it. When it cannot be started at all, "rodsea: <argv[0]> could
// not be started" goes to `err` and the code is `exec_failure`. Throws FileError when no pipe
// or process can be made.
int run_program(std::vector<std::string> argv, std::ostream& out, std::ostream& err,
                int exec_failure = 127);

}  // namespace rodsea
