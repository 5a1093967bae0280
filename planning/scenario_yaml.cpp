#include "planning/scenario_yaml.h"

#include <algorithm>
#include <cmath>

#include "base/input_error.h"
#include "envs/generators.h"
#include "envs/generators3d.h"
#include "envs/mesh_loader.h"

namespace acdplan::planning {

namespace {

// The keys a generated workspace has in 2D and 3D: `generator`, `seed` (default 1) and the
// passage and wall sizes; then `generate(name, seed, parameters)` builds it, its InputError
// reported at `key`.
template <typename Parameters, typename Generate>
auto ReadGenerated(const YamlFile& file, const YAML::Node& node, const std::string& key,
                   std::string* label, const Generate& generate) {
  auto child = [&key](const char* name) { return YamlFile::Child(key, name); };
  file.CheckKeys(node, key, {"generator", "seed", "passage_width", "wall_thickness"});
  if (!node["generator"]) file.Fail(child("generator"), "required (or give a file name)");
  const std::string name = file.String(node["generator"], child("generator"));
  const std::uint64_t seed =
      node["seed"] ? file.Integer(node["seed"], child("seed"), "an integer >= 0", 0) : 1;
  Parameters parameters;
  if (node["passage_width"]) {
    parameters.passage_width =
        file.Number(node["passage_width"], child("passage_width"), "a positive number", Positive);
  }
  if (node["wall_thickness"]) {
    parameters.wall_thickness =
        file.Number(node["wall_thickness"], child("wall_thickness"), "a positive number", Positive);
  }
  *label = "generator " + name + " (seed " + std::to_string(seed) + ")";
  try {
    return generate(name, seed, parameters);
  } catch (const InputError& error) {
    file.Fail(key, error.what());
  }
}

}  // namespace

envs::Workspace2d ReadGeneratedWorkspace(const YamlFile& file, const YAML::Node& node,
                                         const std::string& key, std::string* label) {
  return ReadGenerated<envs::GeneratorParameters>(file, node, key, label,
                                                  envs::GenerateWorkspace2d);
}

bool NamesGenerator3d(const YAML::Node& node) {
  if (!node.IsMap() || !node["generator"] || !node["generator"].IsScalar()) return false;
  const std::vector<std::string> names = envs::Generator3dNames();
  return std::find(names.begin(), names.end(), node["generator"].Scalar()) != names.end();
}

envs::Workspace3d ReadGeneratedWorkspace3d(const YamlFile& file, const YAML::Node& node,
                                           const std::string& key, std::string* label) {
  return ReadGenerated<envs::Generator3dParameters>(
      file, node, key, label,
      [](const std::string& name, std::uint64_t seed, const envs::Generator3dParameters& p) {
        return envs::GenerateWorkspace3d(name, seed, p);
      });
}

void ReadAcdSamplerOptions(const YamlFile& file, const YAML::Node& node, const std::string& key,
                           AcdSamplerOptions* options) {
  auto child = [&key](const char* name) { return YamlFile::Child(key, name); };
  if (node["uniform_share"]) {
    options->uniform_share = file.Number(node["uniform_share"], child("uniform_share"),
                                         "a number in [0, 1]", UnitInterval);
  }
  if (node["opening_weight"]) {
    options->opening_weight =
        file.Number(node["opening_weight"], child("opening_weight"), "a number >= 0", NonNegative);
  }
  if (node["centroid_spread"]) {
    options->centroid_spread = file.Number(node["centroid_spread"], child("centroid_spread"),
                                           "a positive number", Positive);
  }
  if (node["opening_spread"]) {
    options->opening_spread =
        file.Number(node["opening_spread"], child("opening_spread"), "a positive number", Positive);
  }
  if (node["max_attempts"]) {
    options->max_attempts = static_cast<int>(
        file.Integer(node["max_attempts"], child("max_attempts"), "an integer >= 1", 1));
  }
  if (node["aligned_jitter"]) {
    options->aligned_jitter = file.Number(node["aligned_jitter"], child("aligned_jitter"),
                                          "a number >= 0 [rad]", NonNegative);
  }
  if (node["orientation"]) {
    options->orientation =
        file.Parsed(node["orientation"], child("orientation"), ParseAcdOrientation);
  }
}

namespace {

/// ReadRobot() without its check of the mapping's keys.
envs::Robot ReadRobotBody(const YamlFile& file, const YAML::Node& node, const std::string& key) {
  auto child = [&key](const char* name) { return YamlFile::Child(key, name); };
  const envs::RobotShape shape =
      node["shape"] ? file.Parsed(node["shape"], child("shape"), envs::ParseRobotShape)
                    : envs::RobotShape::kPoint;
  if (node["radius"] && shape != envs::RobotShape::kDisc) {
    file.Fail(child("radius"), "only for shape disc");
  }
  if (node["polygon"] && shape != envs::RobotShape::kPolygon) {
    file.Fail(child("polygon"), "only for shape polygon");
  }
  if (node["mesh"] && shape != envs::RobotShape::kMesh) {
    file.Fail(child("mesh"), "only for shape mesh");
  }
  try {
    switch (shape) {
      case envs::RobotShape::kPoint:
        return envs::Robot::Point();
      case envs::RobotShape::kDisc:
        if (!node["radius"]) file.Fail(child("radius"), "required for shape disc");
        return envs::Robot::Disc(
            file.Number(node["radius"], child("radius"), "a positive number", Positive));
      case envs::RobotShape::kPolygon: {
        const YAML::Node& list = node["polygon"];
        if (!list) file.Fail(child("polygon"), "required for shape polygon");
        if (!list.IsSequence() || list.size() < 3) {
          file.Fail(child("polygon"), "expected a list of at least 3 [x, y] pairs");
        }
        acd::Polygon2d outline;
        for (size_t i = 0; i < list.size(); ++i) {
          const std::string item = YamlFile::Item(child("polygon"), i);
          const std::vector<double> xy = file.Numbers(list[i], item, 2, "an [x, y] pair");
          outline.outer.emplace_back(xy[0], xy[1]);
        }
        if (acd::SignedArea(outline.outer) < 0) outline.outer = acd::Reversed(outline.outer);
        return envs::Robot::Polygon(outline);
      }
      case envs::RobotShape::kMesh: {
        if (!node["mesh"]) file.Fail(child("mesh"), "required for shape mesh (a mesh file)");
        const std::string mesh = file.ResolvePath(file.String(node["mesh"], child("mesh")));
        return envs::Robot::Mesh(envs::ReadMesh(mesh));
      }
    }
  } catch (const InputError& error) {
    const std::string what = error.what();
    if (what.rfind(file.path() + ": ", 0) == 0) throw;
    file.Fail(key, what);
  }
  file.Fail(child("shape"), "unknown robot shape");
}

}  // namespace

envs::Robot ReadRobot(const YamlFile& file, const YAML::Node& node, const std::string& key) {
  file.CheckKeys(node, key, {"shape", "radius", "polygon", "mesh"});
  return ReadRobotBody(file, node, key);
}

bool NamesCarRobot(const YAML::Node& node) { return node.IsMap() && node["type"]; }

CarRobot ReadCarRobot(const YamlFile& file, const YAML::Node& node, const std::string& key) {
  auto child = [&key](const char* name) { return YamlFile::Child(key, name); };
  file.CheckKeys(
      node, key,
      {"type", "length", "width", "max_speed", "max_steer", "max_accel", "max_steer_rate", "step",
       "min_control_steps", "max_control_steps", "shape", "radius", "polygon"});
  CarRobot car;
  car.model = file.Parsed(node["type"], child("type"), control::ParseCarModel);
  control::CarOptions& o = car.options;
  auto positive = [&](const char* name, double* value) {
    if (node[name]) *value = file.Number(node[name], child(name), "a positive number", Positive);
  };
  positive("length", &o.length);
  positive("max_speed", &o.max_speed);
  positive("step", &o.step);
  if (node["max_steer"]) {
    o.max_steer = file.Number(node["max_steer"], child("max_steer"), "a number in (0, pi/2) [rad]",
                              [](double x) { return x > 0 && x < M_PI / 2; });
  }
  for (const char* name : {"max_accel", "max_steer_rate"}) {
    if (node[name] && car.model != control::CarModel::kDynamic) {
      file.Fail(child(name),
                "only for type dynamic_car (the kinematic car's controls are its "
                "speed and steering angle)");
    }
  }
  positive("max_accel", &o.max_accel);
  positive("max_steer_rate", &o.max_steer_rate);
  if (node["min_control_steps"]) {
    o.min_control_steps = static_cast<unsigned>(
        file.Integer(node["min_control_steps"], child("min_control_steps"), "an integer >= 1", 1));
  }
  if (node["max_control_steps"]) {
    o.max_control_steps = static_cast<unsigned>(
        file.Integer(node["max_control_steps"], child("max_control_steps"), "an integer >= 1", 1));
  }
  if (o.max_control_steps < o.min_control_steps) {
    file.Fail(child("max_control_steps"), "expected >= min_control_steps (" +
                                              std::to_string(o.min_control_steps) + "), got " +
                                              std::to_string(o.max_control_steps));
  }
  const bool own_shape = node["shape"] || node["radius"] || node["polygon"];
  if (own_shape && node["width"]) {
    file.Fail(child("width"), "not with shape (width is the default rectangle body's)");
  }
  if (own_shape) {
    if (node["shape"] && node["shape"].IsScalar() && node["shape"].Scalar() == "mesh") {
      file.Fail(child("shape"), "a car's body is 2D: point, disc or polygon");
    }
    car.body = ReadRobotBody(file, node, key);
  } else {
    const double half_length = o.length / 2;
    const double half_width =
        node["width"]
            ? file.Number(node["width"], child("width"), "a positive number", Positive) / 2
            : o.length / 4;
    acd::Polygon2d rectangle;
    rectangle.outer = {{-half_length, -half_width},
                       {half_length, -half_width},
                       {half_length, half_width},
                       {-half_length, half_width}};
    car.body = envs::Robot::Polygon(rectangle);
  }
  return car;
}

double ReadTauDiag(const YamlFile& file, const YAML::Node& acd, const std::string& key,
                   double fallback, std::vector<std::string>* warnings) {
  const std::string diag_key = YamlFile::Child(key, "tau_diag");
  const std::string rel_key = YamlFile::Child(key, "tau_rel");
  if (acd["tau_diag"] && acd["tau_rel"]) {
    file.Fail(rel_key, "give tau_diag only (tau_rel is its older spelling)");
  }
  if (acd["tau_diag"]) return file.Number(acd["tau_diag"], diag_key, "a number >= 0", NonNegative);
  if (!acd["tau_rel"]) return fallback;
  warnings->push_back(file.path() + ": " + rel_key +
                      ": read as tau_diag, the tolerance relative to the bounds' diagonal; "
                      "write tau_diag (tau_rel is relative to the reference radius in "
                      "acdplan decompose)");
  return file.Number(acd["tau_rel"], rel_key, "a number >= 0", NonNegative);
}

}  // namespace acdplan::planning
