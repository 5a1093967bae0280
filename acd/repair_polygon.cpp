#include "acd/repair_polygon.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "acd/internal/even_odd_regions.h"
#include "acd/internal/ring_name.h"
#include "acd/internal/text_parsing.h"
#include "acd/prepare_polygon.h"
#include "base/bit_hash.h"
#include "base/format.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

using internal::RingName;

// Distinct vertices of `ring` and whether they span an area (not all collinear), exactly.
int DistinctNonCollinear(const Ring2d& ring, bool* spans_area) {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Epick::Point_2> points;
  for (const Point2d& p : ring) points.emplace_back(p.x(), p.y());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  *spans_area = false;
  for (size_t i = 2; i < points.size() && !*spans_area; ++i) {
    *spans_area = !CGAL::collinear(points[0], points[1], points[i]);
  }
  return static_cast<int>(points.size());
}

// `ring` without a vertex equal to the one before it (cyclically).
Ring2d WithoutRepeatedVertices(const Ring2d& ring) {
  Ring2d out;
  for (const Point2d& p : ring) {
    if (out.empty() || p != out.back()) out.push_back(p);
  }
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

// The fewest leading vertices of `ring` (no vertex equal to the one before it) that the ring
// repeats to its end: its size unless it runs around the same vertices more than once.
size_t Period(const Ring2d& ring) {
  const size_t n = ring.size();
  for (size_t p = 1; p < n; ++p) {
    if (n % p != 0) continue;
    bool repeats = true;
    for (size_t i = p; i < n && repeats; ++i) repeats = ring[i] == ring[i - p];
    if (repeats) return p;
  }
  return n;
}

// Whether rings `a` and `b` (no vertex equal to the one before it) have the same vertices in
// the same cyclic order, in either direction.
bool SameRing(const Ring2d& a, const Ring2d& b) {
  const size_t n = a.size();
  if (b.size() != n || n == 0) return false;
  for (size_t s = 0; s < n; ++s) {
    if (b[s] != a[0]) continue;
    bool forward = true, backward = true;
    for (size_t i = 1; i < n && (forward || backward); ++i) {
      forward = forward && a[i] == b[(s + i) % n];
      backward = backward && a[i] == b[(s + n - i) % n];
    }
    if (forward || backward) return true;
  }
  return false;
}

// A hash of the vertices of `ring` that ignores their order (so also where the ring starts and
// which way it runs); -0 counts as 0.
std::uint64_t VertexSetHash(const Ring2d& ring) {
  std::uint64_t sum = ring.size();
  for (const Point2d& p : ring) sum += BitHash(BitHash(kBitHashSeed, p.x() + 0.0), p.y() + 0.0);
  return sum;
}

// The message of `error` without the "<where>: " it starts with.
std::string Rule(const InputError& error, const std::string& where) {
  std::string message = error.what();
  if (message.compare(0, where.size() + 2, where + ": ") == 0) message.erase(0, where.size() + 2);
  return message;
}

// `message` about a polygon whose rings are the input's rings `kept` (ascending, the outer ring
// first), with each "hole K" named as the input numbers it.
std::string WithInputHoleNumbers(const std::string& message, const std::vector<size_t>& kept) {
  const std::string word = "hole ";
  std::string renamed;
  size_t done = 0;
  for (size_t at = message.find(word); at != std::string::npos; at = message.find(word, at)) {
    at += word.size();
    size_t end = at;
    while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
    if (end == at) continue;
    const size_t hole = std::stoul(message.substr(at, end - at));
    if (hole + 1 >= kept.size()) continue;  // Not a ring name; left as it is.
    renamed += message.substr(done, at - done) + std::to_string(kept[hole + 1] - 1);
    done = end;
    at = end;
  }
  return renamed + message.substr(done);
}

}  // namespace

