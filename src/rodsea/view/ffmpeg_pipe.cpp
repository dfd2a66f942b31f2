#include "rodsea/view/ffmpeg_pipe.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "rodsea/error.hpp"

namespace rodsea {

namespace fs = std::filesystem;

std::optional<fs::path> find_ffmpeg() {
    if (const char* explicit_path = std::getenv("RODSEA_FFMPEG")) {
        if (::access(explicit_path, X_OK) == 0) return fs::path(explicit_path);
        return std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / "ffmpeg";
        if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate))
            return candidate;
    }
    return std::nullopt;
}

FfmpegEncoder::FfmpegEncoder(const fs::path& ffmpeg, const fs::path& output,
                             const VideoSettings& settings)
    : output_(output), log_(output.string() + ".ffmpeg.log"), settings_(settings) {
    const std::string size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
    const std::string fps = format_number(settings.fps);
    // Cairo's ARGB32 is B, G, R, A in memory on little-endian machines: ffmpeg's bgra.
    const std::vector<std::string> args{ffmpeg.string(),
                                        "-hide_banner",
                                        "-nostdin",
                                        "-loglevel",
                                        "error",
                                        "-y",
                                        "-f",
                                        "rawvideo",
                                        "-pix_fmt",
                                        "bgra",
                                        "-s",
                                        size,
                                        "-framerate",
                                        fps,
                                        "-i",
                                        "pipe:0",
                                        "-c:v",
                                        "libx264",
                                        "-preset",
                                        "medium",
                                        "-crf",
                                        std::to_string(settings.crf),
                                        "-pix_fmt",
                                        "yuv420p",
                                        "-movflags",
                                        "+faststart",
                                        "-f",
                                        "mp4",
                                        output.string()};
    std::vector<char*> argv;
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);

    int fds[2];
    if (::pipe(fds) != 0) throw FileError(ffmpeg.string(), "cannot create a pipe to ffmpeg");
    const int log_fd = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log_fd < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw FileError(log_.string(), std::string("cannot write: ") + std::strerror(errno));
    }
    child_ = ::fork();
    if (child_ == 0) {
        // Its own process group: Ctrl-C stops rodsea, which then stops ffmpeg and removes the
        // unfinished file, instead of ffmpeg closing a half movie on its own.
        ::setpgid(0, 0);
        ::dup2(fds[0], STDIN_FILENO);
        ::dup2(log_fd, STDOUT_FILENO);
        ::dup2(log_fd, STDERR_FILENO);
        ::close(fds[0]);
        ::close(fds[1]);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(fds[0]);
    ::close(log_fd);
    if (child_ < 0) {
        ::close(fds[1]);
        fs::remove(log_);
        throw FileError(ffmpeg.string(), "cannot start ffmpeg (fork failed)");
    }
    pipe_ = fds[1];
    // A dead ffmpeg must show up as a failed write, not kill rodsea with SIGPIPE.
    previous_sigpipe_ = ::signal(SIGPIPE, SIG_IGN);
}

FfmpegEncoder::~FfmpegEncoder() {
    stop_child();
    std::error_code ignored;
    fs::remove(log_, ignored);
    ::signal(SIGPIPE, previous_sigpipe_);
}

void FfmpegEncoder::stop_child() {
    if (pipe_ >= 0) ::close(pipe_);
    pipe_ = -1;
    if (child_ > 0) {
        ::kill(child_, SIGTERM);
        int status = 0;
        ::waitpid(child_, &status, 0);
    }
    child_ = -1;
}

void FfmpegEncoder::fail(const std::string& what) {
    stop_child();
    std::ifstream in(log_);
    std::stringstream log;
    log << in.rdbuf();
    std::string tail = log.str();
    if (tail.size() > 2000) tail = "…" + tail.substr(tail.size() - 2000);
    throw FileError(output_.string(), what + (tail.empty() ? "" : "; ffmpeg said:\n" + tail));
}

void FfmpegEncoder::write_frame(const Image& image) {
    if (image.width != settings_.width || image.height != settings_.height)
        fail("a frame of the wrong size reached the encoder");
    const auto* data = reinterpret_cast<const char*>(image.pixels.data());
    std::size_t left = image.pixels.size() * sizeof(std::uint32_t);
    while (left > 0) {
        const ssize_t n = ::write(pipe_, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail("ffmpeg stopped reading frames");
        data += n;
        left -= static_cast<std::size_t>(n);
    }
}

void FfmpegEncoder::finish() {
    ::close(pipe_);
    pipe_ = -1;
    int status = 0;
    while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
    child_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        fail(WIFEXITED(status) && WEXITSTATUS(status) == 127
                 ? "ffmpeg could not be started"
                 : "ffmpeg failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
}

}  // namespace rodsea
