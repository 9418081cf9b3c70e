#include "app/plot_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

namespace handover::app {

int drawPlots(const std::string& dir, bool quiet) { return runPlotScript("plot_run.py", dir, quiet); }

int drawReportPlot(const std::string& dir, bool quiet) { return runPlotScript("plot_report.py", dir, quiet); }

int runPlotScript(const std::string& name, const std::string& dir, bool quiet) {
  const std::string script = std::string(HANDOVER_SOURCE_DIR) + "/scripts/" + name;
  const char* python = access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (quiet) {
      const int devnull = open("/dev/null", O_WRONLY);
      if (devnull >= 0) dup2(devnull, STDOUT_FILENO);
    }
    execlp(python, python, script.c_str(), dir.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 127;
}

}  // namespace handover::app
