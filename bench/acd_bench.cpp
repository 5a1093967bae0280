// The 2D ACD benchmark: see bench/acd_bench.h and tools/acd_bench.md.

#include "bench/acd_bench.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <list>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/concavity_measure.h"
#include "acd/decompose2d.h"
#include "acd/decomposition2d.h"
#include "acd/decomposition_io.h"
#include "acd/polygon2d.h"
#include "acd/read_polygons.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/stopwatch.h"
#include "bench/time_runs.h"

namespace acdplan::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using PartitionTraits = CGAL::Partition_traits_2<Kernel>;
using CgalPoint = PartitionTraits::Point_2;
using CgalPolygon = PartitionTraits::Polygon_2;

/// The default inputs, relative to the acd2d data folder.
// clang-format off
const std::vector<std::string> kDefaultInputs = {
    "nazca/nazca_monkey.poly", "nazca/nazca_monkey_2.poly", "nazca/nazca_heron.poly",
    "neuron/neuron.poly",
    "simple1.poly", "simple2.poly", "simple3.poly", "simple4.poly",
    "simple5.poly", "simple6.poly", "simple7.poly", "simple8.poly",
    "hole1.poly", "hole2.poly", "hole3.poly", "hole4.poly", "hole5.poly",
    "torus1.poly", "torus2.poly", "dragon.poly", "mammoth.poly", "texas.poly", "taiwan.poly",
    "batlogo.poly", "BarbedThing.poly", "fisheye.poly",
    "star/star1.poly", "star/star2.poly", "star/star3.poly",
    "star/star4.poly", "star/star5.poly", "star/star6.poly"};
// clang-format on

const std::vector<acd::ConcavityMeasure> kMeasures = {
    acd::ConcavityMeasure::kStraightLine, acd::ConcavityMeasure::kShortestPath,
    acd::ConcavityMeasure::kHybrid1, acd::ConcavityMeasure::kHybrid2};

const char* const kCgalApprox = "cgal-approx";
const char* const kCgalGreene = "cgal-greene";
const char* const kCgalOptimal = "cgal-optimal";

/// One polygon file, read and prepared.
struct BenchInput {
  std::string name;  ///< As shown in the table (relative to the data folder for defaults).
  std::vector<acd::Polygon2d> polygons;
  double radius = 0.0;  ///< Largest reference radius as written in the file.
  int vertices = 0;
  int notches = 0;
  int holes = 0;
};

CgalPoint ToCgal(const acd::Point2d& p) { return CgalPoint(p.x(), p.y()); }

/// Area of the convex hull of `points` (any order).
double HullArea(const std::vector<CgalPoint>& points) {
  std::vector<CgalPoint> hull;
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  if (hull.size() < 3) return 0.0;
  return std::abs(CGAL::polygon_area_2(hull.begin(), hull.end(), Kernel()));
}

/// Eqn. 4.4 for our components: sum of areas / sum of hull areas, hulls recomputed here the
/// same way as for CGAL's pieces so both columns are measured alike.
double Convexity(const acd::Decomposition2d& decomposition) {
  double area = 0.0, hull_area = 0.0;
  for (const acd::Component2d& component : decomposition.components) {
    area += acd::Area(component.polygon);
    std::vector<CgalPoint> points;
    for (const acd::Point2d& p : component.polygon.outer) points.push_back(ToCgal(p));
    hull_area += HullArea(points);
  }
  return hull_area > 0.0 ? area / hull_area : 1.0;
}

/// Eqn. 4.4 for CGAL's pieces (1.0 up to rounding for a convex partition).
double Convexity(const std::vector<CgalPolygon>& pieces) {
  double area = 0.0, hull_area = 0.0;
  for (const CgalPolygon& piece : pieces) {
    area += std::abs(CGAL::to_double(piece.area()));
    hull_area += HullArea(std::vector<CgalPoint>(piece.vertices_begin(), piece.vertices_end()));
  }
  return hull_area > 0.0 ? area / hull_area : 1.0;
}

