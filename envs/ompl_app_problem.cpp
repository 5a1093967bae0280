#include "envs/ompl_app_problem.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/input_error.h"
#include "envs/mesh_loader.h"

namespace acdplan::envs {
namespace {

/// OMPL.app's planner names (BenchmarkOptions' KNOWN_PLANNERS and the ones later releases
/// added), with ours where we run it ("" where we do not).
const std::vector<std::pair<std::string, std::string>>& PlannerNameTable() {
  static const std::vector<std::pair<std::string, std::string>> table = {
      {"prm", "PRM"},         {"prmstar", "PRMstar"},
      {"lazyprm", "LazyPRM"}, {"lazyprmstar", ""},
      {"rrt", "RRT"},         {"rrtconnect", "RRTConnect"},
      {"rrtstar", "RRTstar"}, {"lazyrrt", ""},
      {"est", "EST"},         {"sbl", "SBL"},
      {"kpiece", "KPIECE1"},  {"bkpiece", "BKPIECE1"},
      {"lbkpiece", ""},       {"stride", ""},
      {"pdst", ""},           {"spars", ""},
      {"spars2", ""},         {"lbtrrt", ""},
      {"trrt", ""},           {"fmt", ""},
      {"cforest", ""},        {"aps", ""},
      {"sycloprrt", ""},      {"syclopest", ""},
  };
  return table;
}

/// OMPL.app's control planner names and ours (planning/control/plan_car.h).
const std::vector<std::pair<std::string, std::string>>& ControlPlannerNameTable() {
  static const std::vector<std::pair<std::string, std::string>> table = {
      {"rrt", "RRT"},   {"kpiece", "KPIECE1"},      {"est", "EST"},
      {"pdst", "PDST"}, {"sycloprrt", "SyclopRRT"}, {"syclopest", "SyclopEST"},
      {"sst", ""},
  };
  return table;
}

/// OMPL.app's valid-state sampler names and ours.
const std::vector<std::pair<std::string, std::string>>& SamplerNameTable() {
  static const std::vector<std::pair<std::string, std::string>> table = {
      {"uniform", "uniform"},
      {"gaussian", "gaussian"},
      {"obstacle_based", "obstacle_based"},
      {"max_clearance", "max_clearance"},
      {"bridge_test", "bridge"},
  };
  return table;
}

std::string Trim(const std::string& s) {
  size_t begin = 0, end = s.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(s[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(s[end - 1]))) --end;
  return s.substr(begin, end - begin);
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool StartsWith(const std::string& s, const std::string& prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

/// One `key=value` line of the file.
struct Entry {
  std::string key, value;
  int line = 0;
};

/// The file as sections of entries, in file order (an INI reader: `[section]`, `key=value`,
/// comments from `#` anywhere (as boost::program_options reads these files) or `;` at the
/// start of a line, blank lines).
struct IniFile {
  std::string path;
  std::map<std::string, int> section_lines;  ///< Section name -> its header's line.
  std::map<std::string, std::vector<Entry>> sections;
};

IniFile ReadIni(const std::string& path) {
  if (const std::string reason = UnreadableFileReason(path); !reason.empty()) {
    throw InputError(path + ":0: cannot read the file: " + reason);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ":0: cannot read the file: " + std::strerror(errno));
  acd::internal::SkipByteOrderMark(in);
  IniFile ini;
  ini.path = path;
  std::string text, section;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const std::string where = path + ":" + std::to_string(line) + ": ";
    const size_t hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    text = Trim(text);
    if (text.empty() || text[0] == ';') continue;
    if (text[0] == '[') {
      if (text.back() != ']') throw InputError(where + "expected '[section]', got '" + text + "'");
      section = Lower(Trim(text.substr(1, text.size() - 2)));
      if (section.empty()) throw InputError(where + "empty section name '[]'");
      if (!ini.section_lines.count(section)) ini.section_lines[section] = line;
      continue;
    }
    const size_t equals = text.find('=');
    if (equals == std::string::npos) {
      throw InputError(where + "expected 'key=value' or '[section]', got '" + text + "'");
    }
    Entry entry{Lower(Trim(text.substr(0, equals))), Trim(text.substr(equals + 1)), line};
    if (entry.key.empty()) throw InputError(where + "a line '=" + entry.value + "' has no key");
    if (section.empty()) {
      throw InputError(where + entry.key +
                       ": outside any section (start with [problem], [benchmark] or [planner])");
    }
    ini.sections[section].push_back(std::move(entry));
  }
  return ini;
}

/// The entries of one section by key, refusing keys given twice.
class KeyTable {
 public:
  KeyTable(const IniFile& ini, const std::string& section) : path_(ini.path) {
    const auto header = ini.section_lines.find(section);
    header_line_ = header == ini.section_lines.end() ? 0 : header->second;
    const auto it = ini.sections.find(section);
    if (it == ini.sections.end()) return;
    for (const Entry& entry : it->second) {
      const auto [previous, inserted] = entries_.emplace(entry.key, entry);
      if (!inserted) {
        Fail(entry, "given twice (first on line " + std::to_string(previous->second.line) + ")");
      }
    }
  }

  const Entry* Find(const std::string& key) const {
    const auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : &it->second;
  }
  bool Has(const std::string& key) const { return entries_.count(key) > 0; }
  int header_line() const { return header_line_; }
  const std::map<std::string, Entry>& entries() const { return entries_; }

  [[noreturn]] void Fail(const Entry& entry, const std::string& rule) const {
    Fail(entry.line, entry.key, rule);
  }
  [[noreturn]] void Fail(int line, const std::string& key, const std::string& rule) const {
    throw InputError(path_ + ":" + std::to_string(line) + ": " + key + ": " + rule);
  }

  double Number(const Entry& entry) const {
    const char* begin = entry.value.c_str();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    if (entry.value.empty() || end != begin + entry.value.size() || errno == ERANGE ||
        !std::isfinite(value)) {
      Fail(entry, "expected a number, got '" + entry.value + "'");
    }
    return value;
  }
  double Number(const std::string& key) const { return Number(*Find(key)); }

 private:
  std::string path_;
  int header_line_ = 0;
  std::map<std::string, Entry> entries_;
};

/// OMPL.app's RigidBodyGeometry::getRobotCenter(): the mean of every vertex of the scene as
/// assimp imports it with OMPL.app's flags (so vertices are split where their normals differ),
/// each moved by its node's transform.
Eigen::Vector3d OmplAppRobotCenter(const std::string& mesh_path, const std::string& where) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      mesh_path, aiProcess_GenNormals | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                     aiProcess_SortByPType | aiProcess_OptimizeGraph);
  if (scene == nullptr || !scene->HasMeshes()) {
    throw InputError(where + ": cannot read mesh: " + importer.GetErrorString());
  }
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  long long count = 0;
  struct Visit {
    const aiScene* scene;
    Eigen::Vector3d* sum;
    long long* count;
    void operator()(const aiNode* node, aiMatrix4x4 transform) const {
      transform *= node->mTransformation;
      for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        const aiMesh* mesh = scene->mMeshes[node->mMeshes[i]];
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
          const aiVector3D p = transform * mesh->mVertices[v];
          *sum += Eigen::Vector3d(p.x, p.y, p.z);
          ++*count;
        }
      }
      for (unsigned n = 0; n < node->mNumChildren; ++n) (*this)(node->mChildren[n], transform);
    }
  };
  Visit{scene, &sum, &count}(scene->mRootNode, aiMatrix4x4());
  if (count == 0) throw InputError(where + ": no vertices in the robot's scene");
  return sum / static_cast<double>(count);
}

