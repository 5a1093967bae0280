// acd_bench: the 2D ACD benchmark (issue 2). Runs our Decompose2d() with each concavity measure
// and CGAL's convex partitions (the peer measured in the same run, DESIGN.md) on a list of
// polygon files, and prints a Markdown table, a JSON copy of it, and the targets judged
// from the measured rows. See tools/acd_bench.md.
//
// Exit status: 0 done; 2 bad usage or an unreadable file named on the command line; 1 one of
// our decompositions threw or failed --check (the table is still complete and says where).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/partition_2.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <list>
#include <nlohmann/json.hpp>
#include <optional>
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
#include "base/input_error.h"
#include "acd/polygon2d.h"
#include "acd/read_polygons.h"

#ifndef ACDPLAN_BENCH_DATA_DIR
#define ACDPLAN_BENCH_DATA_DIR "."
#endif

namespace {

namespace acd = acdplan::acd;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using PartitionTraits = CGAL::Partition_traits_2<Kernel>;
using CgalPoint = PartitionTraits::Point_2;
using CgalPolygon = PartitionTraits::Polygon_2;

/// The default inputs, relative to the acd2d data folder (issue 2's benchmark list).
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

/// What the benchmark was asked to do.
struct BenchArguments {
  std::vector<std::string> files;  ///< Empty: kDefaultInputs under `data_dir`.
  std::vector<double> tau_rels;    ///< Empty: {0.01, 0}.
  int repeats = 21;                ///< Timed runs per cell (fewer when a cell is slow).
  double cell_budget_ms = 2000.0;  ///< Stop repeating a cell after this much time, >= 3 runs.
  int optimal_max_vertices = 150;  ///< CGAL's O(n^4) optimal partition only up to this n.
  std::string json_path;
  std::string data_dir = ACDPLAN_BENCH_DATA_DIR;
  bool check = false;
};

/// One polygon file, read and prepared.
struct BenchInput {
  std::string name;  ///< As shown in the table (relative to the data folder for defaults).
  std::vector<acd::Polygon2d> polygons;
  double radius = 0.0;  ///< Largest reference radius as written in the file.
  int vertices = 0;
  int notches = 0;
  int holes = 0;
};

/// One line of the table (and one object of the JSON list).
struct Row {
  std::string polygon;
  int vertices = 0, notches = 0, holes = 0;
  std::optional<double> tau_rel, tau;  ///< Empty for CGAL's partitions (no tolerance).
  std::string method;
  std::optional<int> components;  ///< Empty when the method did not run (see `note`).
  double convexity = 0.0;
  double median_ms = 0.0;
  int runs = 0;
  std::string note;   ///< "n/a (holes)", "n/a (n > 150)", "failed: ...".
  std::string check;  ///< With --check on our rows: "ok" or "FAIL (k)".
};

/// Median time of repeated runs and the result of the last one.
template <typename Result>
struct Timed {
  Result result;
  double median_ms = 0.0;
  int runs = 0;
};

/// Calls `run` up to `repeats` times and returns the median wall time. A slow cell stops once
/// `budget_ms` is spent and at least min(3, repeats) runs are done, so the whole benchmark
/// stays within minutes while fast cells still get many runs (the machine is shared and noisy).
/// The previous result is destroyed outside the timed region. Fast cells first run untimed for
/// kWarmUpMs: otherwise the first cells of a process run at the idle CPU clock (nazca_monkey SL
/// measured 1.26 ms as the first cell, 0.85 ms after a warm-up).
template <typename Run>
auto TimeRuns(Run&& run, int repeats, double budget_ms) {
  constexpr double kWarmUpMs = 100.0;
  using Result = decltype(run());
  Timed<Result> timed;
  std::vector<double> times;
  double total_ms = 0.0;
  const int min_runs = std::min(3, repeats);
  auto time_one = [&run, &timed]() {
    const auto start = std::chrono::steady_clock::now();
    Result result = run();
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    timed.result = std::move(result);
    return ms;
  };
  double warm_up_ms = time_one();
  if (warm_up_ms >= kWarmUpMs) {
    times.push_back(warm_up_ms);  // A slow cell: one cold run among seconds is noise.
    total_ms = warm_up_ms;
  }
  while (times.empty() && warm_up_ms < kWarmUpMs) warm_up_ms += time_one();
  while (static_cast<int>(times.size()) < repeats) {
    const double ms = time_one();
    times.push_back(ms);
    total_ms += ms;
    if (static_cast<int>(times.size()) >= min_runs && total_ms >= budget_ms) break;
  }
  std::sort(times.begin(), times.end());
  const size_t k = times.size();
  timed.median_ms = k % 2 == 1 ? times[k / 2] : 0.5 * (times[k / 2 - 1] + times[k / 2]);
  timed.runs = static_cast<int>(k);
  return timed;
}

std::string Format(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

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
    return "invalid output: pieces' area " + Format("%.10g", pieces_area) + " != polygon's " +
           Format("%.10g", input_area);
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

Row RowFor(const BenchInput& input, const std::string& method) {
  Row row;
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
bool BenchOurs(const BenchInput& input, double tau_rel, const BenchArguments& args,
               std::vector<Row>* rows, std::vector<std::string>* problems) {
  bool ok = true;
  for (acd::ConcavityMeasure measure : kMeasures) {
    Row row = RowFor(input, MethodName(measure));
    acd::Decompose2dOptions options;
    options.measure = measure;
    options.tau = tau_rel * input.radius;
    row.tau_rel = tau_rel;
    row.tau = options.tau;
    try {
      auto timed = TimeRuns([&] { return acd::Decompose2d(input.polygons, options); }, args.repeats,
                            args.cell_budget_ms);
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
            problems->push_back(input.name + ", tau_rel " + Format("%g", tau_rel) + ", " +
                                row.method + ": check: " + problem);
          }
        }
      }
    } catch (const std::exception& error) {
      ok = false;
      row.note = std::string("failed: ") + error.what();
      problems->push_back(input.name + ", tau_rel " + Format("%g", tau_rel) + ", " + row.method +
                          ": threw: " + error.what());
    }
    rows->push_back(row);
  }
  return ok;
}

