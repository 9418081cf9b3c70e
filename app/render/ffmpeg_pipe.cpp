#include "app/render/ffmpeg_pipe.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace handover::render {
namespace {

std::string errnoText(int err) { return std::strerror(err); }

std::string formatDouble(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

FfmpegPipe::FfmpegPipe(const FfmpegSettings& settings) : settings_(settings) {
  // stderr capture: an unlinked temp file, close-on-exec in the parent.
  char tmpl[] = "/tmp/handover-ffmpeg-XXXXXX";
  stderr_fd_ = mkostemp(tmpl, O_CLOEXEC);
  if (stderr_fd_ < 0) throw std::runtime_error("cannot create a temp file for ffmpeg's stderr: " + errnoText(errno));
  unlink(tmpl);

  // A socket rather than a pipe: send(MSG_NOSIGNAL) turns a dead reader into
  // EPIPE instead of SIGPIPE. CLOEXEC keeps other children from inheriting it.
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
    ::close(stderr_fd_);
    throw std::runtime_error("cannot create the pipe to ffmpeg: " + errnoText(errno));
  }
  shutdown(fds[0], SHUT_RD);  // parent only writes
  shutdown(fds[1], SHUT_WR);  // child only reads

  const std::string size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
  const std::string rate = formatDouble(settings.fps);
  std::vector<std::string> args = {
      settings.executable, "-hide_banner", "-nostdin", "-loglevel", "error", "-y",
      "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-r", rate, "-i", "pipe:0",
      "-an", "-c:v", "libx264", "-preset", "veryfast", "-crf", std::to_string(settings.crf),
      "-pix_fmt", "yuv420p", "-movflags", "+faststart", settings.path};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 0);
  posix_spawn_file_actions_adddup2(&actions, stderr_fd_, 2);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int err = posix_spawnp(&pid, settings.executable.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (err != 0) {
    ::close(fds[0]);
    ::close(stderr_fd_);
    stderr_fd_ = -1;
    if (err == ENOENT)
      throw std::runtime_error("cannot record video: '" + settings.executable +
                               "' not found on PATH (install ffmpeg, e.g. scripts/setup.sh)");
    throw std::runtime_error("cannot start '" + settings.executable + "': " + errnoText(err));
  }
  pid_ = pid;
  input_fd_ = fds[0];
}

FfmpegPipe::~FfmpegPipe() {
  if (pid_ > 0) finish();
  if (stderr_fd_ >= 0) ::close(stderr_fd_);
}

void FfmpegPipe::write(const unsigned char* rgb, std::size_t bytes) {
  if (pid_ <= 0) throw std::runtime_error("video " + settings_.path + ": write after close");
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t n = send(input_fd_, rgb + done, bytes - done, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      const int code = finish();
      throw std::runtime_error("video " + settings_.path + ": ffmpeg stopped reading frames (" +
                               errnoText(err) + ", exit code " + std::to_string(code) + "): " +
                               stderrTail());
    }
    done += static_cast<std::size_t>(n);
  }
}

void FfmpegPipe::close() {
  if (pid_ <= 0) return;
  const int code = finish();
  if (code != 0)
    throw std::runtime_error("video " + settings_.path + ": ffmpeg failed (exit code " +
                             std::to_string(code) + "): " + stderrTail());
}

int FfmpegPipe::finish() {
  if (input_fd_ >= 0) {
    ::close(input_fd_);
    input_fd_ = -1;
  }
  int status = 0;
  pid_t r;
  do {
    r = waitpid(pid_, &status, 0);
  } while (r < 0 && errno == EINTR);
  pid_ = -1;
  if (r < 0) return -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

std::string FfmpegPipe::stderrTail() const {
  if (stderr_fd_ < 0) return "(no stderr)";
  const off_t end = lseek(stderr_fd_, 0, SEEK_END);
  if (end <= 0) return "(ffmpeg printed nothing)";
  const off_t keep = 800;
  const off_t start = end > keep ? end - keep : 0;
  std::string text(static_cast<std::size_t>(end - start), '\0');
  const ssize_t n = pread(stderr_fd_, text.data(), text.size(), start);
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

}  // namespace handover::render
