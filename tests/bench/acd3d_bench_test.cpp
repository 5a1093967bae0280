// The 3D ACD benchmark on small meshes of the corpus: rows, ratios, per-cell memory, the JSON
// and the Markdown, and the errors it raises before any cell runs.

#include "bench/acd3d_bench.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "base/input_error.h"
#include "bench/vhacd_peer.h"
#include "tests/data_paths.h"

namespace acdplan::bench {
namespace {

#define EXPECT_HAS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

std::string Mesh(const std::string& name) {
  return acdplan::test::DataDir() + "/meshes/vhacd/" + name;
}

TEST(Acd3dBench, ACubeIsOneConvexPartPerTau) {
  Acd3dBenchOptions options;
  options.files = {Mesh("cube.obj")};
  options.tau_rels = {0.2, 0.02};
  options.methods = {kAcdSolid};
  options.repeats = 1;
  options.check = true;
  options.data_dir = acdplan::test::DataDir() + "/meshes/vhacd";
  options.max_hulls = 3;  // A closed mesh: one more cell, capped, at capped_tau_rel.
  options.capped_tau_rel = 0.1;
  const Acd3dBenchResult result = RunAcd3dBench(options);
  EXPECT_TRUE(result.ok);
  ASSERT_EQ(result.rows.size(), 3u);
  EXPECT_EQ(result.rows[0].max_hulls, 0);
  EXPECT_EQ(result.rows[2].max_hulls, 3);
  EXPECT_DOUBLE_EQ(*result.rows[2].tau_rel, 0.1);
  for (const Acd3dBenchRow& row : result.rows) {
    EXPECT_EQ(row.mesh, "cube.obj");  // Shown relative to the data folder.
    EXPECT_EQ(row.input, "solid");
    EXPECT_EQ(row.mode, "solid");
    ASSERT_TRUE(row.parts.has_value()) << row.note;
    EXPECT_EQ(*row.parts, 1);
    ASSERT_TRUE(row.VolumeRatio().has_value());
    EXPECT_NEAR(*row.VolumeRatio(), 1.0, 1e-9);
    EXPECT_GT(row.peak_rss_mib, 0.0);
    EXPECT_EQ(row.runs, 1);
    EXPECT_EQ(row.check, "ok");
  }
  const nlohmann::json json = nlohmann::json::parse(Acd3dBenchJson(result, options));
  ASSERT_EQ(json.size(), 3u);
  EXPECT_EQ(json[0]["method"], "acd-solid");
  EXPECT_DOUBLE_EQ(json[1]["tau_rel"].get<double>(), 0.02);
  EXPECT_EQ(json[0]["parts"], 1);
  EXPECT_EQ(json[0]["max_hulls"], 0);
  EXPECT_EQ(json[2]["max_hulls"], 3);
  const std::string md = Acd3dBenchMarkdown(result, options);
  EXPECT_HAS(md, "| cube.obj | 26 | 48 | solid | acd-solid | 0.2 | — | solid | 1 | 1.000 |");
  EXPECT_HAS(md, "|  |  |  |  | acd-solid | 0.1 | 3 | solid | 1 | 1.000 |");
  EXPECT_HAS(md, "at tau_rel 0.1 merged down to at most 3 parts");
  EXPECT_HAS(md, "Problems (failed cells, CheckDecomposition3d failures, failed repairs): none");
  // Targets see the rows, and the V-HACD figures only where V-HACD ran.
  const std::vector<TargetRow> rows = Acd3dBenchTargetRows(result.rows);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].labels.at("input"), "solid");
  EXPECT_EQ(rows[0].labels.at("max_hulls"), "0");
  EXPECT_EQ(rows[2].labels.at("max_hulls"), "3");
  EXPECT_EQ(rows[0].metrics.at("failed"), 0.0);
  EXPECT_EQ(rows[0].metrics.count("vhacd.median_ms"), 0u);
}

TEST(Acd3dBench, AnOpenMeshGetsTheSurfaceAcdAndNoVolume) {
  Acd3dBenchOptions options;
  options.files = {Mesh("deer_bound.obj")};
  options.tau_rels = {0.2};
  options.methods = {kAcdSolid, kAcdSurface};
  options.repeats = 1;
  const Acd3dBenchResult result = RunAcd3dBench(options);
  ASSERT_FALSE(result.rows.empty());
  for (const Acd3dBenchRow& row : result.rows) {
    SCOPED_TRACE(row.method + " " + row.note);
    EXPECT_FALSE(row.failed());
    if (row.input == "non-solid") {
      EXPECT_EQ(row.method, kAcdSurface);
      EXPECT_FALSE(row.VolumeRatio().has_value());
    }
  }
}

TEST(Acd3dBench, BadOptionsFailBeforeAnyCell) {
  auto error_of = [](const Acd3dBenchOptions& options) {
    try {
      RunAcd3dBench(options);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  Acd3dBenchOptions unknown;
  unknown.files = {Mesh("cube.obj")};
  unknown.methods = {"coacd"};
  EXPECT_EQ(error_of(unknown),
            "--method coacd: unknown (expected one of: acd-solid, acd-surface, vhacd)");
  Acd3dBenchOptions missing;
  missing.files = {Mesh("no_such.obj")};
  EXPECT_HAS(error_of(missing), "no_such.obj: no such file");
  Acd3dBenchOptions zero;
  zero.files = {Mesh("cube.obj")};
  zero.tau_rels = {0};
  EXPECT_EQ(error_of(zero), "--tau-rel 0: must be finite and > 0");
  Acd3dBenchOptions negative_cap;
  negative_cap.files = {Mesh("cube.obj")};
  negative_cap.max_hulls = -1;
  EXPECT_EQ(error_of(negative_cap), "--max-hulls -1: must be >= 0 (0: no capped cell)");
  Acd3dBenchOptions no_data;
  no_data.data_dir = "/nowhere";
  EXPECT_HAS(error_of(no_data), "--data /nowhere: not a folder");
}

TEST(Acd3dBench, VhacdRowsOnlyWhenBuiltWithIt) {
  Acd3dBenchOptions options;
  options.files = {Mesh("cube.obj")};
  options.methods = {kVhacd};
  options.repeats = 1;
  const Acd3dBenchResult result = RunAcd3dBench(options);
  EXPECT_EQ(result.vhacd, HaveVhacd());
  EXPECT_EQ(result.rows.size(), HaveVhacd() ? 1u : 0u);
  if (!HaveVhacd()) {
    EXPECT_HAS(Acd3dBenchMarkdown(result, options),
               "V-HACD did not run (built without ACDPLAN_VHACD_INCLUDE_DIR)");
  }
}

}  // namespace
}  // namespace acdplan::bench
