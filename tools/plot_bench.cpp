#include "tools/plot_bench.h"

#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>

namespace acdplan::tools {

std::string SelfExecutable() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? "" : exe.string();
}

std::string FindPlotBenchScript(const std::string& executable, const std::string& env_script) {
  if (!env_script.empty()) return env_script;
  if (executable.empty()) return "";
  const std::filesystem::path dir = std::filesystem::path(executable).parent_path();
  std::error_code ec;
  for (const std::filesystem::path& candidate :
       {dir / "plot_bench.py", dir.parent_path() / "share" / "acdplan" / "plot_bench.py"}) {
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate.string();
  }
  return "";
}

int RunProgram(const std::vector<std::string>& argv, bool quiet) {
  if (argv.empty()) return 127;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (quiet) {
      const int null = open("/dev/null", O_WRONLY);
      if (null >= 0) {
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
        close(null);
      }
    }
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 127;
}

std::string FindPlotPython(const std::string& env_python) {
  if (!env_python.empty()) return env_python;
  // The PATH's python3 may be a user's own (pyenv, a venv) without matplotlib while the
  // system's has it (Debian's python3-matplotlib).
  for (const char* candidate : {"python3", "/usr/bin/python3"}) {
    if (RunProgram({candidate, "-c", "import matplotlib"}, true) == 0) return candidate;
  }
  return "";
}

void PlotBench(const std::string& dir, std::ostream* log) {
  auto say = [&](const std::string& text) {
    if (log) *log << text << "\n";
  };
  const char* env = std::getenv("ACDPLAN_PLOT_BENCH");
  const std::string script = FindPlotBenchScript(SelfExecutable(), env ? env : "");
  std::error_code ec;
  if (script.empty() || !std::filesystem::is_regular_file(script, ec)) {
    say("bench: no plots: " +
        (script.empty() ? std::string("plot_bench.py not found next to the "
                                      "executable or in ../share/acdplan")
                        : "$ACDPLAN_PLOT_BENCH " + script + " does not exist") +
        " (set ACDPLAN_PLOT_BENCH)");
    return;
  }
  const char* env_python = std::getenv("ACDPLAN_PYTHON");
  const std::string python = FindPlotPython(env_python ? env_python : "");
  if (python.empty()) {
    say("bench: no plots: no python3 with matplotlib (PATH's python3, /usr/bin/python3; "
        "Debian: apt-get install python3-matplotlib; or set ACDPLAN_PYTHON); run "
        "tools/plot_bench.py " +
        dir + " later");
    return;
  }
  if (RunProgram({python, script, dir}, false) != 0) {
    say("bench: the plot script failed: " + python + " " + script + " " + dir);
  }
}

}  // namespace acdplan::tools
