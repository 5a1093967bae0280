#include "envs/generators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "base/format.h"
#include "base/input_error.h"
#include "base/random.h"
#include "envs/internal/generator_rules.h"
#include "envs/internal/trace_cells.h"

namespace acdplan::envs {
namespace {

using acd::Point2d;
using acd::Polygon2d;
using acd::Ring2d;

using internal::Format;
using internal::Positive;
using internal::Require;

Polygon2d Box(double x0, double y0, double x1, double y1) {
  return Polygon2d{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

int UniformInt(RandomEngine& rng, int n) {  // In [0, n).
  return static_cast<int>(UniformIndex(rng, static_cast<std::uint64_t>(n)));
}

// One side of an open polyline offset by `h` to its left (h < 0: right), with miter joins.
Ring2d OffsetPolyline(const std::vector<Point2d>& points, double h) {
  std::vector<Point2d> normals;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const Point2d d = (points[i + 1] - points[i]).normalized();
    normals.emplace_back(-d.y(), d.x());
  }
  Ring2d side = {points.front() + h * normals.front()};
  for (size_t j = 1; j + 1 < points.size(); ++j) {
    const Point2d& a = normals[j - 1];
    const Point2d& b = normals[j];
    side.push_back(points[j] + h * (a + b) / (1.0 + a.dot(b)));
  }
  side.push_back(points.back() + h * normals.back());
  return side;
}

// The polyline thickened to `thickness` (flat ends), as one polygon.
Polygon2d ThickPolyline(const std::vector<Point2d>& points, double thickness) {
  Ring2d ring = OffsetPolyline(points, -thickness / 2);
  const Ring2d left = OffsetPolyline(points, thickness / 2);
  ring.insert(ring.end(), left.rbegin(), left.rend());
  return Polygon2d{ring, {}};
}

Workspace2d Finish(Workspace2d workspace, const char* where) {
  // Validates what the options produced (e.g. a corridor too wide for its world).
  return PrepareWorkspace2d(workspace, where);
}

}  // namespace

Workspace2d MakeWallWithGap(std::uint64_t seed, const WallGapOptions& o) {
  const char* where = "MakeWallWithGap()";
  Require(Positive(o.width) && Positive(o.height) && Positive(o.wall_thickness), where,
          "width, height and wall_thickness must be > 0");
  Require(Positive(o.passage_width) && o.passage_width <= o.height / 2, where,
          "passage_width must be in (0, height / 2]");
  Require(o.wall_thickness < o.width, where, "wall_thickness must be < width");
  RandomEngine rng(seed);
  const double y0 = UniformReal(rng, 0.1 * o.height, 0.9 * o.height - o.passage_width);
  const double x0 = (o.width - o.wall_thickness) / 2, x1 = x0 + o.wall_thickness;
  Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(o.width, o.height));
  w.obstacles = {Box(x0, 0, x1, y0), Box(x0, y0 + o.passage_width, x1, o.height)};
  w.description = "wall_gap: a wall across the world with one gap " + Format(o.passage_width) +
                  " wide (seed " + std::to_string(seed) + ")";
  return Finish(w, where);
}

Workspace2d MakeZigZagCorridor(std::uint64_t seed, const ZigZagOptions& o) {
  const char* where = "MakeZigZagCorridor()";
  Require(Positive(o.width) && Positive(o.height) && Positive(o.passage_width), where,
          "width, height and passage_width must be > 0");
  Require(o.turns >= 1, where, "turns must be >= 1");
  RandomEngine rng(seed);
  const double stub = 0.1 * o.width;
  const double spacing = (o.width - 2 * stub) / o.turns;
  std::vector<Point2d> centre = {{0, o.height / 2}, {stub, o.height / 2}};
  double sign = UniformInt(rng, 2) == 0 ? 1.0 : -1.0;
  for (int k = 0; k < o.turns; ++k) {
    const double x = stub + (k + 0.5) * spacing + UniformReal(rng, -0.15, 0.15) * spacing;
    const double amplitude = UniformReal(rng, 0.15, 0.3) * o.height;
    centre.emplace_back(x, o.height / 2 + sign * amplitude);
    sign = -sign;
  }
  centre.emplace_back(o.width - stub, o.height / 2);
  centre.emplace_back(o.width, o.height / 2);
  Ring2d upper = OffsetPolyline(centre, o.passage_width / 2);
  upper.emplace_back(o.width, o.height);
  upper.emplace_back(0, o.height);
  Ring2d lower = OffsetPolyline(centre, -o.passage_width / 2);
  lower.emplace_back(o.width, 0);
  lower.emplace_back(0, 0);
  for (const Ring2d* ring : {&upper, &lower}) {
    for (const Point2d& p : *ring) {
      Require(p.y() >= 0 && p.y() <= o.height, where,
              "passage_width " + Format(o.passage_width) + " is too wide for height " +
                  Format(o.height));
    }
  }
  Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(o.width, o.height));
  w.obstacles = {Polygon2d{upper, {}}, Polygon2d{lower, {}}};
  w.description = "zigzag: a corridor " + Format(o.passage_width) + " wide with " +
                  std::to_string(o.turns) + " sharp turns from x = 0 to x = " + Format(o.width) +
                  " (seed " + std::to_string(seed) + ")";
  return Finish(w, where);
}

