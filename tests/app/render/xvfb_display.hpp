// Starts a private Xvfb server for GUI tests and points DISPLAY at it.
#pragma once

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <cstdlib>
#include <poll.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace handover::render::test {

/// Xvfb picks a free display number itself (-displayfd), so parallel test
/// runs by several developers never collide. `error()` is empty on success.
class XvfbDisplay {
 public:
  XvfbDisplay() {
    int fds[2];
    if (pipe(fds) != 0) {
      error_ = "pipe failed";
      return;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 3);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    char* argv[] = {const_cast<char*>("Xvfb"), const_cast<char*>("-displayfd"), const_cast<char*>("3"),
                    const_cast<char*>("-screen"), const_cast<char*>("0"),
                    const_cast<char*>("1024x768x24"), const_cast<char*>("-nolisten"),
                    const_cast<char*>("tcp"), nullptr};
    const int err = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (err != 0) {
      close(fds[0]);
      pid_ = -1;
      missing_ = (err == ENOENT);
      error_ = missing_ ? "Xvfb is not installed (apt-get install xvfb)" : "cannot start Xvfb";
      return;
    }
    // Xvfb writes "N\n" once it accepts connections
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    while (poll(&p, 1, 15000) > 0) {
      char c;
      if (read(fds[0], &c, 1) != 1 || c == '\n') break;
      number += c;
    }
    close(fds[0]);
    if (number.empty()) {
      error_ = "Xvfb did not report a display within 15 s";
      return;
    }
    const char* old = std::getenv("DISPLAY");
    had_display_ = old != nullptr;
    if (old) old_display_ = old;
    setenv("DISPLAY", (":" + number).c_str(), 1);
    set_display_ = true;
  }
  ~XvfbDisplay() {
    if (set_display_) {
      if (had_display_) setenv("DISPLAY", old_display_.c_str(), 1);
      else unsetenv("DISPLAY");
    }
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      int status;
      waitpid(pid_, &status, 0);
    }
  }
  const std::string& error() const { return error_; }
  bool missing() const { return missing_; }

 private:
  pid_t pid_ = -1;
  bool missing_ = false;
  bool had_display_ = false;
  bool set_display_ = false;
  std::string old_display_;
  std::string error_;
};

}  // namespace handover::render::test
