#pragma once
// PNG output of rendered images, written atomically: a reader never sees half a picture, and a
// failed write leaves no file behind.
#include <filesystem>

#include "rodsea/view/frame_renderer.hpp"

namespace rodsea {

// Throws FileError naming `path` when it cannot be written.
void write_png(const Image& image, const std::filesystem::path& path);

// Reads a PNG back into the same layout (tests and tools). Throws FileError.
Image read_png(const std::filesystem::path& path);

}  // namespace rodsea
