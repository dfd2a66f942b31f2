#include "rodsea/view/detail/frame_flags.hpp"

namespace rodsea {

namespace {

// Times are checked against the run's span by the selection; this only keeps them finite.
constexpr double kAnyTime = 1e12;

std::optional<double> time_flag(const Arguments& args, const char* flag) {
    if (const auto text = args.value(flag))
        return parse_number(flag, *text, -kAnyTime, kAnyTime, "s");
    return std::nullopt;
}

}  // namespace

const std::vector<std::string> kFrameWindowFlags{"--from", "--to", "--every"};

std::optional<std::size_t> single_frame_from(const Arguments& args, const StoredRun& run) {
    std::optional<long long> frame;
    if (const auto text = args.value("--frame"))
        frame = parse_count("--frame", *text, -(1LL << 40), 1LL << 40);
    const std::optional<double> time = time_flag(args, "--time");
    if (!frame && !time) return std::nullopt;
    return select_frame(run, frame, time);
}

std::vector<std::size_t> frame_window_from(const Arguments& args, const StoredRun& run) {
    const long long every =
        parse_count("--every", args.value("--every").value_or("1"), 1, 1LL << 40);
    return select_frame_window(run, time_flag(args, "--from"), time_flag(args, "--to"), every);
}

}  // namespace rodsea
