#include "rodsea/view/export_formats.hpp"