Workspace2d MakeBugTrap(std::uint64_t seed, const BugTrapOptions& o) {
  const char* where = "MakeBugTrap()";
  Require(Positive(o.width) && Positive(o.height) && Positive(o.trap_size) &&
              Positive(o.wall_thickness) && Positive(o.passage_width),
          where, "all sizes must be > 0");
  Require(o.trap_size < std::min(o.width, o.height), where,
          "trap_size must be < min(width, height)");
  const double s = o.trap_size, t = o.wall_thickness, m = o.passage_width;
  const double lip = s / 4;
  Require(s - 2 * t - lip > t && s > 4 * t + m + 2 * t, where,
          "the mouth and the walls do not fit in trap_size");
  RandomEngine rng(seed);
  const double l = (o.width - s) / 2, b = (o.height - s) / 2, r = l + s, top = b + s;
  // The mouth [m0, m0 + m] keeps a wall's thickness of clearance from the corners.
  const double m0 = UniformReal(rng, b + 3 * t, top - 3 * t - m), m1 = m0 + m;
  const double li = r - t - lip;  // Where the lips end inside the cage.
  const Ring2d ring = {{r, b},           {r, m0},         {li, m0},       {li, m0 - t},
                       {r - t, m0 - t},  {r - t, b + t},  {l + t, b + t}, {l + t, top - t},
                       {r - t, top - t}, {r - t, m1 + t}, {li, m1 + t},   {li, m1},
                       {r, m1},          {r, top},        {l, top},       {l, b}};
  Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(o.width, o.height));
  w.obstacles = {Polygon2d{ring, {}}};
  w.description = "bug_trap: a cage whose inside is reached only through a funnel mouth " +
                  Format(m) + " wide on its right side (seed " + std::to_string(seed) + ")";
  return Finish(w, where);
}

Workspace2d MakeTwoRooms(std::uint64_t seed, const TwoRoomsOptions& o) {
  const char* where = "MakeTwoRooms()";
  Require(Positive(o.width) && Positive(o.height) && Positive(o.wall_thickness) &&
              Positive(o.passage_width),
          where, "all sizes must be > 0");
  Require(o.furniture >= 0, where, "furniture must be >= 0");
  const double W = o.width, H = o.height, t = o.wall_thickness, d = o.passage_width;
  Require(d + 2 * t + 1.0 < H && 6 * t + 2.0 < W, where, "the rooms are too small for the door");
  RandomEngine rng(seed);
  const double y0 = UniformReal(rng, t + 0.5, H - t - 0.5 - d), y1 = y0 + d;
  const double xm = W / 2;
  Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(W, H));
  // Outer walls reach a wall thickness beyond the bounds; the dividing wall overlaps them.
  w.obstacles = {Box(-t, -t, W + t, t),
                 Box(-t, H - t, W + t, H + t),
                 Box(-t, -t, t, H + t),
                 Box(W - t, -t, W + t, H + t),
                 Box(xm - t / 2, 0, xm + t / 2, y0),
                 Box(xm - t / 2, y1, xm + t / 2, H)};
  // Furniture: boxes anywhere in a room (overlapping walls or each other is fine) but outside
  // the door's approach, so the door stays a passage of width `d`.
  const double approach = 2 * d + 1.0;
  for (int room = 0; room < 2; ++room) {
    const double lo = room == 0 ? t : xm + t / 2, hi = room == 0 ? xm - t / 2 : W - t;
    for (int placed = 0, tries = 0; placed < o.furniture && tries < 1000; ++tries) {
      const double sx = UniformReal(rng, 0.4, 1.2), sy = UniformReal(rng, 0.4, 1.2);
      const double cx = UniformReal(rng, lo, hi), cy = UniformReal(rng, t, H - t);
      const double x0 = cx - sx / 2, x1 = cx + sx / 2, ya = cy - sy / 2, yb = cy + sy / 2;
      const bool near_door =
          x1 > xm - approach && x0 < xm + approach && yb > y0 - approach && ya < y1 + approach;
      if (near_door) continue;
      w.obstacles.push_back(Box(x0, ya, x1, yb));
      ++placed;
    }
  }
  w.description = "two_rooms: two furnished rooms joined by a door " + Format(d) +
                  " wide; outer walls cross the bounds (seed " + std::to_string(seed) + ")";
  return Finish(w, where);
}

