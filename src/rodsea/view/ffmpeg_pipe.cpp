#include "rodsea/view/ffmpeg_pipe.hpp"
