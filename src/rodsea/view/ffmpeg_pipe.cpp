#include "rodsea/view/detail/ffmpeg_pipe.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "rodsea/cli/stop_signal.hpp"
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
                             const fs::path& shown_as, const VideoSettings& settings,
                             std::function<int()> stop_signal)
    : shown_as_(shown_as), settings_(settings), stop_signal_(std::move(stop_signal)) {
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
    // ffmpeg's messages go to memory, not to a file beside the movie: on a full disk a log
    // file stays empty, and its error ("No space left on device") is what the user needs.
    const int log_fd = ::memfd_create("rodsea-ffmpeg-log", MFD_CLOEXEC);
    if (log_fd < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw FileError("ffmpeg", std::string("cannot keep its log: ") + std::strerror(errno));
    }
    child_ = ::fork();
    if (child_ == 0) {
        // Its own process group: Ctrl-C stops rodsea, which then stops ffmpeg and removes the
        // unfinished file, instead of ffmpeg closing a half movie on its own.
        ::setpgid(0, 0);
        // ... and it dies with rodsea, so that a second Ctrl-C (which kills rodsea at once)
        // does not leave it finishing a movie nobody will rename into place.
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        ::dup2(fds[0], STDIN_FILENO);
        ::dup2(log_fd, STDOUT_FILENO);
        ::dup2(log_fd, STDERR_FILENO);
        ::close(fds[0]);
        ::close(fds[1]);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(fds[0]);
    log_fd_ = log_fd;
    if (child_ < 0) {
        ::close(fds[1]);
        throw FileError(ffmpeg.string(), "cannot start ffmpeg (fork failed)");
    }
    pipe_ = fds[1];
    ::fcntl(pipe_, F_SETFL, ::fcntl(pipe_, F_GETFL) | O_NONBLOCK);
    // A dead ffmpeg must show up as a failed write, not kill rodsea with SIGPIPE.
    previous_sigpipe_ = ::signal(SIGPIPE, SIG_IGN);
}

FfmpegEncoder::~FfmpegEncoder() {
    stop_child();
    if (log_fd_ >= 0) ::close(log_fd_);
    ::signal(SIGPIPE, previous_sigpipe_);
}

void FfmpegEncoder::stop_child() {
    if (pipe_ >= 0) ::close(pipe_);
    pipe_ = -1;
    if (child_ > 0) {
        // Its output is a temporary file about to be removed: nothing to let it finish.
        ::kill(child_, SIGKILL);
        int status = 0;
        ::waitpid(child_, &status, 0);
    }
    child_ = -1;
}

void FfmpegEncoder::fail(const std::string& what) {
    stop_child();
    std::string tail;
    char buffer[4096];
    ssize_t n = 0;
    ::lseek(log_fd_, 0, SEEK_SET);
    while ((n = ::read(log_fd_, buffer, sizeof buffer)) > 0)
        tail.append(buffer, static_cast<std::size_t>(n));
    if (tail.size() > 2000) tail = "…" + tail.substr(tail.size() - 2000);
    throw FileError(shown_as_.string(), what + (tail.empty() ? "" : "; ffmpeg said:\n" + tail));
}

void FfmpegEncoder::check_stop() {
    if (const int signal = stop_signal_ ? stop_signal_() : 0) {
        stop_child();
        throw StopRequested{signal};
    }
}

void FfmpegEncoder::write_frame(const Image& image) {
    if (image.width != settings_.width || image.height != settings_.height)
        fail("a frame of the wrong size reached the encoder");
    const auto* data = reinterpret_cast<const char*>(image.pixels.data());
    std::size_t left = image.pixels.size() * sizeof(std::uint32_t);
    // The pipe is non-blocking and polled in short waits: a frame is megabytes and ffmpeg may
    // be slow to take it, and a stop signal must not wait for that.
    while (left > 0) {
        check_stop();
        pollfd ready{pipe_, POLLOUT, 0};
        if (::poll(&ready, 1, 50) <= 0) continue;
        const ssize_t n = ::write(pipe_, data, left);
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n <= 0) fail("ffmpeg stopped reading frames");
        data += n;
        left -= static_cast<std::size_t>(n);
    }
}

void FfmpegEncoder::finish() {
    ::close(pipe_);
    pipe_ = -1;
    // ffmpeg flushes its encoder after the last frame, which takes seconds for big movies:
    // poll, so that a stop signal in that time still stops it.
    int status = 0;
    pid_t done = 0;
    while ((done = ::waitpid(child_, &status, WNOHANG)) == 0 || (done < 0 && errno == EINTR)) {
        check_stop();
        ::usleep(20000);
    }
    child_ = -1;
    if (done < 0) fail("lost track of ffmpeg (waitpid failed)");
    if (WIFSIGNALED(status))
        fail("ffmpeg was killed by signal " + std::to_string(WTERMSIG(status)));
    if (WEXITSTATUS(status) == 127) fail("ffmpeg could not be started");
    if (WEXITSTATUS(status) != 0)
        fail("ffmpeg failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
}

}  // namespace rodsea
