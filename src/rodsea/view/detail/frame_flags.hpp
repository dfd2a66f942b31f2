#pragma once
// The frame-choosing flags of the read-side commands, parsed one way for all of them:
// --frame N / --time T pick one frame; --from T / --to T / --every K a window of frames.
#include <optional>
#include <vector>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/io/stored_run.hpp"

namespace rodsea {

extern const std::vector<std::string> kFrameWindowFlags;  // --from --to --every

// The frame --frame or --time names, or none when neither is given. Throws InvalidParameter
// naming the flag and the run's range.
std::optional<std::size_t> single_frame_from(const Arguments& args, const StoredRun& run);

// The frames of --from/--to (default: the whole run), every --every-th of them.
std::vector<std::size_t> frame_window_from(const Arguments& args, const StoredRun& run);

}  // namespace rodsea