/// Why CGAL's `pieces` are not a convex partition of `input`'s outer rings, or "" if they are
/// (up to rounding). CGAL checks its postcondition only in debug builds, so a Release benchmark
/// checks here (untimed), and the targets do not compare against a wrong answer.
std::string PartitionProblem(const BenchInput& input, const std::vector<CgalPolygon>& pieces) {
  double input_area = 0.0, pieces_area = 0.0;
  for (const acd::Polygon2d& polygon : input.polygons) input_area += acd::Area(polygon);
  for (size_t i = 0; i < pieces.size(); ++i) {
    const CgalPolygon& piece = pieces[i];
    if (!CGAL::is_convex_2(piece.vertices_begin(), piece.vertices_end(), Kernel())) {
      return "invalid output: piece " + std::to_string(i) + " (" + std::to_string(piece.size()) +
             " vertices) is not convex";
    }
    pieces_area += std::abs(CGAL::to_double(piece.area()));
  }
  if (std::abs(pieces_area - input_area) > 1e-9 * input_area) {
    return "invalid output: pieces' area " + FormatSignificant(pieces_area, 10) + " != polygon's " +
           FormatSignificant(input_area, 10);
  }
  return "";
}

/// Reflex vertices of a prepared polygon (outer ring ccw, holes cw: a right turn is reflex).
int CountNotches(const acd::Polygon2d& polygon) {
  int notches = 0;
  auto count = [&notches](const acd::Ring2d& ring) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const CgalPoint a = ToCgal(ring[(i + n - 1) % n]), b = ToCgal(ring[i]),
                      c = ToCgal(ring[(i + 1) % n]);
      if (CGAL::orientation(a, b, c) == CGAL::RIGHT_TURN) ++notches;
    }
  };
  count(polygon.outer);
  for (const acd::Ring2d& hole : polygon.holes) count(hole);
  return notches;
}

BenchInput LoadInput(const std::string& name, const std::string& path) {
  BenchInput input;
  input.name = name;
  std::vector<double> radii;
  input.polygons = acd::ReadPolygons(path, &radii);
  // One tau for the whole file, relative to its largest polygon (as `acdplan decompose`).
  for (double radius : radii) input.radius = std::max(input.radius, radius);
  for (const acd::Polygon2d& polygon : input.polygons) {
    input.vertices += acd::VertexCount(polygon);
    input.notches += CountNotches(polygon);
    input.holes += static_cast<int>(polygon.holes.size());
  }
  return input;
}

/// `path` relative to `data_dir` when it lies inside it (as the default list is shown), else as
/// given.
std::string DisplayName(const std::string& path, const std::string& data_dir) {
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::weakly_canonical(path, ec);
  const std::filesystem::path dir = std::filesystem::weakly_canonical(data_dir, ec);
  if (ec) return path;
  const std::filesystem::path relative = file.lexically_relative(dir);
  if (relative.empty() || *relative.begin() == "..") return path;
  return relative.string();
}

AcdBenchRow RowFor(const BenchInput& input, const std::string& method) {
  AcdBenchRow row;
  row.polygon = input.name;
  row.vertices = input.vertices;
  row.notches = input.notches;
  row.holes = input.holes;
  row.method = method;
  return row;
}

std::string MethodName(acd::ConcavityMeasure measure) { return "acd-" + acd::ToString(measure); }

/// Runs our decomposition with every measure at `tau_rel`; adds one row each. Returns false
/// if a decomposition threw or failed its check.
bool BenchOurs(const BenchInput& input, double tau_rel, const AcdBenchOptions& args,
               std::vector<AcdBenchRow>* rows, std::vector<std::string>* problems) {
  bool ok = true;
  for (acd::ConcavityMeasure measure : kMeasures) {
    AcdBenchRow row = RowFor(input, MethodName(measure));
    acd::Decompose2dOptions options;
    options.measure = measure;
    options.tau = tau_rel * input.radius;
    row.tau_rel = tau_rel;
    row.tau = options.tau;
    try {
      auto timed = TimeRuns([&] { return acd::Decompose2d(input.polygons, options); }, args.repeats,
                            args.cell_budget_ms, 3);
      row.components = static_cast<int>(timed.result.components.size());
      row.convexity = Convexity(timed.result);
      row.median_ms = timed.median_ms;
      row.runs = timed.runs;
      if (args.check) {
        const acd::DecompositionCheck check = acd::CheckDecomposition(input.polygons, timed.result);
        if (check.ok()) {
          row.check = "ok";
        } else {
          ok = false;
          row.check = "FAIL (" + std::to_string(check.problems.size()) + ")";
          for (const std::string& problem : check.problems) {
            problems->push_back(input.name + ", tau_rel " + FormatSignificant(tau_rel, 6) + ", " +
                                row.method + ": check: " + problem);
          }
        }
      }
    } catch (const std::exception& error) {
      ok = false;
      row.note = std::string("failed: ") + error.what();
      problems->push_back(input.name + ", tau_rel " + FormatSignificant(tau_rel, 6) + ", " +
                          row.method + ": threw: " + error.what());
    }
    rows->push_back(row);
  }
  return ok;
}

