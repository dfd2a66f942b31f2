#include "rodsea/view/plot_command.hpp"

#include <ostream>

namespace rodsea {

const char* const kPlotHelp = "rodsea plot: not yet\n";

int plot_command(const std::vector<std::string>&, std::ostream&, std::ostream& err) {
    err << "rodsea plot: not yet\n";
    return 1;
}

}  // namespace rodsea
