#include "bench/runner.h"

#include <ompl/util/Console.h>
#include <poll.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <sstream>

#include "base/input_error.h"
#include "base/stopwatch.h"
#include "collision/collision_mode.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/decomposition_cache.h"
#include "planning/plan_scenario.h"

namespace acdplan::bench {

namespace {

using planning::Scenario;

/// `q` with the dimension `robot` plans in: [x, y, yaw] for a polygon or a car (yaw 0 if
/// absent), [x, y] otherwise.
std::vector<double> Fitted(std::vector<double> q, const envs::Robot& robot, bool car = false) {
  if (car || robot.shape == envs::RobotShape::kPolygon) {
    if (q.size() == 2) q.push_back(0.0);
  } else {
    q.resize(2);
  }
  return q;
}

Scenario RunScenario(const BenchSpec& spec, const BenchCase& c, std::uint64_t seed) {
  const BenchWorld& world = spec.worlds[c.world];
  const BenchRobot& robot = spec.robots[c.robot];
  Scenario s = world.scenario;
  s.path = spec.path;
  if (!robot.from_scenario) s.robot = robot.robot;
  if (c.control) {
    // A car: the robot's model and bounds (or the world scenario's own car), the case's control
    // planner and decomposition, the world scenario's goal radius.
    planning::CarScenario car;
    if (world.scenario.car) car = *world.scenario.car;
    if (robot.car) car.model = robot.car->model, car.options = robot.car->options;
    car.planner = c.control_planner;
    if (c.decomposition) {
      car.decomposition = c.decomposition->kind;
      car.grid_cells = std::max(1, c.decomposition->cells);
    }
    s.car = car;
    s.start = Fitted(s.start, s.robot, true);
    s.goal = Fitted(s.goal, s.robot, true);
    s.samples = 0;
    s.time_limit = c.budget.time_limit;
    s.seed = seed;
    return s;
  }
  s.car.reset();
  if (s.dimension == 3) {
    // A 3D world keeps its poses ([x, y, z] for a point, 6 numbers for a mesh robot).
    if (s.robot.shape == envs::RobotShape::kPoint) s.start.resize(3), s.goal.resize(3);
  } else {
    s.start = Fitted(s.start, s.robot);
    s.goal = Fitted(s.goal, s.robot);
  }
  s.sampler = c.sampler;
  s.planner = c.planner;
  s.samples = c.budget.samples;
  if (c.budget.samples == 0) s.time_limit = c.budget.time_limit;
  s.sampler_options = robot.acd_options;
  if (s.dimension == 3 && robot.from_scenario) {
    // The scenario's own robot in 3D: its orientation law (aligned for a mesh) and spread.
    s.sampler_options.orientation = world.scenario.sampler_options.orientation;
    s.sampler_options.aligned_jitter = world.scenario.sampler_options.aligned_jitter;
  }
  s.seed = seed;
  return s;
}

/// The pose of configuration `q` ([x, y] or [x, y, yaw]).
Eigen::Isometry2d Pose(const std::vector<double>& q) {
  Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
  pose.translate(Eigen::Vector2d(q[0], q[1]));
  if (q.size() == 3) pose.rotate(q[2]);
  return pose;
}

/// As PlanScenario's validity checker: the robot inside the bounds and free of obstacles.
bool Fits(const collision::CollisionWorld& world, const envs::Robot& robot,
          const Eigen::AlignedBox2d& bounds, const Eigen::Isometry2d& pose) {
  return envs::InsideBounds(robot, bounds, pose) && world.IsValid(pose);
}

/// Fails before any run if a robot does not fit at a world's start or goal.
void CheckQueries(const BenchSpec& spec) {
  std::set<std::pair<int, int>> pairs;
  for (const BenchCase& c : spec.cases) pairs.insert({c.world, c.robot});
  std::map<int, std::shared_ptr<const collision::ObstacleSet>> obstacles;
  for (const auto& [w, r] : pairs) {
    const BenchWorld& world = spec.worlds[w];
    // 3D worlds: PlanScenario3d() checks the start and the goal of each run (an InputError).
    if (world.scenario.dimension == 3) continue;
    const BenchRobot& robot = spec.robots[r];
    if (!obstacles.count(w)) {
      obstacles[w] = std::make_shared<const collision::ObstacleSet>(
          collision::BuildObstacleSet(world.scenario.workspace));
    }
    collision::CollisionWorldOptions options;
    options.mode = world.scenario.collision_mode;
    const envs::Robot& body = robot.from_scenario ? world.scenario.robot : robot.robot;
    const bool car = robot.car.has_value() || (robot.from_scenario && world.scenario.car);
    const collision::CollisionWorld check(obstacles[w], body, options);
    const Eigen::AlignedBox2d& bounds = world.scenario.workspace.bounds;
    for (const char* which : {"start", "goal"}) {
      const std::vector<double> q =
          Fitted(which[0] == 's' ? world.scenario.start : world.scenario.goal, body, car);
      if (!Fits(check, body, bounds, Pose(q))) {
        throw InputError(spec.path + ": worlds: " + world.name + ": robot " + robot.name + ": " +
                         which + ": the robot is in collision or out of bounds there");
      }
    }
  }
}

/// The child's side: plan, report one line on `fd`, exit. Never returns.
[[noreturn]] void RunChild(const Scenario& scenario, double watchdog_s, int fd) {
  std::signal(SIGINT, SIG_IGN);  // The parent decides what a Ctrl-C does to a run.
  std::signal(SIGTERM, SIG_DFL);
  alarm(static_cast<unsigned>(std::ceil(watchdog_s)));
  std::string line;
  int status = 0;
  try {
    planning::ConfigureOmpl(scenario.seed, true);
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);  // Keep the progress line readable.
    const planning::PlanResult result = planning::PlanScenario(scenario);
    // acd samplers: the run's time with the decomposition as this run paid for it (a cache
    // look-up: the parent decomposed each map before forking), and the map's one-off
    // decomposition cost beside it. The other samplers do not use it: not in their time.
    // A car's case uses the ACD when Syclop follows it.
    const bool acd = scenario.car ? result.car && result.car->decomposition ==
                                                      planning::control::DecompositionKind::kAcd
                                  : planning::UsesDecomposition(scenario.sampler);
    const double paid_s = result.decomposition_ms / 1e3;
    char buffer[512];
    std::snprintf(buffer, sizeof(buffer), "OK %d %.17g %.17g %llu %llu %.17g %d %d\n",
                  result.solved ? 1 : 0,
                  acd ? result.time_s : std::max(0.0, result.time_s - paid_s),
                  acd ? result.decomposition_compute_ms / 1e3 : 0.0,
                  static_cast<unsigned long long>(result.samples),
                  static_cast<unsigned long long>(result.collision_checks), result.path_length,
                  result.components, result.openings);
    line = buffer;
  } catch (const InputError& error) {
    line = std::string("E ") + error.what() + "\n";
    status = 2;
  } catch (const std::exception& error) {
    line = std::string("X ") + error.what() + "\n";
    status = 1;
  } catch (...) {
    line = "X unknown exception\n";
    status = 1;
  }
  size_t written = 0;
  while (written < line.size()) {
    const ssize_t n = write(fd, line.data() + written, line.size() - written);
    if (n <= 0) break;
    written += static_cast<size_t>(n);
  }
  close(fd);
  _exit(status);  // No destructors or atexit handlers of the parent's objects.
}

std::string Duration(double s) {
  char buffer[32];
  const long t = std::lround(s);
  if (t >= 3600) {
    std::snprintf(buffer, sizeof(buffer), "%ldh%02ldm", t / 3600, t / 60 % 60);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%ldm%02lds", t / 60, t % 60);
  }
  return buffer;
}

struct Child {
  int fd = -1;
  BenchRunId id;
  std::string output;
};

}  // namespace