/// `ring` rotated to start at its lexicographically smallest vertex, which is convex. CGAL
/// 5.5.1's optimal_convex_partition_2 returns pieces that are neither simple nor convex when the
/// first vertex is reflex (CGAL issue #9322, fixed by the same rotation in CGAL 6.3). Its output
/// for acd2d/mammoth.poly stays invalid even so (93 pieces, one of 66 vertices not convex; the
/// targets bound the optimum from below there).
std::vector<CgalPoint> StartAtConvexVertex(const std::vector<CgalPoint>& ring) {
  std::vector<CgalPoint> rotated = ring;
  std::rotate(rotated.begin(), std::min_element(rotated.begin(), rotated.end()), rotated.end());
  return rotated;
}

/// Runs CGAL's three partitions (independent of tau, so once per polygon).
void BenchCgal(const BenchInput& input, const AcdBenchOptions& args,
               std::vector<AcdBenchRow>* rows) {
  std::vector<std::vector<CgalPoint>> rings;
  for (const acd::Polygon2d& polygon : input.polygons) {
    std::vector<CgalPoint> ring;
    for (const acd::Point2d& p : polygon.outer) ring.push_back(ToCgal(p));
    rings.push_back(std::move(ring));
  }
  using PartitionFunction = void (*)(const std::vector<CgalPoint>&, std::list<CgalPolygon>*);
  const std::pair<const char*, PartitionFunction> methods[] = {
      {kCgalApprox,
       [](const std::vector<CgalPoint>& ring, std::list<CgalPolygon>* out) {
         CGAL::approx_convex_partition_2(ring.begin(), ring.end(), std::back_inserter(*out),
                                         PartitionTraits());
       }},
      {kCgalGreene,
       [](const std::vector<CgalPoint>& ring, std::list<CgalPolygon>* out) {
         CGAL::greene_approx_convex_partition_2(ring.begin(), ring.end(), std::back_inserter(*out),
                                                PartitionTraits());
       }},
      {kCgalOptimal,
       [](const std::vector<CgalPoint>& ring, std::list<CgalPolygon>* out) {
         const std::vector<CgalPoint> rotated = StartAtConvexVertex(ring);
         CGAL::optimal_convex_partition_2(rotated.begin(), rotated.end(), std::back_inserter(*out),
                                          PartitionTraits());
       }},
  };
  for (const auto& entry : methods) {
    // Not a structured binding: C++17 lambdas cannot capture one (clang rejects it).
    const char* method = entry.first;
    const auto& partition = entry.second;
    AcdBenchRow row = RowFor(input, method);
    if (input.holes > 0) {
      row.note = "n/a (holes)";
    } else if (method == kCgalOptimal && input.vertices > args.optimal_max_vertices) {
      row.note = "n/a (n > " + std::to_string(args.optimal_max_vertices) + ")";
    } else {
      try {
        auto timed = TimeRuns(
            [&] {
              std::list<CgalPolygon> pieces;
              for (const std::vector<CgalPoint>& ring : rings) partition(ring, &pieces);
              return pieces;
            },
            args.repeats, args.cell_budget_ms, 3);
        const std::vector<CgalPolygon> pieces(timed.result.begin(), timed.result.end());
        row.components = static_cast<int>(pieces.size());
        row.convexity = Convexity(pieces);
        row.note = PartitionProblem(input, pieces);
        row.median_ms = timed.median_ms;
        row.runs = timed.runs;
      } catch (const std::exception& error) {
        row.note = std::string("failed: ") + error.what();
      }
    }
    rows->push_back(row);
  }
}

std::string FormatMs(double ms) {
  if (ms < 10.0) return FormatFixed(ms, 3);
  if (ms < 1000.0) return FormatFixed(ms, 1);
  return FormatFixed(ms, 0);
}

