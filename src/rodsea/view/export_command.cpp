#include "rodsea/view/export_command.hpp"

#include <ostream>

namespace rodsea {

const char* const kExportHelp = "rodsea export: not yet\n";

int export_command(const std::vector<std::string>&, std::ostream&, std::ostream& err) {
    err << "rodsea export: not yet\n";
    return 1;
}

}  // namespace rodsea
