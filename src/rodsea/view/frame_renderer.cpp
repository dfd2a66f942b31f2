#include "rodsea/view/frame_renderer.hpp"