/// OMPL's SO3StateSpace::StateType::setAxisAngle(): a zero axis gives the identity.
Eigen::Matrix3d AxisAngle(const Eigen::Vector3d& axis, double theta) {
  const double norm = axis.norm();
  if (norm < 1e-9) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(theta, axis / norm).toRotationMatrix();
}

const char* const k3dPoseKeys[] = {"start.z", "start.axis.x", "start.axis.y", "start.axis.z",
                                   "goal.z",  "goal.axis.x",  "goal.axis.y",  "goal.axis.z"};
const char* const kPlanarPoseKeys[] = {"start.x", "start.y", "start.theta",
                                       "goal.x",  "goal.y",  "goal.theta"};

/// Decides 2 or 3 as OMPL.app's isSE2Problem / isSE3Problem, with an error naming the key
/// that makes the file neither.
int Dimension(const KeyTable& problem) {
  const Entry* first_3d = nullptr;
  for (const char* key : k3dPoseKeys) {
    const Entry* entry = problem.Find(key);
    if (entry != nullptr && (first_3d == nullptr || entry->line < first_3d->line)) {
      first_3d = entry;
    }
  }
  for (const char* key : kPlanarPoseKeys) {
    if (!problem.Has(key)) {
      const std::string kind = first_3d ? "a 3D problem (" + first_3d->key + " is given on line " +
                                              std::to_string(first_3d->line) +
                                              ") needs start and goal x, y, z, theta, "
                                              "axis.x, axis.y, axis.z"
                                        : "a 2D problem needs start and goal x, y, theta";
      problem.Fail(first_3d ? first_3d->line : problem.header_line(), key, "missing; " + kind);
    }
  }
  if (first_3d == nullptr) return 2;
  for (const char* key : k3dPoseKeys) {
    if (!problem.Has(key)) {
      problem.Fail(first_3d->line, key,
                   "missing; a 3D problem (" + first_3d->key +
                       " is given here) needs start and "
                       "goal x, y, z, theta, axis.x, axis.y, axis.z (a 2D problem has none of z "
                       "and axis)");
    }
  }
  return 3;
}