/// Runs CGAL's three partitions (independent of tau, so once per polygon).
void BenchCgal(const BenchInput& input, const BenchArguments& args, std::vector<Row>* rows) {
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
         CGAL::optimal_convex_partition_2(ring.begin(), ring.end(), std::back_inserter(*out),
                                          PartitionTraits());
       }},
  };
  for (const auto& [method, partition] : methods) {
    Row row = RowFor(input, method);
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
            args.repeats, args.cell_budget_ms);
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
  if (ms < 10.0) return Format("%.3f", ms);
  if (ms < 1000.0) return Format("%.1f", ms);
  return Format("%.0f", ms);
}

std::string MarkdownTable(const std::vector<Row>& rows, bool with_check) {
  std::ostringstream out;
  out << "| polygon | n | notches | holes | tau_rel | tau | method | components | convexity "
         "| median ms | runs |"
      << (with_check ? " check |" : "") << "\n";
  out << "|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|" << (with_check ? "---|" : "")
      << "\n";
  std::string previous;
  for (const Row& row : rows) {
    // The polygon's figures only on its first line, so groups stand out.
    const bool first = row.polygon != previous;
    previous = row.polygon;
    out << "| " << (first ? row.polygon : "") << " | "
        << (first ? std::to_string(row.vertices) : "") << " | "
        << (first ? std::to_string(row.notches) : "") << " | "
        << (first ? std::to_string(row.holes) : "") << " | "
        << (row.tau_rel ? Format("%g", *row.tau_rel) : "—") << " | "
        << (row.tau ? Format("%.4g", *row.tau) : "—") << " | " << row.method
        << (row.components && !row.note.empty() ? " **(invalid output)**" : "") << " | ";
    if (row.components) {
      out << *row.components << " | " << Format("%.4f", row.convexity) << " | "
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

Json JsonRows(const std::vector<Row>& rows, bool with_check) {
  Json list = Json::array();
  for (const Row& row : rows) {
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

// ----- targets (issue 2) ---------------------------------------------------------------------

std::string BaseName(const std::string& name) {
  return std::filesystem::path(name).filename().string();
}

/// The row of `method` on the polygon whose file name is `base`, at `tau_rel` (empty for
/// CGAL), or nullptr if there is none. The row may be a failure or "n/a" (no `components`).
const Row* Find(const std::vector<Row>& rows, const std::string& base,
                std::optional<double> tau_rel, const std::string& method) {
  for (const Row& row : rows) {
    if (BaseName(row.polygon) == base && row.method == method &&
        row.tau_rel.has_value() == tau_rel.has_value() &&
        (!tau_rel || std::abs(*row.tau_rel - *tau_rel) < 1e-12)) {
      return &row;
    }
  }
  return nullptr;
}

std::string Verdict(bool pass) { return pass ? "**PASS**" : "**MISS**"; }

/// "<= 104 components in <= 5 ms" (either bound may be absent) for one row at tau_rel 0.01.
std::string CountAndTimeTarget(const std::vector<Row>& rows, const std::string& base,
                               acd::ConcavityMeasure measure, std::optional<int> max_components,
                               std::optional<double> max_ms) {
  std::string label = base + ", tau_rel 0.01, " + MethodName(measure) + ":";
  if (max_components) label += " <= " + std::to_string(*max_components) + " components";
  if (max_components && max_ms) label += " in";
  if (max_ms) label += " <= " + Format("%g", *max_ms) + " ms";
  const Row* row = Find(rows, base, 0.01, MethodName(measure));
  if (row == nullptr) return "- " + label + ": not measured (polygon or tau_rel 0.01 not run)";
  if (!row->components) return "- " + label + ": " + Verdict(false) + " — failed";
  const bool pass = (!max_components || *row->components <= *max_components) &&
                    (!max_ms || row->median_ms <= *max_ms);
  return "- " + label + ": " + Verdict(pass) + " — " + std::to_string(*row->components) +
         " components, " + FormatMs(row->median_ms) + " ms (median of " +
         std::to_string(row->runs) + " runs)";
}

/// One measure's outcome against a CGAL partition at tau = 0.
struct PeerComparison {
  int compared = 0;
  double worst = 0.0;  ///< Largest ours / peer component ratio.
  std::string worst_polygon;
  std::vector<std::string> misses;
  std::vector<std::string> excluded;  ///< Polygons where the peer's partition was invalid.
  bool Pass() const { return compared > 0 && misses.empty(); }
  std::string Summary(const std::string& peer) const {
    std::ostringstream line;
    line << compared - misses.size() << "/" << compared << " polygons";
    if (compared > 0) {
      line << ", worst ours / " << peer << " = " << Format("%.2f", worst) << " (" << worst_polygon
           << ")";
    }
    if (!misses.empty()) {
      line << "; misses:";
      for (size_t i = 0; i < misses.size(); ++i) line << (i ? ", " : " ") << misses[i];
    }
    if (!excluded.empty()) {
      line << "; not compared (" << peer << " output invalid):";
      for (size_t i = 0; i < excluded.size(); ++i) line << (i ? ", " : " ") << excluded[i];
    }
    return line.str();
  }
};

/// Compares `measure` at tau = 0 with `peer` on every polygon where both have a row and the
/// peer ran: pass when ours <= factor x peer (or ours < peer when `strict`). A decomposition of
/// ours that failed counts as a miss.
PeerComparison ComparePeer(const std::vector<Row>& rows, const std::vector<std::string>& polygons,
                           acd::ConcavityMeasure measure, const std::string& peer_method,
                           double factor, bool strict) {
  PeerComparison result;
  for (const std::string& polygon : polygons) {
    const std::string base = BaseName(polygon);
    const Row* ours = Find(rows, base, 0.0, MethodName(measure));
    const Row* peer = Find(rows, base, std::nullopt, peer_method);
    if (ours == nullptr || peer == nullptr || !peer->components) continue;
    if (!peer->note.empty()) {  // An invalid partition is no yardstick.
      result.excluded.push_back(polygon);
      continue;
    }
    ++result.compared;
    if (!ours->components) {
      result.misses.push_back(polygon + " failed");
      continue;
    }
    const int a = *ours->components, b = *peer->components;
    const double ratio = static_cast<double>(a) / b;
    if (ratio > result.worst) {
      result.worst = ratio;
      result.worst_polygon = polygon;
    }
    if (strict ? !(a < b) : !(a <= factor * b)) {
      std::string miss = polygon + " " + std::to_string(a) + " vs " + std::to_string(b);
      // Against a heuristic peer, say when no partition could have done better.
      const Row* optimal = Find(rows, base, std::nullopt, kCgalOptimal);
      if (peer_method != kCgalOptimal && optimal != nullptr && optimal->components &&
          optimal->note.empty()) {
        miss += " (optimal " + std::to_string(*optimal->components) + ")";
      }
      result.misses.push_back(miss);
    }
  }
  return result;
}

std::string TargetsSection(const std::vector<Row>& rows) {
  std::ostringstream out;
  out << "## Targets (issue 2)\n\n";
  out << CountAndTimeTarget(rows, "nazca_monkey.poly", acd::ConcavityMeasure::kShortestPath, 104,
                            5.0)
      << "\n";
  out << CountAndTimeTarget(rows, "nazca_monkey.poly", acd::ConcavityMeasure::kStraightLine, 101,
                            1.0)
      << "\n";
  out << CountAndTimeTarget(rows, "nazca_monkey_2.poly", acd::ConcavityMeasure::kShortestPath,
                            std::nullopt, 40.0)
      << "\n";

  {
    const std::string label = "neuron.poly, tau_rel 0.01: <= 160 components with every measure";
    std::string figures;
    bool pass = true, measured = true;
    for (acd::ConcavityMeasure measure : kMeasures) {
      const Row* row = Find(rows, "neuron.poly", 0.01, MethodName(measure));
      if (row == nullptr) {
        measured = false;
        break;
      }
      pass = pass && row->components && *row->components <= 160;
      figures += (figures.empty() ? "" : ", ") + acd::ToString(measure) + " " +
                 (row->components ? std::to_string(*row->components) : "failed");
    }
    if (measured) {
      out << "- " << label << ": " << Verdict(pass) << " — " << figures << "\n";
    } else {
      out << "- " << label << ": not measured\n";
    }
  }

  // tau = 0: against CGAL's optimal partition (where it ran) and approx_convex_partition_2.
  // Judged with SP (the default measure); every measure's own outcome is listed under it.
  std::vector<std::string> polygons;
  for (const Row& row : rows) {
    if (row.tau_rel && *row.tau_rel == 0.0 &&
        std::find(polygons.begin(), polygons.end(), row.polygon) == polygons.end()) {
      polygons.push_back(row.polygon);
    }
  }
  if (polygons.empty()) {
    out << "- tau = 0 targets: not measured (tau_rel 0 not run)\n";
    return out.str();
  }
  struct Target {
    const char* peer;
    double factor;
    bool strict;
    const char* label;
  };
  const Target targets[] = {
      {kCgalOptimal, 1.3, false,
       "tau = 0: components <= 1.3 x CGAL optimal_convex_partition_2, where it ran (no holes, "
       "n <= 150)"},
      {kCgalApprox, 1.0, true,
       "tau = 0: fewer components than CGAL approx_convex_partition_2 on every polygon it ran "
       "on (no holes)"},
  };
  for (const Target& target : targets) {
    std::vector<std::string> meeting;
    std::ostringstream per_measure;
    std::string sp_line;
    for (acd::ConcavityMeasure measure : kMeasures) {
      const PeerComparison comparison =
          ComparePeer(rows, polygons, measure, target.peer, target.factor, target.strict);
      if (comparison.Pass()) meeting.push_back(acd::ToString(measure));
      per_measure << "  - " << acd::ToString(measure) << ": " << comparison.Summary(target.peer)
                  << "\n";
      if (measure == acd::ConcavityMeasure::kShortestPath) {
        sp_line = comparison.compared == 0 ? "not measured (no polygon where both ran)"
                                           : Verdict(comparison.Pass()) + " with SP — " +
                                                 comparison.Summary(target.peer);
      }
    }
    out << "- " << target.label << ": " << sp_line << ". Measures meeting it on every polygon: ";
    if (meeting.empty()) out << "none";
    for (size_t i = 0; i < meeting.size(); ++i) out << (i ? ", " : "") << meeting[i];
    out << ".\n" << per_measure.str();
  }
  return out.str();
}

std::string LoadAverage() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(file >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

int Run(const BenchArguments& args) {
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
  if (!args.json_path.empty()) {
    // Fail before the (minutes long) runs rather than after them.
    const std::filesystem::path parent = std::filesystem::path(args.json_path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
      throw acdplan::InputError("--json " + args.json_path + ": folder " + parent.string() +
                            " does not exist");
    }
  }

  const std::string load_before = LoadAverage();
  std::vector<Row> rows;
  std::vector<std::string> problems;
  bool ok = true;
  for (const BenchInput& input : inputs) {
    std::cerr << "acd_bench: " << input.name << " (n " << input.vertices << ", holes "
              << input.holes << ")" << std::endl;
    for (double tau_rel : tau_rels) ok = BenchOurs(input, tau_rel, args, &rows, &problems) && ok;
    BenchCgal(input, args, &rows);
  }

  std::ostringstream out;
  out << "# acd_bench\n\n";
  out << "Median wall time of Decompose2d() (SL, SP, H1, H2; tau = tau_rel x the polygon's "
         "reference radius as written in the file) and of CGAL "
      << CGAL_STRINGIZE(CGAL_VERSION)
      << "'s partitions (no tolerance; simple polygons without holes), " << args.repeats
      << " runs per cell, or fewer (but >= " << std::min(3, args.repeats)
      << ") once a cell's runs have used " << Format("%g", args.cell_budget_ms)
      << " ms; CGAL's optimal partition only for n <= " << args.optimal_max_vertices
      << ". Convexity is Eqn. 4.4 (sum of areas / sum of hull areas).\n\n";
  out << MarkdownTable(rows, args.check) << "\n";
  if (!skipped.empty()) {
    out << "Skipped (did not load):\n\n";
    for (const std::string& line : skipped) out << "- " << line << "\n";
    out << "\n";
  }
  for (const Row& row : rows) {
    if (row.method.rfind("cgal", 0) == 0 &&
        (row.note.rfind("failed", 0) == 0 || row.note.rfind("invalid", 0) == 0)) {
      problems.push_back(row.polygon + ", " + row.method + ": " + row.note);
    }
  }
  out << "Problems (our decompositions that threw"
      << (args.check ? " or failed CheckDecomposition" : "")
      << "; CGAL failures): " << (problems.empty() ? "none" : std::to_string(problems.size()))
      << "\n\n";
  for (const std::string& problem : problems) out << "- " << problem << "\n";
  if (!problems.empty()) out << "\n";
  out << TargetsSection(rows) << "\n";
  out << "Machine: " << std::thread::hardware_concurrency()
      << " hardware threads (std::thread::hardware_concurrency); load average " << load_before
      << " before, " << LoadAverage() << " after the runs.\n";
  std::cout << out.str() << std::flush;

  if (!args.json_path.empty()) {
    acd::WriteFileAtomically(args.json_path, JsonRows(rows, args.check).dump(1) + "\n");
  }
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  BenchArguments args;
  CLI::App app{
      "acd_bench: 2D approximate convex decomposition benchmark against CGAL's "
      "convex partitions (tools/acd_bench.md)"};
  app.add_option("files", args.files,
                 "Polygon files (.poly, .wkt, .geojson); default: the issue's list under --data");
  app.add_option("--tau-rel", args.tau_rels,
                 "tau relative to the reference radius; repeatable (default: 0.01 and 0)")
      ->allow_extra_args(false)
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--repeats", args.repeats, "Timed runs per cell (median)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--cell-budget-ms", args.cell_budget_ms,
                 "Stop repeating a cell once it used this long (at least 3 runs)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e9));
  app.add_option("--optimal-max-n", args.optimal_max_vertices,
                 "Run CGAL's O(n^4) optimal partition only up to this many vertices")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  app.add_option("--json", args.json_path, "Also write the table as JSON (a list of rows)");
  app.add_option("--data", args.data_dir, "Folder of the default polygon list")
      ->capture_default_str();
  app.add_flag("--check", args.check,
               "Run CheckDecomposition on each of our decompositions and report failures");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  try {
    return Run(args);
  } catch (const acdplan::InputError& error) {
    std::cerr << "acd_bench: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "acd_bench: internal error: " << error.what() << "\n";
    return 1;
  }
}
