#pragma once
// The parts of a scenario's YAML that benchmark definitions share: a generated workspace, a
// robot, the ACD sampler's options. Errors name the file and the key path (base/yaml_file.h).

#include <string>
#include <vector>

#include "base/yaml_file.h"
#include "envs/robot.h"
#include "envs/workspace2d.h"
#include "envs/workspace3d.h"
#include "planning/acd_sampler_options.h"
#include "planning/control/car.h"

namespace acdplan::planning {

/// A generated workspace from `{generator, seed, passage_width, wall_thickness}` at `key`
/// (envs::GenerateWorkspace2d); `*label` becomes "generator <name> (seed s)".
/// @throws InputError "<file>: <key>...: <rule>".
envs::Workspace2d ReadGeneratedWorkspace(const YamlFile& file, const YAML::Node& node,
                                         const std::string& key, std::string* label);

/// Whether mapping `node` names a 3D generator (envs::Generator3dNames()) as its `generator`.
bool NamesGenerator3d(const YAML::Node& node);

/// A generated 3D workspace from `{generator, seed, passage_width, wall_thickness}` at `key`
/// (envs::GenerateWorkspace3d: passage_width is the window, mouth, hatch or tube side);
/// `*label` becomes "generator <name> (seed s)".
/// @throws InputError "<file>: <key>...: <rule>".
envs::Workspace3d ReadGeneratedWorkspace3d(const YamlFile& file, const YAML::Node& node,
                                           const std::string& key, std::string* label);

/// The ACD sampler options present in mapping `node` at `key` (uniform_share, opening_weight,
/// centroid_spread, opening_spread, max_attempts, orientation, aligned_jitter) into `*options`;
/// the caller
/// checks which keys the mapping may hold.
/// @throws InputError "<file>: <key>.<option>: <rule>".
void ReadAcdSamplerOptions(const YamlFile& file, const YAML::Node& node, const std::string& key,
                           AcdSamplerOptions* options);

/// A robot from `{shape: point | disc (radius) | polygon (polygon: [[x, y], ...]) | mesh (mesh:
/// FILE, relative to the YAML file, any envs::ReadMesh() format)}` at `key`.
/// @throws InputError "<file>: <key>...: <rule>".
envs::Robot ReadRobot(const YamlFile& file, const YAML::Node& node, const std::string& key);

/// A car read from a robot mapping (ReadCarRobot()).
struct CarRobot {
  envs::Robot body;  ///< The length x width rectangle, or the mapping's `shape`.
  control::CarModel model = control::CarModel::kKinematic;
  control::CarOptions options;
};

/// Whether the robot mapping `node` has a `type` (a control-space robot: a car).
bool NamesCarRobot(const YAML::Node& node);

/// A car from `{type: kinematic_car | dynamic_car, length, width, max_speed, max_steer,
/// max_accel, max_steer_rate, step, min_control_steps, max_control_steps}` at `key`, its body
/// the length x width rectangle centred on the car's (x, y) (width default length / 2) unless
/// the mapping gives `shape` (point, disc, polygon; as ReadRobot()). The dynamic car's keys
/// (max_accel, max_steer_rate) are errors for the kinematic car.
/// @throws InputError "<file>: <key>.<field>: <rule>".
CarRobot ReadCarRobot(const YamlFile& file, const YAML::Node& node, const std::string& key);

/// The ACD tolerance relative to the bounds' diagonal: key `tau_diag` of mapping `acd` (at
/// key path `key`), or its older spelling `tau_rel`, accepted with a line in `*warnings`
/// (tau_rel also names `acdplan decompose --tau-rel`, relative to the reference radius);
/// `fallback` when neither is there.
/// @throws InputError if both are given or the value is not a number >= 0.
double ReadTauDiag(const YamlFile& file, const YAML::Node& acd, const std::string& key,
                   double fallback, std::vector<std::string>* warnings);

}  // namespace acdplan::planning