Eigen::Isometry3d ReadPose(const KeyTable& problem, const std::string& which, int dimension) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const double theta = problem.Number(which + ".theta");
  if (dimension == 2) {
    pose.translation() =
        Eigen::Vector3d(problem.Number(which + ".x"), problem.Number(which + ".y"), 0.0);
    pose.linear() = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  } else {
    pose.translation() = Eigen::Vector3d(problem.Number(which + ".x"), problem.Number(which + ".y"),
                                         problem.Number(which + ".z"));
    pose.linear() = AxisAngle(
        Eigen::Vector3d(problem.Number(which + ".axis.x"), problem.Number(which + ".axis.y"),
                        problem.Number(which + ".axis.z")),
        theta);
  }
  return pose;
}

std::string ResolvePath(const std::string& cfg, const std::string& file) {
  return (std::filesystem::path(cfg).parent_path() / file).lexically_normal().string();
}

acd::TriangleMesh ReadMeshAt(const KeyTable& problem, const Entry& entry, const std::string& path) {
  try {
    return ReadMesh(path);
  } catch (const InputError& error) {
    problem.Fail(entry, error.what());
  }
}

/// Our sampler name for OMPL.app's `value`.
std::string SamplerName(const KeyTable& table, const Entry& entry) {
  std::vector<std::string> known;
  for (const auto& [ompl_app, ours] : SamplerNameTable()) {
    if (entry.value == ompl_app) return ours;
    known.push_back(ompl_app);
  }
  table.Fail(entry, UnknownName("sampler", entry.value, known));
}