Workspace2d MakeSpiral(std::uint64_t seed, const SpiralOptions& o) {
  const char* where = "MakeSpiral()";
  Require(o.turns >= 1, where, "turns must be >= 1");
  Require(Positive(o.wall_thickness) && Positive(o.passage_width), where,
          "wall_thickness and passage_width must be > 0");
  Require(std::isfinite(o.margin) && o.margin >= 0, where, "margin must be >= 0");
  RandomEngine rng(seed);
  const int start = UniformInt(rng, 4);
  const int sense = UniformInt(rng, 2) == 0 ? 1 : 3;  // Counter-clockwise or clockwise.
  static constexpr std::array<std::array<int, 2>, 4> kDirections = {
      {{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
  // A square spiral: segment k has length pitch * (k / 2 + 1), so parallel walls of
  // consecutive turns are one pitch apart and the corridor between them is passage_width.
  const double pitch = o.passage_width + o.wall_thickness;
  std::vector<Point2d> points = {{0, 0}};
  for (int k = 0, dir = start; k < 4 * o.turns; ++k, dir = (dir + sense) % 4) {
    const double length = pitch * (k / 2 + 1);
    points.push_back(points.back() + length * Point2d(kDirections[dir][0], kDirections[dir][1]));
  }
  Eigen::AlignedBox2d box;
  for (const Point2d& p : points) box.extend(p);
  const double pad = o.wall_thickness / 2 + o.margin;
  Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(box.min().array() - pad, box.max().array() + pad);
  w.obstacles = {ThickPolyline(points, o.wall_thickness)};
  w.description = "spiral: a corridor " + Format(o.passage_width) + " wide winding " +
                  std::to_string(o.turns) + " turns from the outside to the centre (0, 0) (seed " +
                  std::to_string(seed) + ")";
  return Finish(w, where);
}

Workspace2d MakeMaze(std::uint64_t seed, const MazeOptions& o) {
  const char* where = "MakeMaze()";
  Require(o.columns >= 1 && o.rows >= 1 && o.columns <= 1000 && o.rows <= 1000, where,
          "columns and rows must be in [1, 1000]");
  Require(Positive(o.wall_thickness) && Positive(o.passage_width), where,
          "wall_thickness and passage_width must be > 0");
  // A (2 columns + 1) x (2 rows + 1) grid, y up: odd/odd cells are passage cells, the others
  // walls until the depth-first search carves them.
  const int w = 2 * o.columns + 1, h = 2 * o.rows + 1;
  std::vector<std::uint8_t> blocked(static_cast<size_t>(w) * h, 1);
  std::vector<char> seen(static_cast<size_t>(o.columns) * o.rows, 0);
  RandomEngine rng(seed);
  const int first = UniformInt(rng, o.columns * o.rows);
  std::vector<int> stack = {first};
  seen[first] = 1;
  blocked[(2 * (first / o.columns) + 1) * w + 2 * (first % o.columns) + 1] = 0;
  while (!stack.empty()) {
    const int cell = stack.back();
    const int cx = cell % o.columns, cy = cell / o.columns;
    std::array<int, 4> options;
    int count = 0;
    static constexpr std::array<std::array<int, 2>, 4> kSteps = {
        {{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
    for (int k = 0; k < 4; ++k) {
      const int nx = cx + kSteps[k][0], ny = cy + kSteps[k][1];
      if (nx >= 0 && ny >= 0 && nx < o.columns && ny < o.rows && !seen[ny * o.columns + nx]) {
        options[count++] = k;
      }
    }
    if (count == 0) {
      stack.pop_back();
      continue;
    }
    const int k = options[UniformInt(rng, count)];
    const int nx = cx + kSteps[k][0], ny = cy + kSteps[k][1];
    seen[ny * o.columns + nx] = 1;
    blocked[(2 * cy + 1 + kSteps[k][1]) * w + 2 * cx + 1 + kSteps[k][0]] = 0;  // The wall.
    blocked[(2 * ny + 1) * w + 2 * nx + 1] = 0;
    stack.push_back(ny * o.columns + nx);
  }
  std::vector<double> xs(w + 1, 0.0), ys(h + 1, 0.0);
  for (int i = 0; i < w; ++i) xs[i + 1] = xs[i] + (i % 2 == 0 ? o.wall_thickness : o.passage_width);
  for (int i = 0; i < h; ++i) ys[i + 1] = ys[i] + (i % 2 == 0 ? o.wall_thickness : o.passage_width);
  Workspace2d result;
  result.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(xs.back(), ys.back()));
  result.obstacles = internal::TraceCells(w, h, blocked, xs, ys);
  result.description = "maze: a " + std::to_string(o.columns) + " x " + std::to_string(o.rows) +
                       " perfect maze with passages " + Format(o.passage_width) + " wide (seed " +
                       std::to_string(seed) + ")";
  return Finish(result, where);
}

namespace {

/// One generator: its name and how to make it with the common parameters applied.
struct Generator {
  const char* name;
  bool has_wall_thickness;
  Workspace2d (*make)(std::uint64_t seed, const GeneratorParameters& p);
};

/// `options` with the parameters that are set (> 0) applied.
template <typename Options>
Options With(Options options, const GeneratorParameters& p) {
  if (p.passage_width > 0.0) options.passage_width = p.passage_width;
  if constexpr (!std::is_same_v<Options, ZigZagOptions>) {
    if (p.wall_thickness > 0.0) options.wall_thickness = p.wall_thickness;
  }
  return options;
}

const std::array<Generator, 6> kGenerators = {{
    {"wall_gap", true,
     [](std::uint64_t seed, const GeneratorParameters& p) {
       return MakeWallWithGap(seed, With(WallGapOptions{}, p));
     }},
    {"zigzag", false,
     [](std::uint64_t seed, const GeneratorParameters& p) {
       return MakeZigZagCorridor(seed, With(ZigZagOptions{}, p));
     }},
    {"bug_trap", true,
     [](std::uint64_t seed, const GeneratorParameters& p) {
       return MakeBugTrap(seed, With(BugTrapOptions{}, p));
     }},
    {"two_rooms", true,
     [](std::uint64_t seed, const GeneratorParameters& p) {
       return MakeTwoRooms(seed, With(TwoRoomsOptions{}, p));
     }},
    {"spiral", true,
     [](std::uint64_t seed, const GeneratorParameters& p) {
       return MakeSpiral(seed, With(SpiralOptions{}, p));
     }},
    {"maze", true,
     [](std::uint64_t seed, const GeneratorParameters& p) {
       return MakeMaze(seed, With(MazeOptions{}, p));
     }},
}};

}  // namespace

std::vector<std::string> GeneratorNames() {
  std::vector<std::string> names;
  for (const Generator& g : kGenerators) names.push_back(g.name);
  return names;
}

Workspace2d GenerateWorkspace2d(const std::string& name, std::uint64_t seed,
                                const GeneratorParameters& parameters) {
  const char* where = "GenerateWorkspace2d()";
  Require(parameters.passage_width >= 0.0 && std::isfinite(parameters.passage_width), where,
          "passage_width must be >= 0 (0 = default)");
  Require(parameters.wall_thickness >= 0.0 && std::isfinite(parameters.wall_thickness), where,
          "wall_thickness must be >= 0 (0 = default)");
  for (const Generator& g : kGenerators) {
    if (name != g.name) continue;
    Require(g.has_wall_thickness || parameters.wall_thickness == 0.0, where,
            "wall_thickness is not an option of generator '" + name + "'");
    return g.make(seed, parameters);
  }
  throw InputError(std::string(where) + ": " + UnknownName("generator", name, GeneratorNames()));
}

}  // namespace acdplan::envs
