#include "rodsea/view/movie_command.hpp"

#include <ostream>

namespace rodsea {

const char* const kMovieHelp = "rodsea movie: not yet\n";

int movie_command(const std::vector<std::string>&, std::ostream&, std::ostream& err) {
    err << "rodsea movie: not yet\n";
    return 1;
}

}  // namespace rodsea