void ReadBounds(const KeyTable& problem, OmplAppProblem* p) {
  const std::vector<std::string> axes = p->dimension == 2 ? std::vector<std::string>{"x", "y"}
                                                          : std::vector<std::string>{"x", "y", "z"};
  std::vector<const Entry*> given;
  for (const std::string& axis : axes) {
    for (const char* side : {"volume.min.", "volume.max."}) {
      if (const Entry* entry = problem.Find(side + axis)) given.push_back(entry);
    }
  }
  if (p->dimension == 2) {
    for (const char* key : {"volume.min.z", "volume.max.z"}) {
      if (const Entry* entry = problem.Find(key)) {
        p->warnings.push_back(p->path + ":" + std::to_string(entry->line) + ": " + key +
                              ": ignored in a 2D problem");
      }
    }
  }
  if (given.empty()) {
    if (p->world.vertices.rows() == 0) {
      problem.Fail(problem.header_line(), "volume.min.x",
                   "missing; without a world the volume bounds are required");
    }
    p->bounds = acd::BoundingBox(p->world);
    if (p->dimension == 2) p->bounds.min().z() = p->bounds.max().z() = 0.0;
    return;
  }
  const int expected = 2 * static_cast<int>(axes.size());
  if (static_cast<int>(given.size()) != expected) {
    for (const std::string& axis : axes) {
      for (const char* side : {"volume.min.", "volume.max."}) {
        if (!problem.Has(side + axis)) {
          problem.Fail(given.front()->line, side + axis,
                       "missing; give every volume.min/max key of the problem's dimension or "
                       "none (then the world's bounding box is used)");
        }
      }
    }
  }
  p->bounds_from_file = true;
  p->bounds.setEmpty();
  Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < axes.size(); ++i) {
    const Entry& min = *problem.Find("volume.min." + axes[i]);
    const Entry& max = *problem.Find("volume.max." + axes[i]);
    low[static_cast<Eigen::Index>(i)] = problem.Number(min);
    high[static_cast<Eigen::Index>(i)] = problem.Number(max);
    if (!(high[static_cast<Eigen::Index>(i)] > low[static_cast<Eigen::Index>(i)])) {
      problem.Fail(max,
                   "expected a number > " + min.key + " (" + min.value + "), got " + max.value);
    }
  }
  p->bounds = Eigen::AlignedBox3d(low, high);
}

void ReadBenchmark(const IniFile& ini, OmplAppProblem* p) {
  const KeyTable bench(ini, "benchmark");
  for (const auto& [key, entry] : bench.entries()) {
    if (key == "time_limit") {
      p->time_limit = bench.Number(entry);
      if (!(p->time_limit > 0)) bench.Fail(entry, "expected a number > 0, got " + entry.value);
    } else if (key == "mem_limit") {
      p->mem_limit = bench.Number(entry);
      if (!(p->mem_limit >= 0)) bench.Fail(entry, "expected a number >= 0, got " + entry.value);
    } else if (key == "run_count") {
      const double runs = bench.Number(entry);
      if (!(runs >= 1) || runs != std::floor(runs) || runs > 1e9) {
        bench.Fail(entry, "expected an integer >= 1, got " + entry.value);
      }
      p->run_count = static_cast<int>(runs);
    } else if (key == "output" || key == "save_paths") {
      p->warnings.push_back(p->path + ":" + std::to_string(entry.line) + ": benchmark." + key +
                            ": ignored (acdplan bench chooses its own outputs)");
    } else {
      p->warnings.push_back(p->path + ":" + std::to_string(entry.line) + ": benchmark." + key +
                            ": unknown to OMPL.app; ignored");
    }
  }
}