std::string MarkdownTable(const std::vector<AcdBenchRow>& rows, bool with_check) {
  std::ostringstream out;
  out << "| polygon | n | notches | holes | tau_rel | tau | method | components | convexity "
         "| median ms | runs |"
      << (with_check ? " check |" : "") << "\n";
  out << "|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|" << (with_check ? "---|" : "")
      << "\n";
  std::string previous;
  for (const AcdBenchRow& row : rows) {
    // The polygon's figures only on its first line, so groups stand out.
    const bool first = row.polygon != previous;
    previous = row.polygon;
    out << "| " << (first ? row.polygon : "") << " | "
        << (first ? std::to_string(row.vertices) : "") << " | "
        << (first ? std::to_string(row.notches) : "") << " | "
        << (first ? std::to_string(row.holes) : "") << " | "
        << (row.tau_rel ? FormatSignificant(*row.tau_rel, 6) : "—") << " | "
        << (row.tau ? FormatSignificant(*row.tau, 4) : "—") << " | " << row.method
        << (row.components && !row.note.empty() ? " **(invalid output)**" : "") << " | ";
    if (row.components) {
      out << *row.components << " | " << FormatFixed(row.convexity, 4) << " | "
          << FormatMs(row.median_ms) << " | " << row.runs << " |";
    } else {
      // The full message of a failure is in the problems list below the table.
      const bool failed = row.note.rfind("failed", 0) == 0;
      out << (failed ? "**failed**" : row.note) << " | | | |";
    }
    if (with_check) out << " " << row.check << " |";
    out << "\n";
  }
  return out.str();
}

using Json = nlohmann::ordered_json;  // Keys in the documented order.

template <typename T>
Json OrNull(bool present, const T& value) {
  return present ? Json(value) : Json(nullptr);
}

Json JsonRows(const std::vector<AcdBenchRow>& rows, bool with_check) {
  Json list = Json::array();
  for (const AcdBenchRow& row : rows) {
    const bool measured = row.components.has_value();
    Json item = {{"polygon", row.polygon},
                 {"vertices", row.vertices},
                 {"notches", row.notches},
                 {"holes", row.holes},
                 {"tau_rel", OrNull(row.tau_rel.has_value(), row.tau_rel.value_or(0.0))},
                 {"tau", OrNull(row.tau.has_value(), row.tau.value_or(0.0))},
                 {"method", row.method},
                 {"components", OrNull(measured, row.components.value_or(0))},
                 {"convexity", OrNull(measured, row.convexity)},
                 {"median_ms", OrNull(measured, row.median_ms)},
                 {"runs", row.runs}};
    if (!row.note.empty()) item["note"] = row.note;
    if (with_check && !row.check.empty()) item["check"] = row.check;
    list.push_back(std::move(item));
  }
  return list;
}

std::string LoadAverage() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(file >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

}  // namespace

AcdBenchResult RunAcdBench(const AcdBenchOptions& args, std::ostream* progress) {
  std::vector<BenchInput> inputs;
  std::vector<std::string> skipped;
  if (args.files.empty()) {
    // The default list: files that do not load are skipped and listed (some acd2d files are
    // known to break the .poly rules).
    for (const std::string& entry : kDefaultInputs) {
      const std::string path = (std::filesystem::path(args.data_dir) / entry).string();
      try {
        inputs.push_back(LoadInput(entry, path));
      } catch (const std::exception& error) {
        skipped.push_back(entry + ": " + error.what());
      }
    }
  } else {
    // Files named by the user must all load, before any work (exit 2 otherwise).
    for (const std::string& path : args.files)
      inputs.push_back(LoadInput(DisplayName(path, args.data_dir), path));
  }
  const std::vector<double> tau_rels =
      args.tau_rels.empty() ? std::vector<double>{0.01, 0.0} : args.tau_rels;
  AcdBenchResult result;
  result.skipped = skipped;
  result.load_before = LoadAverage();
  std::vector<AcdBenchRow>& rows = result.rows;
  std::vector<std::string>& problems = result.problems;
  for (const BenchInput& input : inputs) {
    if (progress) {
      *progress << "acd_bench: " << input.name << " (n " << input.vertices << ", holes "
                << input.holes << ")" << std::endl;
    }
    for (double tau_rel : tau_rels) {
      result.ok = BenchOurs(input, tau_rel, args, &rows, &problems) && result.ok;
    }
    BenchCgal(input, args, &rows);
  }
  result.load_after = LoadAverage();
  for (const AcdBenchRow& row : rows) {
    if (row.method.rfind("cgal", 0) == 0 &&
        (row.note.rfind("failed", 0) == 0 || row.note.rfind("invalid", 0) == 0)) {
      problems.push_back(row.polygon + ", " + row.method + ": " + row.note);
    }
  }
  return result;
}

