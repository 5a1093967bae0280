// acd_bench: the command line of the 2D ACD benchmark (bench/acd_bench.h, tools/acd_bench.md).
// Prints the Markdown report on stdout, optionally writes the rows as JSON and checks targets.
//
// Exit status: 0 done; 2 bad usage or an unreadable file named on the command line; 1 one of
// our decompositions threw or failed --check (the table is still complete and says where).

#include "bench/acd_bench.h"

#include <CLI/CLI.hpp>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "base/file_io.h"
#include "base/input_error.h"
#include "bench/targets.h"

namespace {

namespace bench = acdplan::bench;
using acdplan::InputError;
using acdplan::WriteFileAtomically;

int Run(const bench::AcdBenchOptions& options, const std::string& json_path,
        const std::string& targets_path) {
  std::error_code ec;
  if (options.files.empty() && !std::filesystem::is_directory(options.data_dir, ec)) {
    throw InputError("--data " + options.data_dir +
                     ": not a folder (the default is relative to the working directory: "
                     "run from the repository, or give --data DIR or polygon files)");
  }
  if (!json_path.empty()) {
    // Fail before the (minutes long) runs rather than after them.
    const std::filesystem::path parent = std::filesystem::path(json_path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
      throw InputError("--json " + json_path + ": folder " + parent.string() + " does not exist");
    }
  }
  std::vector<bench::Target> targets;
  if (!targets_path.empty()) {
    targets = bench::LoadTargetsFile(targets_path, bench::AcdBenchTargetVocabulary());
  }
  const bench::AcdBenchResult result = bench::RunAcdBench(options, &std::cerr);
  std::cout << bench::AcdBenchMarkdown(result, options, targets) << std::flush;
  if (!json_path.empty()) WriteFileAtomically(json_path, bench::AcdBenchJson(result, options));
  return result.ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  bench::AcdBenchOptions options;
  std::string json_path, targets_path;
  CLI::App app{
      "acd_bench: 2D approximate convex decomposition benchmark against CGAL's "
      "convex partitions (tools/acd_bench.md)"};
  app.add_option("files", options.files,
                 "Polygon files (.poly, .wkt, .geojson); default: the benchmark's list under "
                 "--data");
  app.add_option("--tau-rel", options.tau_rels,
                 "tau relative to the reference radius; repeatable (default: 0.01 and 0)")
      ->allow_extra_args(false)
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--repeats", options.repeats, "Timed runs per cell (median)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--cell-budget-ms", options.cell_budget_ms,
                 "Stop repeating a cell once it used this long (at least 3 runs)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e9));
  app.add_option("--optimal-max-n", options.optimal_max_vertices,
                 "Run CGAL's O(n^4) optimal partition only up to this many vertices")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  app.add_option("--json", json_path, "Also write the table as JSON (a list of rows)");
  app.add_option("--data", options.data_dir,
                 "Folder of the default polygon list (relative to the working directory)")
      ->capture_default_str();
  app.add_option("--targets", targets_path,
                 "YAML file of targets to check on the rows (e.g. "
                 "configs/bench/acd2d_targets.yaml; bench/targets.h)");
  app.add_flag("--check", options.check,
               "Run CheckDecomposition on each of our decompositions and report failures");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  try {
    return Run(options, json_path, targets_path);
  } catch (const InputError& error) {
    std::cerr << "acd_bench: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "acd_bench: internal error: " << error.what() << "\n";
    return 1;
  }
}