RepairedPolygon RepairPolygon(const Polygon2d& raw, const std::string& where) {
  // No repair brings a coordinate into range. Nor could the arrangement below take one: its
  // interval filters overflow on cubed coordinates, and CGAL's arrangement then reached
  // undefined behaviour (a vertex at 5e184, fuzz_decompose2d).
  CheckCoordinates(raw, where);
  RepairedPolygon result;
  std::string rule;
  try {
    result.polygons = PreparePolygons(raw, where);
    return result;
  } catch (const InputError& error) {
    rule = Rule(error, where);
  }
  const size_t ring_count = 1 + raw.holes.size();
  auto ring_at = [&](size_t r) -> const Ring2d& { return r == 0 ? raw.outer : raw.holes[r - 1]; };

  // 1. Rings that collapse.
  std::vector<size_t> kept;
  for (size_t r = 0; r < ring_count; ++r) {
    bool spans_area = false;
    const int distinct = DistinctNonCollinear(ring_at(r), &spans_area);
    if (distinct < 3 || !spans_area) {
      result.changes.push_back(where + ": repaired: " + RingName(r) + " has " +
                               std::to_string(distinct) + " distinct vertices" +
                               (distinct >= 3 ? ", all collinear" : "") + ": dropped");
    } else {
      kept.push_back(r);
    }
  }
  if (kept.empty() || kept[0] != 0) {
    result.changes.push_back(where + ": repaired: nothing remains without the outer ring");
    return result;
  }

  // 2. Rings given more than once. The even-odd rule counts every ring edge, so a ring that runs
  // around twice, or a hole listed twice, would cancel itself out; GEOS's make-valid takes
  // coincident edges once. Each is taken once here.
  bool changed = kept.size() < ring_count;
  std::vector<size_t> sources;   // The input's number of each ring in `rings`.
  std::vector<Ring2d> rings;     // As given, unless it ran around more than once.
  std::vector<Ring2d> distinct;  // `rings` without a vertex equal to the one before it.
  std::unordered_map<std::uint64_t, std::vector<size_t>> holes_by_vertices;  // Into `rings`.
  for (const size_t r : kept) {
    Ring2d ring = WithoutRepeatedVertices(ring_at(r));
    const size_t period = Period(ring);
    const bool runs_around = period < ring.size();
    if (runs_around) {
      result.changes.push_back(where + ": repaired: " + RingName(r) + " runs around its first " +
                               std::to_string(period) + " distinct vertices " +
                               std::to_string(ring.size() / period) + " times: taken once");
      ring.resize(period);
      changed = true;
    }
    if (r > 0) {
      std::vector<size_t>& same_vertices = holes_by_vertices[VertexSetHash(ring)];
      const auto earlier = std::find_if(same_vertices.begin(), same_vertices.end(),
                                        [&](size_t k) { return SameRing(distinct[k], ring); });
      if (earlier != same_vertices.end()) {
        result.changes.push_back(where + ": repaired: " + RingName(r) + " repeats " +
                                 RingName(sources[*earlier]) + ": dropped");
        changed = true;
        continue;
      }
      same_vertices.push_back(rings.size());
    }
    sources.push_back(r);
    rings.push_back(runs_around ? ring : ring_at(r));
    distinct.push_back(std::move(ring));
  }
  if (changed) {
    const Polygon2d rest{rings[0], std::vector<Ring2d>(rings.begin() + 1, rings.end())};
    try {
      result.polygons = PreparePolygons(rest, where);
      return result;
    } catch (const InputError& error) {
      rule = WithInputHoleNumbers(Rule(error, where), sources);
    }
  }

  // 3. Even-odd rule over the exact arrangement of all ring edges.
  const std::vector<Polygon2d> parts = internal::EvenOddRegions({rings});
  size_t holes = 0;
  double area = 0.0;
  for (const Polygon2d& part : parts) {
    std::vector<Polygon2d> prepared;
    try {
      prepared = PreparePolygons(part, where);
    } catch (const InputError& error) {
      throw InputError(where + ": repair failed: rounding the even-odd result to doubles left " +
                       Rule(error, where) + " (input: " + rule + ")");
    }
    for (Polygon2d& p : prepared) {
      holes += p.holes.size();
      area += Area(p);
      result.polygons.push_back(std::move(p));
    }
  }
  result.changes.push_back(where + ": repaired: " + rule + ": rebuilt by the even-odd rule into " +
                           std::to_string(result.polygons.size()) + " polygon(s) with " +
                           std::to_string(holes) + " hole(s), area " + FormatSignificant(area, 15));
  return result;
}

}  // namespace acdplan::acd
