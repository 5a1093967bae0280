// Where `acdplan bench` finds its plot script, and how it starts programs (no shell).

#include "tools/plot_bench.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/data_paths.h"
#include "tests/scratch_dir.h"

namespace acdplan::tools {
namespace {

namespace fs = std::filesystem;

fs::path Scratch(const std::string& name) {
  static const test::ScratchDir root("acdplan_plot_test");  // Removed when the process ends.
  const fs::path dir = root.path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(PlotBench, FindsTheScriptNextToTheExecutableThenInShare) {
  const fs::path prefix = Scratch("prefix");
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share" / "acdplan");
  const std::string exe = (prefix / "bin" / "acdplan").string();
  EXPECT_EQ(FindPlotBenchScript(exe, ""), "");
  std::ofstream(prefix / "share" / "acdplan" / "plot_bench.py") << "\n";
  EXPECT_EQ(FindPlotBenchScript(exe, ""),
            (prefix / "share" / "acdplan" / "plot_bench.py").string());
  std::ofstream(prefix / "bin" / "plot_bench.py") << "\n";  // A build tree's copy wins.
  EXPECT_EQ(FindPlotBenchScript(exe, ""), (prefix / "bin" / "plot_bench.py").string());
  // $ACDPLAN_PLOT_BENCH wins, even when wrong (so the mistake is reported, not hidden).
  EXPECT_EQ(FindPlotBenchScript(exe, "/nowhere/plot.py"), "/nowhere/plot.py");
  EXPECT_EQ(FindPlotBenchScript("", ""), "");
}

TEST(PlotBench, TheBuildPutsTheScriptNextToAcdplan) {
  EXPECT_EQ(FindPlotBenchScript(acdplan::test::AcdplanBinary(), ""),
            (fs::path(acdplan::test::AcdplanBinary()).parent_path() / "plot_bench.py").string());
  EXPECT_FALSE(SelfExecutable().empty());
}

TEST(PlotBench, FindsAPythonWithMatplotlib) {
  EXPECT_EQ(FindPlotPython("/opt/my/python"), "/opt/my/python");  // A setting wins, unchecked.
  const std::string found = FindPlotPython("");
  // Either none has matplotlib, or the one found imports it.
  if (!found.empty()) {
    EXPECT_EQ(RunProgram({found, "-c", "import matplotlib"}, true), 0);
  }
  const bool any = RunProgram({"python3", "-c", "import matplotlib"}, true) == 0 ||
                   RunProgram({"/usr/bin/python3", "-c", "import matplotlib"}, true) == 0;
  EXPECT_EQ(found.empty(), !any);
}

TEST(PlotBench, RunsProgramsWithoutAShell) {
  EXPECT_EQ(RunProgram({"sh", "-c", "exit 3"}, true), 3);
  EXPECT_EQ(RunProgram({"true"}, true), 0);
  EXPECT_EQ(RunProgram({"/nonexistent/program"}, true), 127);
  // Arguments reach the program as they are: no shell splits or expands them.
  const fs::path dir = Scratch("args");
  const std::string odd = (dir / "a b;$(echo x)").string();
  EXPECT_EQ(RunProgram({"touch", odd}, true), 0);
  EXPECT_TRUE(fs::exists(odd));
}

}  // namespace
}  // namespace acdplan::tools
