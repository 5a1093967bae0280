#pragma once
// The plots of `acdplan bench` / `bench-merge`: tools/plot_bench.py (python3 + matplotlib) run
// on an output folder. The command line decides to plot; the bench library never runs a
// program.

#include <iosfwd>
#include <string>
#include <vector>

namespace acdplan::tools {

/// The running executable's path (/proc/self/exe); "" if it cannot be read.
std::string SelfExecutable();

/// The plot script: `env_script` ($ACDPLAN_PLOT_BENCH) if not empty (even if it does not exist,
/// so a wrong setting is reported, not silently replaced); else the first existing of
/// <exe dir>/plot_bench.py (the copy the build puts next to the built executable) and
/// <exe dir>/../share/acdplan/plot_bench.py (installed); "" if none exists.
std::string FindPlotBenchScript(const std::string& executable, const std::string& env_script);

/// Runs `argv` (argv[0] looked up in PATH) with fork/execvp, its output to `quiet` ? /dev/null
/// : ours; waits for it. Returns its exit status, 127 if it could not be started, 128 + n if
/// signal n ended it.
int RunProgram(const std::vector<std::string>& argv, bool quiet);

/// The Python interpreter for the plots: `env_python` ($ACDPLAN_PYTHON) if not empty, else the
/// first of PATH's python3 and /usr/bin/python3 that imports matplotlib; "" if neither does.
std::string FindPlotPython(const std::string& env_python);

/// Plots the output folder `dir` with the script FindPlotBenchScript() finds and the
/// interpreter FindPlotPython() finds, and
/// says on `log` what it did or why it could not (no script, no matplotlib, script failed).
void PlotBench(const std::string& dir, std::ostream* log);

}  // namespace acdplan::tools
