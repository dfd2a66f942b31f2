#pragma once
// Frames handed to an ffmpeg child process through a pipe and encoded as H.264 in an MP4 that
// browsers play (yuv420p, +faststart). ffmpeg's messages go to a log that is quoted when it
// fails; the child is killed and reaped if the encoder is abandoned.
#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "rodsea/view/frame_renderer.hpp"

namespace rodsea {

// $RODSEA_FFMPEG if set, otherwise `ffmpeg` on PATH; none when it cannot be found.
std::optional<std::filesystem::path> find_ffmpeg();

struct VideoSettings {
    int width = 0, height = 0;  // pixels, both even
    double fps = 20.0;
    int crf = 20;  // x264 quality: 0 lossless … 51 worst; 18–23 look clean for these pictures
};

class FfmpegEncoder {
  public:
    // Starts ffmpeg writing `output` (an .mp4 path; messages name `shown_as`, the file the user
    // asked for). `stop_signal` is polled while waiting on ffmpeg: when it returns a signal
    // number, ffmpeg is stopped and StopRequested thrown. Throws FileError if ffmpeg cannot start.
    FfmpegEncoder(const std::filesystem::path& ffmpeg, const std::filesystem::path& output,
                  const std::filesystem::path& shown_as, const VideoSettings& settings,
                  std::function<int()> stop_signal);
    ~FfmpegEncoder();
    FfmpegEncoder(const FfmpegEncoder&) = delete;
    FfmpegEncoder& operator=(const FfmpegEncoder&) = delete;

    // Throws FileError quoting ffmpeg's log if it has stopped reading.
    void write_frame(const Image& image);
    // Closes the pipe and waits; throws FileError quoting the log unless ffmpeg succeeded.
    void finish();

  private:
    [[noreturn]] void fail(const std::string& what);
    void check_stop();  // throws StopRequested after stopping ffmpeg
    void stop_child();

    std::filesystem::path shown_as_;
    int log_fd_ = -1;  // ffmpeg's stdout and stderr, kept in memory (memfd)
    VideoSettings settings_;
    std::function<int()> stop_signal_;
    pid_t child_ = -1;
    int pipe_ = -1;
    void (*previous_sigpipe_)(int) = nullptr;
};

}  // namespace rodsea
