#include "envs/generators3d.h"

#include <cmath>
#include <functional>

#include "base/format.h"
#include "base/input_error.h"
#include "base/random.h"
#include "envs/internal/box_grid_solids.h"
#include "envs/internal/generator_rules.h"

namespace acdplan::envs {
namespace {

using Box = Eigen::AlignedBox3d;
using Eigen::Vector3d;

using internal::Format;
using internal::Positive;
using internal::Require;

Box MakeBox(double x0, double y0, double z0, double x1, double y1, double z1) {
  return Box(Vector3d(x0, y0, z0), Vector3d(x1, y1, z1));
}

/// The solid `inside` over the grid through every face of `boxes` (and the world's).
std::vector<acd::TriangleMesh> Solids(const Box& world, const std::vector<Box>& boxes,
                                      const std::function<bool(const Vector3d&)>& inside) {
  std::vector<double> walls[3];
  for (int a = 0; a < 3; ++a) {
    walls[a] = {world.min()[a], world.max()[a]};
    for (const Box& box : boxes) {
      walls[a].push_back(box.min()[a]);
      walls[a].push_back(box.max()[a]);
    }
  }
  return internal::BoxGridSolids(walls[0], walls[1], walls[2], inside);
}

/// `box` contains `p` (cell centres are never on a cell wall, so strictness does not matter).
bool In(const Box& box, const Vector3d& p) { return box.contains(p); }

/// A lower corner uniform in the middle `share` of [0, room] (room = free length).
double MiddleUniform(RandomEngine& rng, double room, double share) {
  return UniformReal(rng, room * (1 - share) / 2, room * (1 + share) / 2);
}

}  // namespace

Workspace3d MakeWindowWall(std::uint64_t seed, const WindowWallOptions& o, Passages3d* passages) {
  const char* where = "MakeWindowWall()";
  Require(Positive(o.width) && Positive(o.depth) && Positive(o.height), where,
          "width, depth and height must be > 0");
  Require(Positive(o.wall_thickness) && o.wall_thickness < o.width, where,
          "wall_thickness must be in (0, width)");
  Require(Positive(o.window_side) && o.window_side < o.depth && o.window_side < o.height, where,
          "window_side must be in (0, min(depth, height))");
  RandomEngine rng(seed);
  const double y0 = MiddleUniform(rng, o.depth - o.window_side, 0.6);
  const double z0 = MiddleUniform(rng, o.height - o.window_side, 0.6);
  const Box world = MakeBox(0, 0, 0, o.width, o.depth, o.height);
  const double x0 = (o.width - o.wall_thickness) / 2, x1 = x0 + o.wall_thickness;
  const Box wall = MakeBox(x0, 0, 0, x1, o.depth, o.height);
  const Box window = MakeBox(x0, y0, z0, x1, y0 + o.window_side, z0 + o.window_side);
  Workspace3d w;
  w.bounds = world;
  w.obstacles = Solids(world, {wall, window},
                       [&](const Vector3d& p) { return In(wall, p) && !In(window, p); });
  w.description = "window_wall: a wall across x with one square window of side " +
                  Format(o.window_side) + " (seed " + std::to_string(seed) + ")";
  if (passages) *passages = {{window, 0}};
  return w;
}

Workspace3d MakeBugTrap3d(std::uint64_t seed, const BugTrap3dOptions& o, Passages3d* passages) {
  const char* where = "MakeBugTrap3d()";
  const double t = o.wall_thickness, m = o.mouth_side;
  Require(Positive(o.size) && Positive(o.trap_size) && o.trap_size < o.size, where,
          "trap_size must be in (0, size)");
  Require(Positive(t) && Positive(m) && o.trap_size > m + 4 * t, where,
          "wall_thickness and mouth_side must be > 0 with trap_size > mouth_side + 4 "
          "wall_thickness");
  Require(Positive(o.funnel_length) && o.funnel_length < o.trap_size - 3 * t, where,
          "funnel_length must be in (0, trap_size - 3 wall_thickness)");
  RandomEngine rng(seed);
  const double c0 = (o.size - o.trap_size) / 2, c3 = c0 + o.trap_size;
  const double c1 = c0 + t, c2 = c3 - t;
  // The funnel's walls stay inside the cavity: its outer side is mouth + 2t.
  const double room = (c2 - c1) - (m + 2 * t);
  const double my = c1 + t + MiddleUniform(rng, room, 0.8);
  const double mz = c1 + t + MiddleUniform(rng, room, 0.8);
  const double fx = c2 - o.funnel_length;
  const Box world = MakeBox(0, 0, 0, o.size, o.size, o.size);
  const Box cage = MakeBox(c0, c0, c0, c3, c3, c3);
  const Box cavity = MakeBox(c1, c1, c1, c2, c2, c2);
  const Box funnel = MakeBox(fx, my - t, mz - t, c2, my + m + t, mz + m + t);
  const Box mouth = MakeBox(fx, my, mz, c3, my + m, mz + m);
  Workspace3d w;
  w.bounds = world;
  w.obstacles = Solids(world, {cage, cavity, funnel, mouth}, [&](const Vector3d& p) {
    return In(cage, p) && (!In(cavity, p) || In(funnel, p)) && !In(mouth, p);
  });
  w.description = "bug_trap3d: a closed cage of side " + Format(o.trap_size) +
                  " entered through a funnel of side " + Format(m) + " (seed " +
                  std::to_string(seed) + ")";
  if (passages) *passages = {{mouth, 0}};
  return w;
}

Workspace3d MakeCubicles(std::uint64_t seed, const CubiclesOptions& o, Passages3d* passages) {
  const char* where = "MakeCubicles()";
  Require(o.floors >= 2, where, "floors must be >= 2");
  Require(
      Positive(o.floor_thickness) && Positive(o.floor_height) && o.floor_thickness < o.floor_height,
      where, "floor_thickness must be in (0, floor_height)");
  Require(Positive(o.hatch_side) && Positive(o.width) && Positive(o.depth) &&
              o.hatch_side < o.width && o.hatch_side < o.depth,
          where, "hatch_side must be in (0, min(width, depth))");
  RandomEngine rng(seed);
  const double height = o.floors * o.floor_height;
  const Box world = MakeBox(0, 0, 0, o.width, o.depth, height);
  Workspace3d w;
  w.bounds = world;
  if (passages) passages->clear();
  for (int k = 1; k < o.floors; ++k) {
    const double z0 = k * o.floor_height - o.floor_thickness / 2;
    const double z1 = z0 + o.floor_thickness;
    const double hx = MiddleUniform(rng, o.width - o.hatch_side, 0.8);
    const double hy = MiddleUniform(rng, o.depth - o.hatch_side, 0.8);
    const Box slab = MakeBox(0, 0, z0, o.width, o.depth, z1);
    const Box hatch = MakeBox(hx, hy, z0, hx + o.hatch_side, hy + o.hatch_side, z1);
    for (acd::TriangleMesh& part : Solids(world, {slab, hatch}, [&](const Vector3d& p) {
           return In(slab, p) && !In(hatch, p);
         })) {
      w.obstacles.push_back(std::move(part));
    }
    if (passages) passages->push_back({hatch, 2});
  }
  w.description = "cubicles: " + std::to_string(o.floors) +
                  " rooms stacked, joined by square hatches of side " + Format(o.hatch_side) +
                  " (seed " + std::to_string(seed) + ")";
  return w;
}

Workspace3d MakeBentTube(std::uint64_t seed, const BentTubeOptions& o, Passages3d* passages) {
  const char* where = "MakeBentTube()";
  const double s = o.tube_side, size = o.size;
  Require(Positive(s) && Positive(size) && size > 6 * s, where,
          "tube_side must be in (0, size / 6)");
  Require(o.bends == 1 || o.bends == 2, where, "bends must be 1 or 2");
  RandomEngine rng(seed);
  // The legs' positions leave at least one tube side of material between them and the faces.
  const double z0 = UniformReal(rng, s, size - 2 * s);
  const double y0 = UniformReal(rng, s, size / 2 - s);
  const double x_turn = UniformReal(rng, size / 4, 3 * size / 4 - s);
  std::vector<Box> legs;
  if (o.bends == 1) {
    legs.push_back(MakeBox(0, y0, z0, x_turn + s, y0 + s, z0 + s));
    legs.push_back(MakeBox(x_turn, y0, z0, x_turn + s, size, z0 + s));
  } else {
    const double y1 = UniformReal(rng, y0 + 2 * s, size - 2 * s);
    legs.push_back(MakeBox(0, y0, z0, x_turn + s, y0 + s, z0 + s));
    legs.push_back(MakeBox(x_turn, y0, z0, x_turn + s, y1 + s, z0 + s));
    legs.push_back(MakeBox(x_turn, y1, z0, size, y1 + s, z0 + s));
  }
  const Box world = MakeBox(0, 0, 0, size, size, size);
  Workspace3d w;
  w.bounds = world;
  w.obstacles = Solids(world, legs, [&](const Vector3d& p) {
    for (const Box& leg : legs) {
      if (In(leg, p)) return false;
    }
    return true;
  });
  w.description = "bent_tube: a square tube of side " + Format(s) + " with " +
                  Plural(o.bends, "bend") + " through solid material (seed " +
                  std::to_string(seed) + ")";
  if (passages) {
    passages->clear();
    for (size_t i = 0; i < legs.size(); ++i) passages->push_back({legs[i], i % 2 == 0 ? 0 : 1});
  }
  return w;
}

std::vector<std::string> Generator3dNames() {
  return {"window_wall", "bug_trap3d", "cubicles", "bent_tube"};
}

Workspace3d GenerateWorkspace3d(const std::string& name, std::uint64_t seed,
                                const Generator3dParameters& p, Passages3d* passages) {
  const char* where = "GenerateWorkspace3d()";
  Require(std::isfinite(p.passage_width) && p.passage_width >= 0, where,
          "passage_width must be a finite number >= 0");
  Require(std::isfinite(p.wall_thickness) && p.wall_thickness >= 0, where,
          "wall_thickness must be a finite number >= 0");
  auto set = [](double value, double* field) {
    if (value > 0) *field = value;
  };
  try {
    if (name == "window_wall") {
      WindowWallOptions o;
      set(p.passage_width, &o.window_side);
      set(p.wall_thickness, &o.wall_thickness);
      return MakeWindowWall(seed, o, passages);
    }
    if (name == "bug_trap3d") {
      BugTrap3dOptions o;
      set(p.passage_width, &o.mouth_side);
      set(p.wall_thickness, &o.wall_thickness);
      return MakeBugTrap3d(seed, o, passages);
    }
    if (name == "cubicles") {
      CubiclesOptions o;
      set(p.passage_width, &o.hatch_side);
      set(p.wall_thickness, &o.floor_thickness);
      return MakeCubicles(seed, o, passages);
    }
    if (name == "bent_tube") {
      Require(p.wall_thickness == 0, where,
              "bent_tube has no wall_thickness (the tube runs through solid material)");
      BentTubeOptions o;
      set(p.passage_width, &o.tube_side);
      return MakeBentTube(seed, o, passages);
    }
  } catch (const InputError& error) {
    throw InputError(std::string(where) + ": " + error.what());
  }
  throw InputError(std::string(where) + ": " + UnknownName("generator", name, Generator3dNames()));
}

}  // namespace acdplan::envs
