// Targets: the YAML format with its key-path errors, the JSON round trip of bench.json, and
// the evaluation (filters, conditions, ratios, not-applicable and not-measured rows).

#include "bench/targets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/input_error.h"
#include "bench/acd3d_bench.h"
#include "bench/collision_bench.h"
#include "bench/summary.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::bench {
namespace {

namespace fs = std::filesystem;

#define EXPECT_HAS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

std::string WriteFile(const std::string& name, const std::string& text) {
  static const test::ScratchDir dir("acdplan_targets_test");  // Removed when the process ends.
  return dir.Write(name, text);
}

/// The message LoadTargetsFile() throws for `text` with the planning vocabulary; "" if none.
std::string TargetsErrorOf(const std::string& text) {
  return test::InputErrorOf(
      [&] { LoadTargetsFile(WriteFile("t.yaml", text), PlanningTargetVocabulary()); });
}

TEST(Targets, ReadsTheFormat) {
  const std::vector<Target> targets = LoadTargetsFile(
      WriteFile("ok.yaml",
                "targets:\n"
                "  - name: rescue\n"
                "    where: {planner: PRM, world: [a, b]}\n"
                "    if: [{metric: uniform.success_rate, compare: '<=', value: 0.2}]\n"
                "    metric: acd.success_rate\n"
                "    compare: '>='\n"
                "    value: 0.95\n"
                "  - {metric: uniform.median_time_s, over: acd.median_time_s, compare: '>',"
                " value: 10}\n"),
      PlanningTargetVocabulary());
  ASSERT_EQ(targets.size(), 2u);
  EXPECT_EQ(targets[0].Label(), "rescue");
  EXPECT_EQ(targets[0].where.at("world"), (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(targets[0].conditions.size(), 1u);
  EXPECT_EQ(targets[0].conditions[0].compare, Comparison::kLessEqual);
  EXPECT_DOUBLE_EQ(targets[0].test.value, 0.95);
  EXPECT_EQ(targets[1].Label(), "uniform.median_time_s / acd.median_time_s > 10");

  // bench.json keeps them as JSON, which the same reader reads back.
  const std::string json = TargetsToJson(targets);
  const YamlFile file = YamlFile::Parse("targets: " + json, "bench.json");
  const std::vector<Target> again =
      ReadTargets(file, file.root()["targets"], "targets", PlanningTargetVocabulary());
  EXPECT_EQ(TargetsToJson(again), json);
}

TEST(Targets, ErrorsNameTheFileAndKeyPath) {
  const std::string ok = "{metric: acd.success_rate, compare: '>=', value: 1}";
  EXPECT_EQ(TargetsErrorOf("targets: [" + ok + "]\n"), "");
  EXPECT_HAS(TargetsErrorOf("goals: []\n"),
             "t.yaml: goals: unknown key (expected one of: targets)");
  EXPECT_HAS(TargetsErrorOf("targets: 3\n"), "t.yaml: targets: expected a list of targets");
  // A list as a key (the where: twin of fuzz_bench_yaml's finding in robots:).
  EXPECT_HAS(
      TargetsErrorOf("targets: [{where: {[a]: PRM}, metric: acd.success_rate, compare: '>=', "
                     "value: 1}]\n"),
      "t.yaml: targets[0].where: expected a mapping with string keys, got a list as a key");
  EXPECT_HAS(TargetsErrorOf("targets: [" + ok + ", {metric: acd.success_rate, value: 1}]\n"),
             "t.yaml: targets[1].compare: required");
  EXPECT_HAS(TargetsErrorOf("targets: [{metric: acd.success_rate, compare: '=>', value: 1}]\n"),
             "t.yaml: targets[0].compare: unknown comparison '=>' (expected one of: <, <=, >, >=, "
             "==, !=)");
  EXPECT_HAS(TargetsErrorOf("targets: [{metric: acd.success_rate, compare: '>=', value: high}]\n"),
             "t.yaml: targets[0].value: expected a finite number, got 'high'");
  EXPECT_HAS(TargetsErrorOf("targets: [{metric: acd.speed, compare: '>=', value: 1}]\n"),
             "t.yaml: targets[0].metric: expected samplers or [planner/]sampler.statistic");
  EXPECT_HAS(TargetsErrorOf("targets: [{metric: magic.success_rate, compare: '>=', value: 1}]\n"),
             "t.yaml: targets[0].metric: unknown sampler 'magic'");
  EXPECT_HAS(TargetsErrorOf("targets: [{metric: PRN/acd.success_rate, compare: '>=', value: 1}]\n"),
             "t.yaml: targets[0].metric: unknown planner 'PRN'");
  EXPECT_HAS(
      TargetsErrorOf("targets: [{metric: acd.success_rate, over: x, compare: '>=', value: 1}]\n"),
      "t.yaml: targets[0].over: expected samplers or");
  EXPECT_HAS(
      TargetsErrorOf("targets: [{where: {colour: red}, metric: acd.success_rate, compare: '>=', "
                     "value: 1}]\n"),
      "t.yaml: targets[0].where.colour: unknown label 'colour' (expected one of: world, "
      "family, robot, "
      "planner, budget, budget_type)");
  EXPECT_HAS(TargetsErrorOf("targets: [{if: [{metric: acd.runs, compare: '>'}], metric: "
                            "acd.success_rate, compare: '>=', value: 1}]\n"),
             "t.yaml: targets[0].if[0].value: required");
  EXPECT_HAS(
      TargetsErrorOf("targets: [{metric: acd.success_rate, compare: '>=', value: 1, by: me}]\n"),
      "t.yaml: targets[0].by: unknown key");
  EXPECT_HAS(TargetsErrorOf("targets: [\n"), "t.yaml:");  // Syntax error with its line.
}

TEST(Targets, ChecksRowsWithFiltersConditionsAndRatios) {
  Target rescue;
  rescue.where["planner"] = {"PRM"};
  rescue.conditions.push_back({"uniform.success_rate", "", Comparison::kLessEqual, 0.2});
  rescue.test = {"acd.success_rate", "", Comparison::kGreaterEqual, 0.95};
  Target faster;
  faster.name = "faster";
  faster.test = {"uniform.median_time_s", "acd.median_time_s", Comparison::kGreaterEqual, 10};

  std::vector<TargetRow> rows(4);
  rows[0].labels = {{"world", "a"}, {"planner", "PRM"}};
  rows[0].metrics = {{"uniform.success_rate", 0.1},
                     {"acd.success_rate", 1.0},
                     {"uniform.median_time_s", 2.0},
                     {"acd.median_time_s", 0.1}};
  rows[1].labels = {{"world", "b"}, {"planner", "PRM"}};  // uniform fine: rescue n/a.
  rows[1].metrics = {{"uniform.success_rate", 0.9},
                     {"acd.success_rate", 0.5},
                     {"uniform.median_time_s", 1.0},
                     {"acd.median_time_s", 0.5}};
  rows[2].labels = {{"world", "c"}, {"planner", "RRT"}};  // acd never solved: NaN misses.
  rows[2].metrics = {{"uniform.success_rate", 0.0},
                     {"acd.success_rate", 0.0},
                     {"uniform.median_time_s", 1.0},
                     {"acd.median_time_s", std::nan("")}};
  rows[3].labels = {{"world", "d"}, {"planner", "PRM"}};  // No acd at all: nothing applies.
  rows[3].metrics = {{"uniform.success_rate", 0.0}};

  const std::vector<Target> targets = {rescue, faster};
  const std::vector<TargetCheck> checks = CheckTargets(targets, rows);
  ASSERT_EQ(checks.size(), 4u);
  EXPECT_EQ(checks[0].row->labels.at("world"), "a");  // rescue on a
  EXPECT_TRUE(checks[0].holds);
  EXPECT_EQ(checks[1].row->labels.at("world"), "a");  // faster on a: 20x
  EXPECT_DOUBLE_EQ(checks[1].measured, 20.0);
  EXPECT_TRUE(checks[1].holds);
  EXPECT_EQ(checks[2].row->labels.at("world"), "b");  // faster on b: 2x
  EXPECT_FALSE(checks[2].holds);
  EXPECT_EQ(checks[3].row->labels.at("world"), "c");
  EXPECT_TRUE(std::isnan(checks[3].measured));
  EXPECT_FALSE(checks[3].holds);

  const std::string md = TargetChecksMarkdown(checks, {"world", "planner"});
  EXPECT_HAS(md, "| world | planner | target | measured | |\n");
  EXPECT_HAS(md,
             "| a | PRM | acd.success_rate >= 0.95 where uniform.success_rate <= 0.2 | 100% "
             "| holds |\n");
  EXPECT_HAS(md, "| b | PRM | faster | 2x | **missed** |\n");
  EXPECT_HAS(md, "| c | RRT | faster | not measured | **missed** |\n");
  EXPECT_HAS(md, "\n2 target checks hold, 2 missed.\n");

  // Numbers in `where` compare as numbers.
  Target at;
  at.where["world"] = {"0.010"};
  at.test = {"x", "", Comparison::kEqual, 1};
  TargetRow row;
  row.labels["world"] = "0.01";
  row.metrics["x"] = 1;
  const std::vector<Target> ats = {at};
  const std::vector<TargetRow> one = {row};
  EXPECT_EQ(CheckTargets(ats, one).size(), 1u);
}

TEST(Targets, AndTestsAndAnyOfMakeOneCheckPerGroup) {
  // "One tau_rel meets all three": ratio, parts against the peer, and time against the peer.
  const std::vector<Target> targets = LoadTargetsFile(
      WriteFile("any.yaml",
                "targets:\n"
                "  - metric: volume_ratio\n"
                "    compare: '<='\n"
                "    value: 1.1\n"
                "    and:\n"
                "      - {metric: parts, over: vhacd.parts, compare: '<=', value: 1}\n"
                "    any_of: tau_rel\n"),
      Acd3dBenchTargetVocabulary());
  ASSERT_EQ(targets.size(), 1u);
  EXPECT_EQ(targets[0].any_of, std::vector<std::string>{"tau_rel"});
  ASSERT_EQ(targets[0].also.size(), 1u);
  EXPECT_EQ(targets[0].Label(), "volume_ratio <= 1.1 and parts / vhacd.parts <= 1 for one tau_rel");
  // JSON round trip keeps both keys.
  const std::string json = TargetsToJson(targets);
  const YamlFile file = YamlFile::Parse("targets: " + json, "bench.json");
  EXPECT_EQ(TargetsToJson(
                ReadTargets(file, file.root()["targets"], "targets", Acd3dBenchTargetVocabulary())),
            json);

  auto row = [](const std::string& mesh, const std::string& tau_rel, double ratio, double parts) {
    TargetRow r;
    r.labels = {{"mesh", mesh}, {"tau_rel", tau_rel}};
    r.metrics = {{"volume_ratio", ratio}, {"parts", parts}, {"vhacd.parts", 64}};
    return r;
  };
  const std::vector<TargetRow> rows = {
      row("a", "0.2", 1.3, 4),    row("a", "0.05", 1.05, 30),  // a: 0.05 meets both.
      row("b", "0.2", 1.3, 4),    row("b", "0.05", 1.05, 80),  // b: the tight one has too many
      row("c", "0.2", 1.05, 100),                              // c: one row, and misses.
  };
  const std::vector<TargetCheck> checks = CheckTargets(targets, rows);
  ASSERT_EQ(checks.size(), 3u);
  EXPECT_TRUE(checks[0].holds);
  EXPECT_EQ(checks[0].row->labels.at("tau_rel"), "0.05");  // The row that holds.
  EXPECT_FALSE(checks[1].holds);
  EXPECT_EQ(checks[1].row->labels.at("tau_rel"), "0.2");  // None holds: the first row.
  EXPECT_FALSE(checks[2].holds);
  EXPECT_EQ(checks[2].missed_also, "parts / vhacd.parts 1.56x");
  const std::string md = TargetChecksMarkdown(checks, {"mesh", "tau_rel"});
  EXPECT_HAS(md,
             "| c | 0.2 | volume_ratio <= 1.1 and parts / vhacd.parts <= 1 for one tau_rel | "
             "1.05 (but parts / vhacd.parts 1.56x) | **missed** |");
  EXPECT_HAS(md, "1 target checks hold, 2 missed.");

  // Without any_of, one check per row.
  Target plain = targets[0];
  plain.any_of.clear();
  EXPECT_EQ(CheckTargets({plain}, rows).size(), 5u);

  // A list: rows that differ in either label form one group ("one setting": a tau_rel, with
  // or without a cap).
  const std::vector<Target> two = LoadTargetsFile(
      WriteFile("any_two.yaml",
                "targets: [{metric: volume_ratio, compare: '<=', value: 1.1, and: [{metric: "
                "parts, compare: '<=', value: 64}], any_of: [tau_rel, max_hulls]}]\n"),
      Acd3dBenchTargetVocabulary());
  ASSERT_EQ(two.size(), 1u);
  EXPECT_EQ(two[0].Label(), "volume_ratio <= 1.1 and parts <= 64 for one tau_rel and max_hulls");
  EXPECT_HAS(TargetsToJson(two), "\"any_of\":[\"tau_rel\",\"max_hulls\"]");
  std::vector<TargetRow> capped = rows;
  for (TargetRow& r : capped) r.labels["max_hulls"] = "0";
  capped.push_back(row("b", "0.05", 1.08, 64));
  capped.back().labels["max_hulls"] = "64";
  const std::vector<TargetCheck> by_setting = CheckTargets(two, capped);
  ASSERT_EQ(by_setting.size(), 3u);  // a, b (three settings), c
  EXPECT_TRUE(by_setting[1].holds);  // b: only the capped row meets both
  EXPECT_EQ(by_setting[1].row->labels.at("max_hulls"), "64");
  EXPECT_FALSE(by_setting[2].holds);
  // With only tau_rel, the capped row is a group of its own.
  EXPECT_EQ(CheckTargets(targets, capped).size(), 4u);

  try {
    LoadTargetsFile(WriteFile("bad_any.yaml",
                              "targets: [{metric: parts, compare: '<', value: 1, any_of: tau}]\n"),
                    Acd3dBenchTargetVocabulary());
    ADD_FAILURE() << "accepted an unknown label";
  } catch (const InputError& error) {
    EXPECT_HAS(error.what(), "bad_any.yaml: targets[0].any_of: unknown label 'tau'");
  }
  try {
    LoadTargetsFile(WriteFile("bad_and.yaml",
                              "targets: [{metric: parts, compare: '<', value: 1, and: [{metric: "
                              "speed, compare: '<', value: 1}]}]\n"),
                    Acd3dBenchTargetVocabulary());
    ADD_FAILURE() << "accepted an unknown metric";
  } catch (const InputError& error) {
    EXPECT_HAS(error.what(), "bad_and.yaml: targets[0].and[0].metric: unknown metric 'speed'");
  }
}

TEST(Targets, CollisionRowsLeaveUnmeasuredFiguresOut) {
  BenchCollisionRow open_mesh;
  open_mesh.world = "bunny/mesh";
  open_mesh.hulls_checks_per_s = 30;
  open_mesh.bvh_checks_per_s = 10;
  open_mesh.locate_exact_points_per_s = std::nan("");
  const std::vector<TargetRow> rows = CollisionTargetRows({open_mesh});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].labels.at("kind"), "mesh");
  EXPECT_EQ(rows[0].metrics.count("locate_exact_points_per_s"), 0u);
  const std::vector<Target> targets = LoadTargetsFile(
      WriteFile(
          "c.yaml",
          "targets:\n"
          "  - {metric: hulls_checks_per_s, over: bvh_checks_per_s, compare: '>=', value: 3}\n"
          "  - {metric: locate_hulls_points_per_s, over: locate_exact_points_per_s,"
          " compare: '>=', value: 10}\n"),
      CollisionTargetVocabulary());
  const std::string md = BenchCollisionMarkdown({open_mesh}, targets);
  EXPECT_HAS(md, "| bunny/mesh | hulls_checks_per_s / bvh_checks_per_s >= 3 | 3x | holds |");
  EXPECT_HAS(md, "1 target checks hold, 0 missed.");
  EXPECT_EQ(BenchCollisionMarkdown({open_mesh}).find("## Targets"), std::string::npos);
  try {
    LoadTargetsFile(WriteFile("bad.yaml", "targets: [{metric: speed, compare: '>', value: 1}]\n"),
                    CollisionTargetVocabulary());
    ADD_FAILURE() << "accepted an unknown metric";
  } catch (const InputError& error) {
    EXPECT_HAS(error.what(),
               "bad.yaml: targets[0].metric: unknown metric 'speed' (expected one of: "
               "triangles, hulls,");
  }
}

}  // namespace
}  // namespace acdplan::bench