BenchRunOutcome RunBench(const BenchSpec& spec, const BenchRunOptions& options) {
  const int runs = options.runs > 0 ? options.runs : spec.runs;
  const int jobs = std::max(1, options.jobs);
  CheckQueries(spec);
  const std::vector<BenchRunId> ids = BenchRunsOfShard(spec, runs, options.shard);
  BenchRunOutcome outcome;
  outcome.planned = ids.size();
  const Stopwatch started;
  Stopwatch since_checkpoint, since_progress;
  const bool tty = options.progress && isatty(STDERR_FILENO);
  std::map<pid_t, Child> running;
  size_t next = 0;
  auto stopping = [&] { return options.stop && *options.stop; };

  auto show_progress = [&](bool final) {
    if (!options.progress) return;
    const double elapsed = started.Seconds();
    if (!final && !tty && since_progress.Seconds() < 10.0) return;
    since_progress.Restart();
    const size_t done = outcome.records.size();
    std::ostringstream line;
    line << "bench " << spec.name << ": " << done << "/" << ids.size() << " runs, elapsed "
         << Duration(elapsed);
    if (done > 0 && done < ids.size()) {
      line << ", about " << Duration(elapsed / done * (ids.size() - done)) << " left";
    }
    *options.progress << (tty ? "\r" : "") << line.str() << (tty && !final ? "   " : "\n")
                      << std::flush;
  };

  auto kill_all = [&] {
    for (auto& [pid, child] : running) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
      close(child.fd);
    }
    running.clear();
  };

  while (next < ids.size() || !running.empty()) {
    if (stopping()) {
      kill_all();
      outcome.interrupted = true;
      break;
    }
    while (static_cast<int>(running.size()) < jobs && next < ids.size()) {
      const BenchRunId id = ids[next++];
      const BenchCase& c = spec.cases[id.case_index];
      const Scenario scenario = RunScenario(spec, c, id.seed);
      // Decompose each map once, here in the parent: the children inherit the cache (2D, in
      // process) or read it from disk (3D, as PlanScenario3d() decomposes).
      if (scenario.dimension == 3) {
        envs::FreeSpaceDecomposition3dOptions acd3d;
        acd3d.tau = scenario.tau_diag * scenario.workspace3d.bounds.sizes().norm();
        envs::DecomposeFreeSpace3d(scenario.workspace3d, acd3d);
      } else {
        planning::DecomposeFreeSpaceCached(scenario.workspace,
                                           planning::ScenarioAcdOptions(scenario));
      }
      const double watchdog = c.budget.samples > 0 ? 600.0 : 10.0 * c.budget.time_limit + 60.0;
      int fds[2];
      if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe(): ") + std::strerror(errno));
      std::fflush(nullptr);
      const pid_t pid = fork();
      if (pid < 0) throw std::runtime_error(std::string("fork(): ") + std::strerror(errno));
      if (pid == 0) {
        close(fds[0]);
        RunChild(scenario, watchdog, fds[1]);
      }
      close(fds[1]);
      running[pid] = Child{fds[0], id, ""};
    }
    // Drain the pipes (a child blocks if its pipe is full) and reap what has finished.
    std::vector<pollfd> polls;
    for (const auto& [pid, child] : running) polls.push_back({child.fd, POLLIN, 0});
    if (poll(polls.data(), polls.size(), 200) < 0 && errno != EINTR) {
      throw std::runtime_error(std::string("poll(): ") + std::strerror(errno));
    }
    for (auto& [pid, child] : running) {
      for (const pollfd& p : polls) {
        if (p.fd != child.fd || !(p.revents & (POLLIN | POLLHUP))) continue;
        char buffer[4096];
        const ssize_t n = read(child.fd, buffer, sizeof(buffer));
        if (n > 0) child.output.append(buffer, static_cast<size_t>(n));
      }
    }
    // Reap only the runner's own children (the keys of `running`): waitpid(-1) would also
    // take the exit status of a child the caller started.
    std::vector<std::pair<pid_t, int>> finished;
    for (const auto& entry : running) {
      int status = 0;
      if (waitpid(entry.first, &status, WNOHANG) == entry.first) {
        finished.emplace_back(entry.first, status);
      }
    }
    for (const auto& [pid, status] : finished) {
      auto it = running.find(pid);
      Child child = std::move(it->second);
      running.erase(it);
      char buffer[4096];
      ssize_t n;
      while ((n = read(child.fd, buffer, sizeof(buffer))) > 0) {
        child.output.append(buffer, static_cast<size_t>(n));
      }
      close(child.fd);
      const BenchCase& c = spec.cases[child.id.case_index];
      const BenchWorld& world = spec.worlds[c.world];
      BenchRecord r;
      r.case_index = c.index;
      r.what.world = world.name;
      r.what.family = world.family;
      r.what.passage_width = world.passage_width;
      r.what.workspace_width = world.workspace_width;
      r.what.robot = spec.robots[c.robot].name;
      r.what.sampler = c.SamplerLabel();
      r.what.planner = c.PlannerLabel();
      r.what.budget = c.budget.Label();
      r.what.time_limit = c.budget.samples > 0 ? 0.0 : c.budget.time_limit;
      r.what.sample_budget = c.budget.samples;
      r.run = child.id.run;
      r.seed = child.id.seed;
      if (child.output.rfind("E ", 0) == 0) {
        kill_all();
        std::string message = child.output.substr(2);
        while (!message.empty() && message.back() == '\n') message.pop_back();
        throw InputError(message);
      }
      int solved = 0;
      unsigned long long samples = 0, checks = 0;
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
          std::sscanf(child.output.c_str(), "OK %d %lf %lf %llu %llu %lf %d %d", &solved, &r.time_s,
                      &r.decomposition_s, &samples, &checks, &r.path_length, &r.components,
                      &r.openings) == 8) {
        r.solved = solved != 0;
        r.status = r.solved ? RunStatus::kSolved : RunStatus::kUnsolved;
        r.samples = samples;
        r.collision_checks = checks;
      } else {
        r.status = WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM ? RunStatus::kTimeout
                                                                      : RunStatus::kCrashed;
        if (options.progress) {
          *options.progress << (tty ? "\n" : "") << "bench: run " << r.run << " of " << c.Key(spec)
                            << " (seed " << r.seed << ") " << ToString(r.status)
                            << (child.output.rfind("X ", 0) == 0 ? ": " + child.output.substr(2)
                                                                 : std::string("\n"));
        }
      }
      outcome.records.push_back(r);
      show_progress(false);
    }
    if (options.checkpoint && since_checkpoint.Seconds() >= options.checkpoint_s) {
      since_checkpoint.Restart();
      std::vector<BenchRecord> sorted = outcome.records;
      SortBenchRecords(&sorted);
      options.checkpoint(sorted);
    }
  }
  SortBenchRecords(&outcome.records);
  outcome.wall_s = started.Seconds();
  show_progress(true);
  return outcome;
}

}  // namespace acdplan::bench