std::string AcdBenchMarkdown(const AcdBenchResult& result, const AcdBenchOptions& args,
                             const std::vector<Target>& targets) {
  const std::vector<AcdBenchRow>& rows = result.rows;

  std::ostringstream out;
  out << "# acd_bench\n\n";
  out << "Median wall time of Decompose2d() (SL, SP, H1, H2; tau = tau_rel x the polygon's "
         "reference radius as written in the file) and of CGAL "
      << CGAL_STRINGIZE(CGAL_VERSION)
      << "'s partitions (no tolerance; simple polygons without holes), " << args.repeats
      << " runs per cell, or fewer (but >= " << std::min(3, args.repeats)
      << ") once a cell's runs have used " << FormatSignificant(args.cell_budget_ms, 6)
      << " ms; CGAL's optimal partition only for n <= " << args.optimal_max_vertices
      << ". Convexity is Eqn. 4.4 (sum of areas / sum of hull areas).\n\n";
  out << MarkdownTable(rows, args.check) << "\n";
  if (!result.skipped.empty()) {
    out << "Skipped (did not load):\n\n";
    for (const std::string& line : result.skipped) out << "- " << line << "\n";
    out << "\n";
  }
  const std::vector<std::string>& problems = result.problems;
  out << "Problems (our decompositions that threw"
      << (args.check ? " or failed CheckDecomposition" : "")
      << "; CGAL failures): " << (problems.empty() ? "none" : std::to_string(problems.size()))
      << "\n\n";
  for (const std::string& problem : problems) out << "- " << problem << "\n";
  if (!problems.empty()) out << "\n";
  if (!targets.empty()) {
    const std::vector<TargetRow> target_rows = AcdBenchTargetRows(rows);
    out << "## Targets\n\n"
        << TargetChecksMarkdown(CheckTargets(targets, target_rows),
                                {"polygon", "tau_rel", "method"})
        << "\n";
  }
  out << "Machine: " << std::thread::hardware_concurrency()
      << " hardware threads (std::thread::hardware_concurrency); load average "
      << result.load_before << " before, " << result.load_after << " after the runs.\n";
  return out.str();
}

std::string AcdBenchJson(const AcdBenchResult& result, const AcdBenchOptions& options) {
  return JsonRows(result.rows, options.check).dump(1) + "\n";
}

const std::vector<std::string>& AcdBenchDefaultInputs() { return kDefaultInputs; }

namespace {

const char* const kAcdMetrics[] = {"components", "convexity", "median_ms", "runs",
                                   "convex_lower_bound"};

std::string CheckAcdMetric(const std::string& metric) {
  std::string name = metric;
  for (const char* peer : {kCgalApprox, kCgalGreene, kCgalOptimal}) {
    if (metric == std::string(peer) + ".components") return "";
  }
  for (const char* known : kAcdMetrics) {
    if (name == known) return "";
  }
  return "unknown metric '" + metric +
         "' (expected one of: components, convexity, median_ms, runs, convex_lower_bound, " +
         kCgalApprox + ".components, " + kCgalGreene + ".components, " + kCgalOptimal +
         ".components)";
}

}  // namespace

const TargetVocabulary& AcdBenchTargetVocabulary() {
  static const TargetVocabulary vocabulary{{"polygon", "file", "method", "tau_rel"},
                                           &CheckAcdMetric};
  return vocabulary;
}

std::vector<TargetRow> AcdBenchTargetRows(const std::vector<AcdBenchRow>& rows) {
  std::vector<TargetRow> out;
  for (const AcdBenchRow& row : rows) {
    const bool ours = row.tau_rel.has_value();
    if (!ours && !row.components) continue;  // A CGAL method that did not run.
    TargetRow t;
    t.labels["polygon"] = row.polygon;
    t.labels["file"] = std::filesystem::path(row.polygon).filename().string();
    t.labels["method"] = row.method;
    if (ours) t.labels["tau_rel"] = FormatSignificant(*row.tau_rel, 6);
    const double nan = std::nan("");
    t.metrics["components"] = row.components ? *row.components : nan;
    t.metrics["convexity"] = row.components ? row.convexity : nan;
    t.metrics["median_ms"] = row.components ? row.median_ms : nan;
    t.metrics["runs"] = row.runs;
    if (ours && row.holes == 0) {
      // Any convex partition of polygons without holes, Steiner points allowed, has at least
      // ceil(r / 2) + 1 pieces for r reflex vertices: a cut resolves at most two of them.
      // It bounds the optimum where CGAL's optimal partition cannot be used.
      t.metrics["convex_lower_bound"] = (row.notches + 1) / 2 + 1;
    }
    if (ours) {
      // The peers on the same polygon, where they ran with a valid output.
      for (const AcdBenchRow& peer : rows) {
        if (peer.polygon == row.polygon && !peer.tau_rel && peer.components && peer.note.empty()) {
          t.metrics[peer.method + ".components"] = *peer.components;
        }
      }
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace acdplan::bench
