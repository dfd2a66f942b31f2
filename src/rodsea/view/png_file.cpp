#include "rodsea/view/png_file.hpp"
