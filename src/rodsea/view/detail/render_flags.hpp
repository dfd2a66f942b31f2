#pragma once
// The picture options shared by `rodsea render` and `rodsea movie`, parsed from their flags.
#include <chrono>
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/view/frame_renderer.hpp"

namespace rodsea {

// The picture flags that render_options_from() reads, shared by render and movie; `size_help`
// says each command's default width.
std::vector<OptionSpec> picture_options(const std::string& size_help);

// Throws InvalidParameter naming the flag for an unknown colouring or a malformed number;
// ranges that depend on the run are checked by FrameRenderer.
RenderOptions render_options_from(const Arguments& args, int default_width);

// "polar by direction, medium neutral, 1200×800 px, whole box": for the plan line.
std::string describe(const RenderOptions& options, const FrameRenderer& renderer);

// The closing line of a picture command: "wrote F (t s)", t the wall time since `start`.
void report_written(std::ostream& out, const std::filesystem::path& output,
                    std::chrono::steady_clock::time_point start);

}  // namespace rodsea
