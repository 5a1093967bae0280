// The 2D ACD benchmark on small polygons: its rows, CGAL's partitions beside ours, and the
// target rows with the optimum's lower bound.

#include "bench/acd_bench.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/data_paths.h"

namespace acdplan::bench {
namespace {

std::string Polygon(const std::string& name) {
  return acdplan::test::DataDir() + "/polygons/acd2d/" + name;
}

const TargetRow* Find(const std::vector<TargetRow>& rows, const std::string& method,
                      const std::string& tau_rel) {
  for (const TargetRow& row : rows) {
    auto m = row.labels.find("method");
    auto t = row.labels.find("tau_rel");
    if (m != row.labels.end() && m->second == method &&
        (tau_rel.empty() ? t == row.labels.end() : t != row.labels.end() && t->second == tau_rel)) {
      return &row;
    }
  }
  return nullptr;
}

TEST(AcdBench, BarbedThingAtTauZeroBesideCgalsPartitionsWithTheLowerBound) {
  AcdBenchOptions options;
  options.files = {Polygon("BarbedThing.poly")};
  options.tau_rels = {0.0};
  options.repeats = 1;
  options.check = true;
  const AcdBenchResult result = RunAcdBench(options);
  ASSERT_TRUE(result.ok);
  const std::vector<TargetRow> rows = AcdBenchTargetRows(result.rows);

  const TargetRow* sl = Find(rows, "acd-sl", "0");
  const TargetRow* optimal = Find(rows, "cgal-optimal", "");
  ASSERT_NE(sl, nullptr);
  ASSERT_NE(optimal, nullptr);  // 31 vertices: within the default n <= 150.
  const int notches = result.rows.front().notches;
  EXPECT_GT(notches, 0);
  // ceil(r / 2) + 1 bounds every convex partition from below, CGAL's optimal one included.
  const double bound = sl->metrics.at("convex_lower_bound");
  EXPECT_EQ(bound, std::ceil(notches / 2.0) + 1);
  EXPECT_LE(bound, optimal->metrics.at("components"));
  EXPECT_LE(optimal->metrics.at("components"), sl->metrics.at("components"));
  EXPECT_EQ(sl->metrics.at("cgal-optimal.components"), optimal->metrics.at("components"));
  // CGAL's rows carry no bound and no peers.
  EXPECT_EQ(optimal->metrics.count("convex_lower_bound"), 0u);
}

TEST(AcdBench, PolygonsWithHolesHaveNoLowerBound) {
  AcdBenchOptions options;
  options.files = {Polygon("hole1.poly")};  // an outer ring with a hole
  options.tau_rels = {0.0};
  options.repeats = 1;
  const AcdBenchResult result = RunAcdBench(options);
  ASSERT_FALSE(result.rows.empty());
  ASSERT_GT(result.rows.front().holes, 0);
  for (const TargetRow& row : AcdBenchTargetRows(result.rows)) {
    EXPECT_EQ(row.metrics.count("convex_lower_bound"), 0u);
  }
}

}  // namespace
}  // namespace acdplan::bench
