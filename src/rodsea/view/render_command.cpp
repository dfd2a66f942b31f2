#include "rodsea/view/render_command.hpp"

#include <ostream>

namespace rodsea {

const char* const kRenderHelp = "rodsea render: not yet\n";

int render_command(const std::vector<std::string>&, std::ostream&, std::ostream& err) {
    err << "rodsea render: not yet\n";
    return 1;
}

}  // namespace rodsea