/// The [planner] section as OMPL.app's BenchmarkOptions::readOptions() reads it: `name=`
/// starts a copy, `name.param=` sets a parameter of that planner's last copy (starting one if
/// there is none), `problem.key=` goes to the copy before it (or the next one, when none is
/// before it).
void ReadPlanners(const IniFile& ini, OmplAppProblem* p) {
  const auto section = ini.sections.find("planner");
  if (section == ini.sections.end()) return;
  // A car's problem names control planners.
  const std::vector<std::pair<std::string, std::string>>& planner_names =
      p->control.empty() ? PlannerNameTable() : ControlPlannerNameTable();
  std::vector<std::string> available;
  for (const auto& [ompl_app, ours] : planner_names) {
    if (!ours.empty()) available.push_back(ompl_app);
  }
  std::vector<std::pair<std::string, std::string>> pending_context;
  OmplAppPlanner* last = nullptr;
  auto fail = [p](const Entry& entry, const std::string& rule) {
    throw InputError(p->path + ":" + std::to_string(entry.line) + ": " + rule);
  };
  for (const Entry& entry : section->second) {
    if (StartsWith(entry.key, "problem.")) {
      const std::string key = entry.key.substr(8);
      if (key == "sampler") {
        bool known = false;
        for (const auto& [ompl_app, ours] : SamplerNameTable()) known |= entry.value == ompl_app;
        if (!known) {
          std::vector<std::string> names;
          for (const auto& [ompl_app, ours] : SamplerNameTable()) names.push_back(ompl_app);
          fail(entry, entry.key + ": " + UnknownName("sampler", entry.value, names));
        }
      }
      if (last == nullptr) {
        pending_context.emplace_back(key, entry.value);
      } else {
        last->context.emplace_back(key, entry.value);
      }
      continue;
    }
    // The longest OMPL.app name that `key` is or starts with followed by a '.'.
    std::string name, ours;
    for (const auto& [ompl_app, mapped] : planner_names) {
      if ((entry.key == ompl_app || StartsWith(entry.key, ompl_app + ".")) &&
          ompl_app.size() > name.size()) {
        name = ompl_app;
        ours = mapped;
      }
    }
    if (name.empty()) {
      std::vector<std::string> known;
      for (const auto& [ompl_app, mapped] : planner_names) known.push_back(ompl_app);
      const std::string planner = entry.key.substr(0, entry.key.find('.'));
      fail(entry, UnknownName("planner", planner, known));
    }
    if (ours.empty()) {
      fail(entry, "planner '" + name +
                      "' is not available in acdplan (available: " + JoinNames(available) + ")");
    }
    OmplAppPlanner* copy = nullptr;
    if (entry.key != name) {
      for (auto it = p->planners.rbegin(); it != p->planners.rend(); ++it) {
        if (it->ompl_app_name == name) {
          copy = &*it;
          break;
        }
      }
    }
    if (copy == nullptr) {
      p->planners.push_back({name, ours, {}, pending_context, entry.line});
      pending_context.clear();
      copy = &p->planners.back();
    }
    if (entry.key != name)
      copy->parameters.emplace_back(entry.key.substr(name.size() + 1), entry.value);
    last = copy;
  }
  if (!pending_context.empty()) {
    const Entry& entry = section->second.back();
    p->warnings.push_back(p->path + ":" + std::to_string(entry.line) +
                          ": planner problem.* settings after no planner; ignored");
  }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> OmplAppPlannerTable() {
  std::vector<std::pair<std::string, std::string>> result;
  for (const auto& entry : PlannerNameTable()) {
    if (!entry.second.empty()) result.push_back(entry);
  }
  return result;
}

OmplAppProblem ReadOmplAppProblem(const std::string& path) {
  const IniFile ini = ReadIni(path);
  OmplAppProblem p;
  p.path = path;
  for (const auto& [section, line] : ini.section_lines) {
    if (section != "problem" && section != "benchmark" && section != "planner") {
      p.warnings.push_back(path + ":" + std::to_string(line) + ": [" + section +
                           "]: unknown section; ignored (OMPL.app reads [problem], [benchmark] "
                           "and [planner])");
    }
  }
  if (!ini.section_lines.count("problem")) {
    throw InputError(path +
                     ":0: [problem]: missing; the robot, the world and the query are "
                     "given there");
  }
  const KeyTable problem(ini, "problem");
  if (const Entry* control = problem.Find("control")) {
    std::string name = control->value;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) {
      return c == ' ' ? '_' : static_cast<char>(std::tolower(c));
    });
    if (name != "kinematic_car" && name != "dynamic_car") {
      problem.Fail(*control, "'" + control->value +
                                 "' is not supported (acdplan plans kinematic_car and "
                                 "dynamic_car; OMPL.app's blimp and quadrotor are 3D)");
    }
    p.control = name;
  }
  static const std::set<std::string> kKnown = {"name",         "robot",
                                               "world",        "start.x",
                                               "start.y",      "start.z",
                                               "start.theta",  "start.axis.x",
                                               "start.axis.y", "start.axis.z",
                                               "goal.x",       "goal.y",
                                               "goal.z",       "goal.theta",
                                               "goal.axis.x",  "goal.axis.y",
                                               "goal.axis.z",  "volume.min.x",
                                               "volume.min.y", "volume.min.z",
                                               "volume.max.x", "volume.max.y",
                                               "volume.max.z", "sampler",
                                               "objective",    "objective.threshold",
                                               "threshold",    "solution_length",
                                               "control"};
  for (const auto& [key, entry] : problem.entries()) {
    if (!kKnown.count(key)) {
      p.warnings.push_back(path + ":" + std::to_string(entry.line) + ": " + key +
                           ": an OMPL.app state-space setting; ignored");
    }
  }
  p.name = problem.Has("name") ? problem.Find("name")->value
                               : std::filesystem::path(path).stem().string();
  p.dimension = Dimension(problem);
  if (!p.control.empty() && p.dimension != 2) {
    problem.Fail(*problem.Find("control"),
                 "a car needs a 2D problem (start and goal x, y, theta), not a 3D one");
  }
  p.start = ReadPose(problem, "start", p.dimension);
  p.goal = ReadPose(problem, "goal", p.dimension);
  if (const Entry* sampler = problem.Find("sampler")) p.sampler = SamplerName(problem, *sampler);
  if (const Entry* objective = problem.Find("objective")) p.objective = objective->value;
  if (const Entry* threshold = problem.Find("objective.threshold")) {
    p.objective_threshold = problem.Number(*threshold);
  }
  if (const Entry* threshold = problem.Find("threshold")) {
    p.goal_threshold = problem.Number(*threshold);
    if (!(p.goal_threshold >= 0)) {
      problem.Fail(*threshold, "expected a number >= 0, got " + threshold->value);
    }
  }
  if (const Entry* length = problem.Find("solution_length")) problem.Number(*length);

  const Entry* robot = problem.Find("robot");
  if (robot == nullptr || robot->value.empty()) {
    problem.Fail(robot ? robot->line : problem.header_line(), "robot",
                 "missing; the robot's mesh file is required");
  }
  p.robot_path = ResolvePath(path, robot->value);
  const acd::TriangleMesh robot_mesh = ReadMeshAt(problem, *robot, p.robot_path);
  try {
    p.robot_center = OmplAppRobotCenter(p.robot_path, p.robot_path);
  } catch (const InputError& error) {
    problem.Fail(*robot, error.what());
  }
  if (p.dimension == 2) p.robot_center.z() = 0.0;
  p.robot = robot_mesh;
  p.robot.vertices.rowwise() -= p.robot_center.transpose();
  if (const Entry* world = problem.Find("world")) {
    if (world->value.empty()) problem.Fail(*world, "expected a mesh file name");
    p.world_path = ResolvePath(path, world->value);
    p.world = ReadMeshAt(problem, *world, p.world_path);
  }
  ReadBounds(problem, &p);
  ReadBenchmark(ini, &p);
  ReadPlanners(ini, &p);
  return p;
}

Workspace3d OmplAppWorkspace3d(const OmplAppProblem& problem) {
  Workspace3d world;
  world.bounds = problem.bounds;
  if (problem.world.vertices.rows() > 0) world.obstacles.push_back(problem.world);
  world.description = "OMPL.app problem " + problem.name;
  return world;
}

}  // namespace acdplan::envs
