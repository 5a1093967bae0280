// acd3d_bench: the command line of the 3D ACD benchmark (bench/acd3d_bench.h,
// tools/acd3d_bench.md). Prints the Markdown report on stdout (or writes it to --md), optionally
// writes the rows as JSON and checks targets.
//
// Exit status: 0 done; 2 bad usage or an unreadable file named on the command line; 1 a cell of
// ours failed (crash, timeout, exception) or failed --check (the table is still complete and
// says where).

#include "bench/acd3d_bench.h"

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

/// Fails before the (long) runs rather than after them.
void CheckOutputFolder(const std::string& option, const std::string& path) {
  if (path.empty()) return;
  std::error_code ec;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
    throw InputError(option + " " + path + ": folder " + parent.string() + " does not exist");
  }
}

int Run(const bench::Acd3dBenchOptions& options, const std::string& md_path,
        const std::string& json_path, const std::string& targets_path) {
  CheckOutputFolder("--md", md_path);
  CheckOutputFolder("--json", json_path);
  std::vector<bench::Target> targets;
  if (!targets_path.empty()) {
    targets = bench::LoadTargetsFile(targets_path, bench::Acd3dBenchTargetVocabulary());
  }
  const bench::Acd3dBenchResult result = bench::RunAcd3dBench(options, &std::cerr);
  const std::string markdown = bench::Acd3dBenchMarkdown(result, options, targets);
  if (md_path.empty()) {
    std::cout << markdown << std::flush;
  } else {
    WriteFileAtomically(md_path, markdown);
  }
  if (!json_path.empty()) WriteFileAtomically(json_path, bench::Acd3dBenchJson(result, options));
  return result.ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  bench::Acd3dBenchOptions options;
  std::string md_path, json_path, targets_path;
  CLI::App app{
      "acd3d_bench: 3D approximate convex decomposition benchmark against V-HACD "
      "(tools/acd3d_bench.md)"};
  app.add_option("files", options.files, "Mesh files (OBJ, STL, PLY, ...); default: --data/*.obj");
  app.add_option("--tau-rel", options.tau_rels,
                 "tau relative to the mesh's reference radius; repeatable (default: 0.2, 0.05, "
                 "0.02)")
      ->allow_extra_args(false)
      ->check(CLI::Range(1e-12, 1e6));
  app.add_option("--method", options.methods,
                 "acd-solid, acd-surface or vhacd; repeatable (default: all)")
      ->allow_extra_args(false);
  app.add_flag("--surface-on-solids", options.surface_on_solids,
               "Also run the surface ACD on meshes that are solid");
  app.add_flag("--feature-grouping", options.feature_grouping,
               "Solid ACD: also try the global cut's plane (feature grouping, Sec. V.B.2)");
  app.add_option("--merge-growth", options.merge_growth,
                 "Solid ACD: merge tau-convex neighbours while their hull grows by at most this "
                 "fraction (Decompose3dOptions::merge_growth; default: tau_rel / 2); < 0: no merge "
                 "pass");
  app.add_option("--max-hulls", options.max_hulls,
                 "One more solid ACD cell, at --capped-tau-rel, merged down to at "
                 "most N parts (Decompose3dOptions::max_hulls); 0: none")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--capped-tau-rel", options.capped_tau_rel, "tau_rel of the --max-hulls cell")
      ->capture_default_str()
      ->check(CLI::Range(1e-12, 1e6));
  app.add_option("--repeats", options.repeats, "Timed runs per cell (median)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--cell-budget-ms", options.cell_budget_ms,
                 "Stop repeating a cell once its runs took this long (at least 1 run)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e9));
  app.add_option("--cell-timeout-s", options.cell_timeout_s,
                 "Kill a cell's child process after this long; the cell shows as failed")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 1e6));
  app.add_option("--md", md_path, "Write the Markdown report here instead of stdout");
  app.add_option("--json", json_path, "Also write the table as JSON (a list of rows)");
  app.add_option("--data", options.data_dir,
                 "Folder of the default mesh list (relative to the working directory)")
      ->capture_default_str();
  app.add_option("--targets", targets_path,
                 "YAML file of targets to check on the rows (e.g. "
                 "configs/bench/acd3d_targets.yaml; bench/targets.h)");
  app.add_flag("--check", options.check,
               "Run CheckDecomposition3d on each of our decompositions and report failures");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  try {
    return Run(options, md_path, json_path, targets_path);
  } catch (const InputError& error) {
    std::cerr << "acd3d_bench: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "acd3d_bench: internal error: " << error.what() << "\n";
    return 1;
  }
}
