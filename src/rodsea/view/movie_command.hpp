#pragma once
// `rodsea movie`: see kMovieHelp and docs/visualisation.md.
#include <iosfwd>
#include <string>
#include <vector>

namespace rodsea {

extern const char* const kMovieHelp;

// `args` are the words after `rodsea movie`. Checks all input before writing anything; throws
// InvalidParameter (exit 2) or FileError (exit 74); returns the exit code otherwise.
int movie_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
