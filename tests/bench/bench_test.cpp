// The benchmark: BENCH.yaml errors name the file and the key path; Wilson intervals; shards
// merged equal the unsharded run; the OMPL log loads in ompl_benchmark_statistics; a small
// Figure-4 bench where acd beats uniform; the CLI's exit statuses (2 bad input, 130 Ctrl-C).
// Budgets are sample counts (results depend on the seeds only) and small; no wall-clock limits.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "bench/merge.h"
#include "bench/ompl_log.h"
#include "bench/outputs.h"
#include "bench/record.h"
#include "bench/runner.h"
#include "bench/spec.h"
#include "bench/stats.h"
#include "tests/asan_build.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::bench {
namespace {

namespace fs = std::filesystem;

using acdplan::test::kConfigs;

fs::path Scratch(const std::string& name) {
  static const test::ScratchDir root("acdplan_bench_test");  // Removed when the process ends.
  const fs::path dir = root.path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Writes a bench file into configs/bench's sibling scratch folder, so "../demo.yaml"-style
/// paths are not needed: worlds use absolute scenario paths or generators.
std::string WriteBench(const std::string& name, const std::string& text) {
  const fs::path path = Scratch("specs_" + name) / (name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

/// The message LoadBenchSpec() throws for `text`; "" if it does not throw.
std::string SpecErrorOf(const std::string& text) {
  return test::InputErrorOf([&] { LoadBenchSpec(WriteBench("bad", text)); });
}

const std::string kWorlds =
    "name: t\n"
    "worlds:\n"
    "  - name: gap\n"
    "    workspace: {generator: wall_gap, seed: 1, passage_width: 0.05, wall_thickness: 1.0}\n"
    "    start: [2.5, 5.0]\n"
    "    goal: [7.5, 5.0]\n";

#define EXPECT_HAS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

TEST(BenchSpec, ErrorsNameTheFileAndKeyPath) {
  const std::string cases =
      "cases:\n  - {samplers: [acd], planners: [PRM], budgets: [{samples: 50}]}\n";
  EXPECT_EQ(SpecErrorOf(kWorlds + cases), "");
  EXPECT_HAS(SpecErrorOf(kWorlds), "bad.yaml: cases: required");
  EXPECT_HAS(SpecErrorOf("name: t\n" + cases), "bad.yaml: worlds: required");
  EXPECT_HAS(SpecErrorOf(kWorlds + cases + "colour: red\n"), "bad.yaml: colour: unknown key");
  // A list as a key (found by fuzz/fuzz_bench_yaml, which stopped on yaml-cpp's bad conversion;
  // fuzz/corpus/bench_yaml/regression-sequence-as-robot-key.yaml).
  EXPECT_HAS(SpecErrorOf(kWorlds + cases + "robots:\n  - {name: bar, [a]: 1}\n"),
             "bad.yaml: robots[0]: expected a mapping with string keys, got a list as a key");
  EXPECT_HAS(SpecErrorOf(kWorlds + cases + "runs: 0\n"),
             "bad.yaml: runs: expected an integer >= 1, got '0'");
  EXPECT_HAS(SpecErrorOf(kWorlds + "cases:\n  - {samplers: [acd], planners: [PRM, PRN], budgets: "
                                   "[{samples: 5}]}\n"),
             "bad.yaml: cases[0].planners[1]: unknown planner 'PRN' (expected one of: PRM,");
  EXPECT_HAS(SpecErrorOf(kWorlds + "cases:\n  - {samplers: [magic], planners: [PRM], budgets: "
                                   "[{samples: 5}]}\n"),
             "bad.yaml: cases[0].samplers[0]: unknown sampler 'magic'");
  EXPECT_HAS(SpecErrorOf(kWorlds + "cases:\n  - {samplers: [acd], planners: [RRTConnect], budgets: "
                                   "[{samples: 5}]}\n"),
             "bad.yaml: cases[0].budgets[0].samples: a sample budget (the Figure-4 protocol) "
             "needs PRM, PRM_ACD or PRMstar, not RRTConnect");
  EXPECT_HAS(SpecErrorOf(kWorlds + "cases:\n  - {samplers: [acd], planners: [PRM], budgets: "
                                   "[{time_limit: -1}]}\n"),
             "bad.yaml: cases[0].budgets[0].time_limit: expected a positive number, got '-1'");
  EXPECT_HAS(SpecErrorOf(kWorlds + "cases:\n  - {worlds: [nowhere], samplers: [acd], planners: "
                                   "[PRM], budgets: [{samples: 5}]}\n"),
             "bad.yaml: cases[0].worlds[0]: unknown name 'nowhere' (expected one of: gap)");
  EXPECT_HAS(SpecErrorOf(kWorlds + "robots:\n  - {name: d, shape: disc}\n" + cases),
             "bad.yaml: robots[0].radius: required for shape disc");
  EXPECT_HAS(SpecErrorOf(kWorlds + "robots:\n  - {name: d, shape: point, wheels: 4}\n" + cases),
             "bad.yaml: robots[0].wheels: unknown key");
  EXPECT_HAS(SpecErrorOf("name: t\nworlds:\n  - {name: w, workspace: {generator: wall_gap, "
                         "passage_width: -1}, start: [1, 1], goal: [2, 2]}\n" +
                         cases),
             "bad.yaml: worlds[0].workspace.passage_width: expected a positive number, got '-1'");
  EXPECT_HAS(SpecErrorOf("name: t\nworlds:\n  - {scenario: missing.yaml}\n" + cases),
             "bad.yaml: worlds[0].scenario: ");
  EXPECT_HAS(SpecErrorOf("name: t\nworlds:\n  - {name: w, workspace: {generator: wall_gap}, "
                         "start: [1, 1]}\n" +
                         cases),
             "bad.yaml: worlds[0].goal: required");
  EXPECT_HAS(
      SpecErrorOf(kWorlds + "  - name: gap\n    scenario: " + kConfigs + "/demo.yaml\n" + cases),
      "bad.yaml: worlds[1].name: duplicate world name 'gap'");
  EXPECT_HAS(SpecErrorOf(kWorlds + "cases: [\n"), "bad.yaml:");  // Syntax error with a line.
}

TEST(BenchSpec, ExpandsCasesSweepsAndShards) {
  const BenchSpec spec = LoadBenchSpec(WriteBench(
      "sweep",
      "name: sweep\nruns: 3\nworlds:\n"
      "  - name: gap\n    workspace: {generator: wall_gap, seed: 1}\n"
      "    start: [2.5, 5.0]\n    goal: [7.5, 5.0]\n    passage_widths: [0.5, 0.05]\n"
      "robots:\n  - {name: p}\n  - {name: d, shape: disc, radius: 0.01}\n"
      "cases:\n  - {samplers: [uniform, acd], planners: [PRM], budgets: [{samples: 10}]}\n"
      "  - {robots: [d], samplers: [acd], planners: [RRTConnect], budgets: [{time_limit: 1}]}\n"));
  ASSERT_EQ(spec.worlds.size(), 2u);
  EXPECT_EQ(spec.worlds[0].name, "gap_w0.5");
  EXPECT_EQ(spec.worlds[1].name, "gap_w0.05");
  EXPECT_EQ(spec.worlds[1].family, "gap");
  EXPECT_DOUBLE_EQ(spec.worlds[1].passage_width, 0.05);
  EXPECT_EQ(spec.cases.size(), 2u * 2u * 2u + 2u);
  EXPECT_EQ(spec.cases[0].Key(spec), "gap_w0.5/p/uniform/PRM/10 samples");

  // Shards partition the runs; seeds do not depend on the shard.
  const std::vector<BenchRunId> all = BenchRunsOfShard(spec, 3, {1, 1});
  EXPECT_EQ(all.size(), spec.cases.size() * 3);
  std::vector<BenchRunId> joined;
  for (int i = 1; i <= 3; ++i) {
    for (const BenchRunId& id : BenchRunsOfShard(spec, 3, {i, 3})) {
      EXPECT_EQ(id.global % 3, static_cast<std::uint64_t>(i - 1));
      joined.push_back(id);
    }
  }
  ASSERT_EQ(joined.size(), all.size());
  for (const BenchRunId& a : all) {
    bool found = false;
    for (const BenchRunId& b : joined) found |= a.global == b.global && a.seed == b.seed;
    EXPECT_TRUE(found) << a.global;
  }
  EXPECT_NE(BenchRunSeed(1, "a", 0), BenchRunSeed(1, "a", 1));
  EXPECT_NE(BenchRunSeed(1, "a", 0), BenchRunSeed(2, "a", 0));
  EXPECT_NE(BenchRunSeed(1, "a", 0), BenchRunSeed(1, "b", 0));
  EXPECT_EQ(BenchRunSeed(7, "x/y", 3), BenchRunSeed(7, "x/y", 3));
}

const std::string kCarWorld =
    "name: cars\nworlds:\n  - {name: trap, scenario: " + kConfigs + "/car_bug_trap.yaml}\n";
const std::string kCars =
    "robots:\n  - {name: kcar, type: kinematic_car, length: 0.3, width: 0.15}\n"
    "  - {name: dcar, type: dynamic_car, length: 0.3, width: 0.15, max_steer_rate: 0.5}\n";

TEST(BenchSpec, CarCasesExpandDecompositionsAndCheckTheirKeys) {
  const BenchSpec spec = LoadBenchSpec(WriteBench(
      "cars", kCarWorld + kCars +
                  "cases:\n  - {planners: [SyclopRRT, SyclopEST], decompositions: [acd, "
                  "grid10, grid40], budgets: [{time_limit: 2}]}\n"
                  "  - {robots: [kcar], planners: [RRT, KPIECE1], budgets: [{time_limit: 2}]}\n"));
  ASSERT_EQ(spec.cases.size(), 2u * 2u * 3u + 2u);
  EXPECT_EQ(spec.cases[0].Key(spec), "trap/kcar/acd/SyclopRRT/2 s");
  EXPECT_EQ(spec.cases[2].Key(spec), "trap/kcar/grid40/SyclopRRT/2 s");
  EXPECT_EQ(spec.cases[12].Key(spec), "trap/kcar/none/RRT/2 s");
  EXPECT_TRUE(spec.cases[12].control);
  EXPECT_FALSE(spec.cases[12].decomposition.has_value());
  ASSERT_TRUE(spec.robots[1].car.has_value());
  EXPECT_EQ(spec.robots[1].car->model, planning::control::CarModel::kDynamic);
  EXPECT_DOUBLE_EQ(spec.robots[1].car->options.max_steer_rate, 0.5);

  const std::string syclop = "cases:\n  - {planners: [SyclopRRT], budgets: [{time_limit: 1}]}\n";
  EXPECT_EQ(SpecErrorOf(kCarWorld + kCars + syclop), "");
  EXPECT_HAS(SpecErrorOf(kCarWorld + kCars + "  - {name: p}\n" + syclop),
             "bad.yaml: cases[0].robots: mixes cars (control planners) and rigid robots");
  EXPECT_HAS(SpecErrorOf(kCarWorld + kCars +
                         "cases:\n  - {samplers: [acd], planners: [RRT], budgets: [{time_limit: "
                         "1}]}\n"),
             "bad.yaml: cases[0].samplers: a car is planned by control planners");
  EXPECT_HAS(SpecErrorOf(kCarWorld + kCars +
                         "cases:\n  - {planners: [PRM], budgets: [{time_limit: 1}]}\n"),
             "bad.yaml: cases[0].planners[0]: unknown control planner 'PRM'");
  EXPECT_HAS(SpecErrorOf(kCarWorld + kCars +
                         "cases:\n  - {planners: [SyclopEST], decompositions: [grid0], budgets: "
                         "[{time_limit: 1}]}\n"),
             "bad.yaml: cases[0].decompositions[0]: unknown decomposition 'grid0' (expected acd "
             "or grid<cells per side, 1-1000>, e.g. grid20)");
  EXPECT_HAS(SpecErrorOf(kCarWorld + kCars +
                         "cases:\n  - {planners: [SyclopEST], budgets: [{samples: 100}]}\n"),
             "bad.yaml: cases[0].budgets[0]: a car's control planner takes a time_limit");
  EXPECT_HAS(SpecErrorOf(kCarWorld +
                         "cases:\n  - {samplers: [acd], planners: [PRM], decompositions: [acd], "
                         "budgets: [{samples: 10}]}\n"),
             "bad.yaml: cases[0].decompositions: only for car robots");
  EXPECT_HAS(SpecErrorOf(kCarWorld + "robots:\n  - {name: c, type: kinematic_car, max_accel: 1}\n" +
                         syclop),
             "bad.yaml: robots[0].max_accel: only for type dynamic_car");
}

TEST(BenchRunner, RunsCarCasesWithTheirDecompositionInTheSamplerColumn) {
  // Short time budgets; only what does not depend on the clock is checked.
  const BenchSpec spec = LoadBenchSpec(WriteBench(
      "car_run", kCarWorld + kCars +
                     "cases:\n  - {robots: [kcar], planners: [SyclopRRT], decompositions: [acd, "
                     "grid10], budgets: [{time_limit: 0.2}]}\n"
                     "  - {robots: [dcar], planners: [KPIECE1], budgets: [{time_limit: 0.2}]}\n"));
  BenchRunOptions one_run;
  one_run.runs = 1;
  const BenchRunOutcome outcome = RunBench(spec, one_run);
  ASSERT_EQ(outcome.records.size(), 3u);
  const BenchRecord& acd = outcome.records[0];
  EXPECT_EQ(acd.what.sampler, "acd");
  EXPECT_EQ(acd.what.planner, "SyclopRRT");
  EXPECT_GT(acd.decomposition_s, 0.0);  // The map's one-off ACD cost.
  EXPECT_EQ(acd.components, 8);         // Syclop's regions: the bug trap's ACD components.
  const BenchRecord& grid = outcome.records[1];
  EXPECT_EQ(grid.what.sampler, "grid10");
  EXPECT_EQ(grid.decomposition_s, 0.0);
  EXPECT_EQ(grid.components, 100);
  const BenchRecord& kpiece = outcome.records[2];
  EXPECT_EQ(kpiece.what.sampler, "none");
  EXPECT_EQ(kpiece.what.robot, "dcar");
  for (const BenchRecord& r : outcome.records) {
    EXPECT_TRUE(r.status == RunStatus::kSolved || r.status == RunStatus::kUnsolved)
        << ToString(r.status);
    EXPECT_GT(r.collision_checks, 0u);
    EXPECT_GT(r.samples, 0u);  // Tree states.
  }
}

TEST(BenchSpec, ShardSyntax) {
  EXPECT_EQ(ParseBenchShard("2/8").index, 2);
  EXPECT_EQ(ParseBenchShard("2/8").count, 8);
  for (const char* bad : {"0/2", "3/2", "1", "a/b", "1/2x", "1/0"}) {
    try {
      ParseBenchShard(bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& error) {
      EXPECT_HAS(error.what(), "expected I/N");
    }
  }
}

TEST(BenchStats, WilsonIntervalKnownValues) {
  // Newcombe (1998), Statistics in Medicine 17, 857-872, Table I (method 3) and direct
  // evaluation of Wilson's formula at z = 1.959964.
  const struct {
    int k, n;
    double lo, hi;
  } known[] = {{0, 10, 0.0, 0.277533},       {5, 10, 0.236593, 0.763407},
               {10, 10, 0.722467, 1.0},      {1, 20, 0.008881, 0.236131},
               {19, 20, 0.763869, 0.991119}, {7, 100, 0.034319, 0.137495}};
  for (const auto& c : known) {
    const auto [lo, hi] = WilsonInterval(c.k, c.n);
    EXPECT_NEAR(lo, c.lo, 1e-6) << c.k << "/" << c.n;
    EXPECT_NEAR(hi, c.hi, 1e-6) << c.k << "/" << c.n;
  }
  EXPECT_EQ(WilsonInterval(0, 0), std::make_pair(0.0, 1.0));
  EXPECT_THROW(WilsonInterval(3, 2), std::invalid_argument);
  EXPECT_DOUBLE_EQ(Quantile({3, 1, 2}, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(Quantile({1, 2, 3, 4}, 0.9), 3.7);
}

/// A small Figure-4 bench: the demo world, sample budgets only (seed-determined results).
std::string SmallFigure4(int runs) {
  return "name: small\nseed: 5\nruns: " + std::to_string(runs) +
         "\nworlds:\n  - scenario: " + kConfigs +
         "/demo.yaml\nrobots:\n  - {name: point}\n"
         "cases:\n  - {samplers: [uniform, gaussian, acd], planners: [PRM], budgets: "
         "[{samples: 200}]}\n";
}

BenchManifest ManifestOf(const BenchSpec& spec, const std::string& shard) {
  BenchManifest m;
  m.name = spec.name;
  m.spec = spec.path;
  m.seed = spec.seed;
  m.runs = spec.runs;
  m.cases = static_cast<int>(spec.cases.size());
  m.shards = {shard};
  m.hostname = "test";
  m.started = "2026-01-01 00:00:00";
  return m;
}

/// `text` without what depends on the clock: the named JSON keys, or in a log the time and
/// decomposition-time fields of the runs and the total time.
nlohmann::json WithoutTimes(nlohmann::json j) {
  for (auto& c : j["cases"]) {
    c.erase("median_time_s");
    c.erase("p90_time_s");
    c.erase("median_decomposition_s");
  }
  return j;
}

void LogWithoutTimes(const std::string& log, std::vector<std::string>* out) {
  std::vector<std::string>& lines = *out;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("seconds spent to collect") != std::string::npos) continue;
    size_t separators = 0;
    for (size_t at = line.find("; "); at != std::string::npos; at = line.find("; ", at + 1)) {
      ++separators;
    }
    if (separators >= 12) {  // A run's measurements.
      std::vector<std::string> fields;
      std::istringstream fs(line);
      std::string f;
      while (std::getline(fs, f, ';')) fields.push_back(f);
      ASSERT_GE(fields.size(), 13u) << line;
      fields[0] = "";  // time
      fields[7] = "";  // decomposition time
      line.clear();
      for (const std::string& x : fields) line += x + ";";
    }
    lines.push_back(line);
  }
}

TEST(BenchRunner, ShardsMergedEqualTheUnshardedRun) {
  const BenchSpec spec = LoadBenchSpec(WriteBench("shards", SmallFigure4(3)));
  const fs::path whole = Scratch("whole"), s1 = Scratch("s1"), s2 = Scratch("s2"),
                 merged = Scratch("merged");
  const BenchRunOutcome all = RunBench(spec);
  ASSERT_EQ(all.records.size(), 9u);
  EXPECT_FALSE(all.interrupted);
  WriteBenchOutputs(whole.string(), ManifestOf(spec, "1/1"), all.records);
  BenchRunOptions o1, o2;
  o1.shard = {1, 2};
  o2.shard = {2, 2};
  const BenchRunOutcome r1 = RunBench(spec, o1), r2 = RunBench(spec, o2);
  EXPECT_EQ(r1.records.size(), 5u);
  EXPECT_EQ(r2.records.size(), 4u);
  WriteBenchOutputs(s1.string(), ManifestOf(spec, "1/2"), r1.records);
  WriteBenchOutputs(s2.string(), ManifestOf(spec, "2/2"), r2.records);

  BenchManifest manifest;
  std::vector<BenchRecord> records;
  MergeBenchRecords({s1.string(), s2.string()}, &manifest, &records);
  EXPECT_EQ(manifest.shards, (std::vector<std::string>{"1/2", "2/2"}));
  WriteBenchOutputs(merged.string(), manifest, records);

  // runs.csv: every field but the two times.
  const std::vector<BenchRecord> a = ReadBenchRecordsCsv((whole / "runs.csv").string());
  const std::vector<BenchRecord> b = ReadBenchRecordsCsv((merged / "runs.csv").string());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    BenchRecord x = a[i], y = b[i];
    x.time_s = y.time_s = 0;
    x.decomposition_s = y.decomposition_s = 0;
    EXPECT_EQ(BenchRecordsToCsv({x}), BenchRecordsToCsv({y})) << i;
  }
  EXPECT_EQ(WithoutTimes(nlohmann::json::parse(ReadText(whole / "results.json"))),
            WithoutTimes(nlohmann::json::parse(ReadText(merged / "results.json"))));
  const std::string log = BenchOmplLogName("demo");
  std::vector<std::string> whole_log, merged_log;
  LogWithoutTimes(ReadText(whole / log), &whole_log);
  LogWithoutTimes(ReadText(merged / log), &merged_log);
  EXPECT_EQ(whole_log, merged_log);

  // A run in two folders is refused.
  try {
    MergeBenchRecords({s1.string(), s1.string()}, &manifest, &records);
    ADD_FAILURE() << "merged a shard with itself";
  } catch (const InputError& error) {
    EXPECT_HAS(error.what(), "is also in");
  }
}

TEST(BenchRunner, ReapsOnlyItsOwnChildren) {
  // A child of the caller's that has exited before the bench runs: the runner must leave its
  // exit status to the caller (a waitpid(-1) would take it).
  const pid_t mine = fork();
  ASSERT_GE(mine, 0);
  if (mine == 0) _exit(7);
  const BenchSpec spec = LoadBenchSpec(WriteBench("reap", SmallFigure4(1)));
  const BenchRunOutcome outcome = RunBench(spec);
  EXPECT_EQ(outcome.records.size(), 3u);
  int status = 0;
  ASSERT_EQ(waitpid(mine, &status, 0), mine) << "the runner reaped a child it did not start";
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 7);
}

TEST(BenchRunner, AcdBeatsUniformOnFigure4) {
  const int runs = acdplan::test::kRateSeeds;
  const BenchSpec spec = LoadBenchSpec(WriteBench("figure4", SmallFigure4(runs)));
  const BenchRunOutcome outcome = RunBench(spec);
  int acd = 0, uniform = 0;
  for (const BenchCaseSummary& c : SummarizeBenchCases(outcome.records)) {
    if (c.what.sampler == "acd") acd = c.successes;
    if (c.what.sampler == "uniform") uniform = c.successes;
    EXPECT_EQ(c.runs, runs);
  }
  EXPECT_GE(acd, runs - 1);
  EXPECT_LE(uniform, 3 * runs / 10);
  for (const BenchRecord& r : outcome.records) {
    EXPECT_EQ(r.samples, 200u);
    EXPECT_GT(r.collision_checks, 0u);
    EXPECT_EQ(r.decomposition_s > 0, r.what.sampler == "acd");
  }
}

TEST(BenchRunner, RunsAnOmplAppProblemWithItsOwnRobot) {
  const std::string cfg = acdplan::test::SourceDir() + "/tests/data/ompl_app/planar.cfg";
  const BenchSpec spec = LoadBenchSpec(WriteBench(
      "cfg", "name: cfg\nseed: 3\nruns: 2\nworlds:\n  - scenario: " + cfg +
                 "\nrobots:\n  - {name: own, shape: scenario}\n"
                 "cases:\n  - {samplers: [acd], planners: [PRM], budgets: [{samples: 600}]}\n"));
  ASSERT_EQ(spec.worlds.size(), 1u);
  EXPECT_EQ(spec.worlds[0].name, "planar");
  EXPECT_EQ(spec.worlds[0].scenario.robot.shape, envs::RobotShape::kPolygon);
  EXPECT_TRUE(spec.robots[0].from_scenario);
  const BenchRunOutcome outcome = RunBench(spec);
  ASSERT_EQ(outcome.records.size(), 2u);
  for (const BenchRecord& r : outcome.records) {
    EXPECT_EQ(r.samples, 600u);
    EXPECT_TRUE(r.solved) << "run " << r.run;
  }
  // `shape: scenario` takes no shape keys of its own.
  EXPECT_HAS(
      SpecErrorOf("name: cfg\nworlds:\n  - scenario: " + cfg +
                  "\nrobots:\n  - {name: own, shape: scenario, radius: 1}\n"
                  "cases:\n  - {samplers: [acd], planners: [PRM], budgets: [{samples: 9}]}\n"),
      "robots[0].radius: not with shape: scenario");
}

// A 3D world runs (its ACD decomposed in the parent into the disk cache; the in-process 2D
// cache once tried to decompose its empty 2D workspace and stopped every run), acd_lead too.
TEST(BenchRunner, RunsA3dWorldWithTheLead) {
  const fs::path cache = Scratch("3d_cache");
  setenv("ACDPLAN_CACHE_DIR", cache.c_str(), 1);
  const std::string scenario = acdplan::test::SourceDir() + "/configs/window_wall_3d.yaml";
  const BenchSpec spec = LoadBenchSpec(
      WriteBench("world3d", "name: world3d\nseed: 2\nruns: 1\nworlds:\n  - scenario: " + scenario +
                                "\nrobots:\n  - {name: own, shape: scenario}\n"
                                "cases:\n  - {samplers: [uniform, acd_lead], planners: [PRM], "
                                "budgets: [{samples: 60}]}\n"));
  const BenchRunOutcome outcome = RunBench(spec);
  unsetenv("ACDPLAN_CACHE_DIR");
  std::filesystem::remove_all(cache);
  ASSERT_EQ(outcome.records.size(), 2u);
  for (const BenchRecord& r : outcome.records) {
    EXPECT_NE(r.status, RunStatus::kCrashed) << r.what.sampler;
    EXPECT_EQ(r.samples, 60u) << r.what.sampler;
  }
}

TEST(BenchReport, SpecTargetsAreCheckedInTheSummaryAndSurviveAMerge) {
  const std::string text = SmallFigure4(2) +
                           "targets:\n"
                           "  - name: acd solves\n"
                           "    where: {planner: PRM, budget_type: samples}\n"
                           "    if: [{metric: uniform.success_rate, compare: '<=', value: 1}]\n"
                           "    metric: acd.success_rate\n"
                           "    compare: '>='\n"
                           "    value: 0.5\n"
                           "  - {metric: gaussian.runs, compare: '==', value: 3}\n";
  const BenchSpec spec = LoadBenchSpec(WriteBench("targets", text));
  ASSERT_EQ(spec.targets.size(), 2u);
  BenchManifest manifest = ManifestOf(spec, "1/1");
  manifest.targets = spec.targets;
  const fs::path dir = Scratch("targets"), merged = Scratch("targets_merged");
  WriteBenchOutputs(dir.string(), manifest, RunBench(spec).records);
  const std::string summary = ReadText(dir / "summary.md");
  EXPECT_HAS(summary, "## Targets\n");
  EXPECT_HAS(summary, "| demo | point | PRM | 200 samples | acd solves | 100% | holds |\n");
  EXPECT_HAS(summary,
             "| demo | point | PRM | 200 samples | gaussian.runs == 3 | 2 | **missed** |\n");
  EXPECT_HAS(summary, "1 target checks hold, 1 missed.");

  BenchManifest joined;
  std::vector<BenchRecord> records;
  MergeBenchRecords({dir.string()}, &joined, &records);
  ASSERT_EQ(joined.targets.size(), 2u);
  WriteBenchOutputs(merged.string(), joined, records);
  EXPECT_EQ(ReadText(merged / "summary.md"), summary);

  // Without targets, no section (and bench.json has no "targets").
  manifest.targets.clear();
  WriteBenchOutputs(dir.string(), manifest, records);
  EXPECT_EQ(ReadText(dir / "summary.md").find("## Targets"), std::string::npos);
  EXPECT_EQ(ReadText(dir / "bench.json").find("\"targets\":"), std::string::npos);

  // A spec's targets are checked with the spec's key path.
  try {
    LoadBenchSpec(WriteBench("bad_targets", SmallFigure4(1) + "targets: [{metric: acd.speed, "
                                                              "compare: '>', value: 1}]\n"));
    ADD_FAILURE() << "accepted an unknown metric";
  } catch (const InputError& error) {
    EXPECT_HAS(error.what(), "bad_targets.yaml: targets[0].metric: expected samplers or");
  }
}

TEST(BenchReport, CsvHeaderIsUnchanged) {
  EXPECT_EQ(BenchCsvHeader(),
            "case,world,family,passage_width,workspace_width,robot,sampler,planner,budget,"
            "time_limit,sample_budget,run,seed,status,solved,time_s,decomposition_s,samples,"
            "collision_checks,path_length,components,openings");
  BenchRecord r;
  r.case_index = 3;
  r.what = {"w", "f", 0.5, 10, "disc", "acd", "PRM", "2 s", 2, 0};
  r.run = 1;
  r.seed = 42;
  r.status = RunStatus::kSolved;
  r.solved = true;
  const std::string csv = BenchRecordsToCsv({r});
  EXPECT_HAS(csv, "\n3,w,f,0.5,10,disc,acd,PRM,2 s,2,0,1,42,solved,1,0,0,0,0,0,0,0\n");
  const fs::path dir = Scratch("csv");
  std::ofstream(dir / "runs.csv") << csv;
  const std::vector<BenchRecord> back = ReadBenchRecordsCsv((dir / "runs.csv").string());
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(BenchRecordsToCsv(back), csv);
  std::ofstream(dir / "bad.csv") << BenchCsvHeader()
                                 << "\n3,w,f,wide,10,disc,acd,PRM,2 s,2,0,1,"
                                    "42,solved,1,0,0,0,0,0,0,0\n";
  try {
    ReadBenchRecordsCsv((dir / "bad.csv").string());
    ADD_FAILURE();
  } catch (const InputError& error) {
    EXPECT_HAS(error.what(), "bad.csv:2: column passage_width: cannot read 'wide'");
  }
}

TEST(BenchReport, OmplLogLoadsInOmplBenchmarkStatistics) {
  const BenchSpec spec = LoadBenchSpec(WriteBench("log", SmallFigure4(2)));
  const fs::path dir = Scratch("log");
  const BenchRunOutcome outcome = RunBench(spec);
  WriteBenchOutputs(dir.string(), ManifestOf(spec, "1/1"), outcome.records);
  const std::string log = ReadText(dir / BenchOmplLogName("demo"));

  // Structure (OMPL's benchmark log grammar): header lines, 3 planners of 2 runs.
  EXPECT_EQ(log.rfind("OMPL version ", 0), 0u);
  EXPECT_HAS(log, "\nExperiment small.demo\n");
  EXPECT_HAS(log, "\n3 planners\n");
  EXPECT_HAS(log, "\nPRM [acd] point, 200 samples\n");
  EXPECT_HAS(log, "\ncollision checks INTEGER\n");
  EXPECT_HAS(log, "\ndecomposition time REAL\n");
  EXPECT_HAS(log, "\n2 runs\n");

  const char* tool = "/usr/bin/ompl_benchmark_statistics";
  if (access(tool, X_OK) != 0) {
    GTEST_SKIP() << tool << " is missing (Debian package ompl-demos); checked the structure only";
  }
  const fs::path db = dir / "bench.db";
  const std::string command = std::string(tool) + " '" + (dir / BenchOmplLogName("demo")).string() +
                              "' -d '" + db.string() + "' > '" + (dir / "stats.txt").string() +
                              "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << ReadText(dir / "stats.txt");
  const std::string query =
      "/usr/bin/python3 -c \"import sqlite3; c = sqlite3.connect('" + db.string() +
      "'); print(c.execute('select count(*), sum(solved), min(collision_checks) > 0, "
      "count(decomposition_time) from runs').fetchone())\" > '" +
      (dir / "query.txt").string() + "'";
  ASSERT_EQ(std::system(query.c_str()), 0);
  EXPECT_HAS(ReadText(dir / "query.txt"), "(6, ");
}

/// Runs the acdplan binary; its exit status.
int Acdplan(const std::string& arguments, const fs::path& output) {
  const std::string command =
      acdplan::test::AcdplanBinary() + " " + arguments + " > '" + output.string() + "' 2>&1";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

TEST(BenchCli, BadInputExitsTwoWithTheKeyPath) {
  const fs::path dir = Scratch("cli_bad");
  const std::string bad = WriteBench(
      "cli_bad",
      kWorlds + "cases:\n  - {samplers: [acd], planners: [EST], budgets: [{samples: 5}]}\n");
  EXPECT_EQ(Acdplan("bench '" + bad + "' --out '" + (dir / "out").string() + "'", dir / "o.txt"),
            2);
  EXPECT_HAS(ReadText(dir / "o.txt"), "cli_bad.yaml: cases[0].budgets[0].samples:");
  EXPECT_FALSE(fs::exists(dir / "out" / "runs.csv"));
  EXPECT_EQ(Acdplan("bench '" + bad + "' --shard 3/2", dir / "o2.txt"), 2);
  EXPECT_EQ(Acdplan("bench-merge '" + (dir / "nowhere").string() + "'", dir / "o3.txt"), 2);
  EXPECT_HAS(ReadText(dir / "o3.txt"), "bench.json: cannot read the file");
}

// What the file says that is read but worth a word reaches stderr: its own warnings (the
// older spelling tau_rel) and its worlds' (a map's yaw left out), once each.
TEST(BenchCli, PrintsTheWarningsOfTheFileAndItsWorlds) {
  const fs::path dir = Scratch("cli_warnings");
  std::ofstream(dir / "map.pgm") << "P2\n4 4\n255\n255 255 255 255\n255 0 0 255\n"
                                    "255 255 255 255\n255 255 255 255\n";
  std::ofstream(dir / "map.yaml") << "image: map.pgm\nresolution: 1\norigin: [0, 0, 0.25]\n";
  const std::string spec = WriteBench("cli_warnings",
                                      "name: w\nacd: {tau_rel: 0.05}\nworlds:\n"
                                      "  - {name: a, workspace: '" +
                                          (dir / "map.yaml").string() +
                                          "', start: [0.5, 0.5], goal: [3.5, 3.5]}\n"
                                          "  - {name: b, workspace: '" +
                                          (dir / "map.yaml").string() +
                                          "', start: [0.5, 0.5], goal: [3.5, 0.5]}\n"
                                          "cases:\n  - {samplers: [uniform], planners: [PRM], "
                                          "budgets: [{samples: 20}]}\n");
  EXPECT_EQ(
      Acdplan("bench '" + spec + "' --runs 1 --no-plots --out '" + (dir / "out").string() + "'",
              dir / "o.txt"),
      0);
  const std::string out = ReadText(dir / "o.txt");
  EXPECT_HAS(out, "acdplan: warning: " + spec + ": acd.tau_rel: read as tau_diag");
  const std::string yaw = "acdplan: warning: " + (dir / "map.yaml").string() +
                          ": origin: yaw 0.25 left out: the map is read unrotated";
  EXPECT_HAS(out, yaw);
  EXPECT_EQ(out.find(yaw), out.rfind(yaw)) << out;  // Two worlds, one file: said once.
}

// A Moving AI problem is a world: the .scen file and the problem's number.
TEST(BenchSpec, TakesAMovingAiProblemAsAWorld) {
  const fs::path dir = Scratch("moving_ai");
  std::ofstream(dir / "maze.map") << "type octile\nheight 4\nwidth 5\nmap\n@@@@@\n@.@.@\n"
                                     "@...@\n@@@@@\n";
  std::ofstream(dir / "maze.map.scen") << "version 1\n0\tmaze.map\t5\t4\t1\t1\t3\t1\t3.41\n";
  const std::string scen = (dir / "maze.map.scen").string();
  const std::string cases =
      "cases:\n  - {samplers: [acd], planners: [PRM], budgets: [{samples: 50}]}\n";
  const BenchSpec spec = LoadBenchSpec(WriteBench(
      "moving_ai", "name: m\nworlds:\n  - {scenario: '" + scen + "', problem: 0}\n" + cases));
  ASSERT_EQ(spec.worlds.size(), 1u);
  EXPECT_EQ(spec.worlds[0].name, "maze.map_0");
  EXPECT_EQ(spec.worlds[0].scenario.start, (std::vector<double>{1.5, 2.5}));
  EXPECT_HAS(SpecErrorOf("name: m\nworlds:\n  - {scenario: '" + scen + "'}\n" + cases),
             "worlds[0].scenario: " + scen + ": holds 1 problem(s)");
  EXPECT_HAS(SpecErrorOf("name: m\nworlds:\n  - {scenario: '" + scen + "', problem: 1}\n" + cases),
             "problem 1 out of range 0..0");
  EXPECT_HAS(SpecErrorOf(kWorlds + "    problem: 0\n" + cases),
             "worlds[0].problem: only with a scenario");
  // A sweep over problems: one world each, of one family.
  std::ofstream(dir / "maze.map.scen", std::ios::app) << "1\tmaze.map\t5\t4\t3\t1\t1\t2\t2\n";
  const BenchSpec sweep =
      LoadBenchSpec(WriteBench("moving_ai", "name: m\nworlds:\n  - {scenario: '" + scen +
                                                "', problems: [1, 0]}\n"
                                                "  - {name: again, scenario: '" +
                                                scen + "', problems: [0]}\n" + cases));
  ASSERT_EQ(sweep.worlds.size(), 3u);
  EXPECT_EQ(sweep.worlds[0].name, "maze.map_1");
  EXPECT_EQ(sweep.worlds[0].scenario.goal, (std::vector<double>{1.5, 1.5}));
  EXPECT_EQ(sweep.worlds[1].name, "maze.map_0");
  EXPECT_EQ(sweep.worlds[0].family, "maze.map");
  EXPECT_EQ(sweep.worlds[1].family, "maze.map");
  EXPECT_EQ(sweep.worlds[2].name, "again_0");
  EXPECT_EQ(sweep.worlds[2].family, "again");
  EXPECT_HAS(
      SpecErrorOf("name: m\nworlds:\n  - {scenario: '" + scen + "', problems: []}\n" + cases),
      "worlds[0].problems: expected a non-empty list of problem numbers");
  EXPECT_HAS(
      SpecErrorOf("name: m\nworlds:\n  - {scenario: '" + scen + "', problems: [0, x]}\n" + cases),
      "worlds[0].problems[1]: expected an integer >= 0");
}

TEST(BenchCli, BenchCollisionNamesTheFlagOfABadPath) {
  const fs::path dir = Scratch("cli_collision");
  EXPECT_EQ(
      Acdplan("bench-collision --poses 1 --points 1 --mesh-dir /nowhere/meshes", dir / "o.txt"), 2);
  EXPECT_HAS(ReadText(dir / "o.txt"), "--mesh-dir /nowhere/meshes: not a folder");
  const std::string bad =
      WriteBench("collision_targets", "targets: [{metric: hulls_speed, compare: '>', value: 1}]\n");
  EXPECT_EQ(Acdplan("bench-collision --poses 1 --points 1 --mesh-dir '' --targets '" + bad + "'",
                    dir / "o2.txt"),
            2);
  EXPECT_HAS(ReadText(dir / "o2.txt"),
             "collision_targets.yaml: targets[0].metric: unknown metric 'hulls_speed'");
}

TEST(BenchCli, BenchCollisionRunsOnlyTheMeshesOfMeshes) {
  const fs::path dir = Scratch("cli_collision_meshes");
  const std::string meshes = acdplan::test::DataDir() + "/meshes/vhacd";
  EXPECT_EQ(Acdplan("bench-collision --poses 2 --points 2 --mesh-dir '" + meshes +
                        "' --meshes cube.obj,cube-notch.obj",
                    dir / "o.txt"),
            0);
  const std::string out = ReadText(dir / "o.txt");
  EXPECT_HAS(out, "| cube/mesh |");
  EXPECT_HAS(out, "| cube-notch/mesh |");
  EXPECT_EQ(out.find("torus1/mesh"), std::string::npos);
}

TEST(BenchCli, CtrlCWritesTheFinishedRunsAndExits130) {
  // Time budgets on a world where uniform rarely solves: each run lasts about its budget, so the
  // bench is still running when the signal comes (the outcome checks hold either way).
  const fs::path dir = Scratch("cli_sigint");
  const std::string spec = WriteBench(
      "cli_sigint", "name: sigint\nruns: 40\nworlds:\n  - scenario: " + kConfigs +
                        "/demo.yaml\ncases:\n  - {samplers: [bridge], planners: [RRT], budgets: "
                        "[{time_limit: 0.5}]}\n");
  const std::string binary = acdplan::test::AcdplanBinary();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string out = (dir / "out").string();
    const std::string log = (dir / "log.txt").string();
    freopen(log.c_str(), "w", stderr);
    freopen(log.c_str(), "a", stdout);
    execl(binary.c_str(), binary.c_str(), "bench", spec.c_str(), "--out", out.c_str(), "--no-plots",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // The signal goes once the bench has said it started, which it does after installing its
  // handler (a fixed delay raced with a slow start-up under the sanitizers on a loaded machine).
  const std::string started = "bench sigint:";
  int status = 0;
  bool said = false;
  for (int waited = 0; waited < 6000 && !said; ++waited) {  // at most 300 s
    said = ReadText(dir / "log.txt").find(started) != std::string::npos;
    if (!said) {
      ASSERT_EQ(waitpid(pid, &status, WNOHANG), 0) << "the bench ended before it started:\n"
                                                   << ReadText(dir / "log.txt");
      usleep(50000);
    }
  }
  if (said) sleep(1);  // a few runs finish first
  kill(pid, SIGINT);
  ASSERT_TRUE(said) << "no '" << started << "' from the bench in 300 s";
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  const int code = WEXITSTATUS(status);
  EXPECT_TRUE(code == 130 || code == 0) << code << "\n" << ReadText(dir / "log.txt");
  // Whatever finished is written, and every output agrees on it.
  const std::vector<BenchRecord> records = ReadBenchRecordsCsv((dir / "out" / "runs.csv").string());
  const nlohmann::json results = nlohmann::json::parse(ReadText(dir / "out" / "results.json"));
  int runs = 0;
  for (const auto& c : results["cases"]) runs += c["runs"].get<int>();
  EXPECT_EQ(static_cast<size_t>(runs), records.size());
  const BenchManifest manifest = ReadBenchManifest((dir / "out" / "bench.json").string());
  EXPECT_EQ(manifest.interrupted, code == 130);
  if (code == 130) {
    EXPECT_LT(records.size(), 40u);
  }
  EXPECT_HAS(ReadText(dir / "out" / "summary.md"), "# Benchmark `sigint`");
}

}  // namespace
}  // namespace acdplan::bench
