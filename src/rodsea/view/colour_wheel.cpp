#include "rodsea/view/colour_wheel.hpp"
