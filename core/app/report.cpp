#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "granpipe/plugin_loader.hpp"

extern char** environ;

namespace granpipe::app {
namespace fs = std::filesystem;

namespace {

// The report is drawn by matplotlib (the project's figures come from a plotting library,
// never from code of our own), so it is a Python script, installed beside the plugins'
// tree: <prefix>/share/granpipe/report.py, which the build tree mirrors.
fs::path report_script() {
  const fs::path bin = executable_dir();
  return bin.empty() ? fs::path() : bin.parent_path() / "share" / "granpipe" / "report.py";
}

}  // namespace

ReportOutcome write_report(const fs::path& run_dir) {
  const fs::path script = report_script();
  if (script.empty() || !fs::is_regular_file(script))
    return {false, "report.html not written: " + script.string() + " is missing"};
  // The configured interpreter, else whichever python3 the PATH finds.
  std::string python = fs::exists(GRANPIPE_REPORT_PYTHON) ? GRANPIPE_REPORT_PYTHON : "python3";
  std::string script_arg = script.string(), dir_arg = run_dir.string();
  std::vector<char*> argv{python.data(), script_arg.data(), dir_arg.data(), nullptr};
  pid_t pid = 0;
  if (const int error = posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ))
    return {false, "report.html not written: cannot start " + python + ": " + std::strerror(error)};
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return {false, "report.html not written: lost the report's process"};
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {true, ""};
  // A crash inside a library (HDF5 on a corrupt file) prints nothing of its own.
  if (WIFSIGNALED(status)) {
    return {false, "report.html not written: " + script.string() + " was stopped by signal " +
                       std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")"};
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return {false,
          "report.html not written: " + script.string() + " failed (exit " + std::to_string(code) +
              "; its message is above)",
          code == 2};
}

}  // namespace granpipe::app
