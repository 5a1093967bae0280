#include "envs/moving_ai_scenario.h"

#include <filesystem>
#include <map>
#include <sstream>
#include <system_error>

#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::envs {
namespace {

bool IsScenarioMapFile(const std::filesystem::path& path) {
  std::error_code ignored;
  return std::filesystem::is_regular_file(path, ignored);
}

}  // namespace

std::vector<MovingAiProblem> ReadMovingAiScenario(const std::string& path) {
  std::istringstream in(ReadFile(path));
  acd::internal::SkipByteOrderMark(in);
  static const char* const kFields[] = {"bucket",     "map",     "map width",
                                        "map height", "start x", "start y",
                                        "goal x",     "goal y",  "optimal length"};
  auto fail = [&](int line, const std::string& rule) {
    throw InputError(path + ":" + std::to_string(line) + ": " + rule);
  };
  std::vector<MovingAiProblem> problems;
  std::map<std::string, std::string> found;  // Each map named, resolved once (a file names one).
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    std::istringstream words(text);
    std::vector<std::string> fields;
    for (std::string word; words >> word;) fields.push_back(word);
    if (fields.empty()) continue;
    if (fields[0] == "version") {
      if (!problems.empty() || fields.size() != 2 || (fields[1] != "1" && fields[1] != "1.0")) {
        fail(number, "expected 'version 1' as the first line, found '" + text + "'");
      }
      continue;
    }
    if (fields.size() != 9) {
      fail(number,
           "expected 9 fields (bucket, map, map width, map height, start x, start "
           "y, goal x, goal y, optimal length), found " +
               std::to_string(fields.size()));
    }
    MovingAiProblem p;
    p.line = number;
    p.map = fields[1];
    auto [at, added] = found.emplace(p.map, "");
    if (added) at->second = ResolveMovingAiMap(path, p.map);
    p.map_path = at->second;
    long long values[8] = {};
    for (int k : {0, 2, 3, 4, 5, 6, 7}) {
      const long long limit = k == 0 ? 1000000000 : 100000;  // The map reader's size limit.
      if (!acd::internal::ParseInt(fields[static_cast<size_t>(k)], values[k]) || values[k] < 0 ||
          values[k] > limit) {
        fail(number, std::string(kFields[k]) + ": expected an integer in [0, " +
                         std::to_string(limit) + "], found '" + fields[k] + "'");
      }
    }
    p.bucket = static_cast<int>(values[0]);
    p.map_width = static_cast<int>(values[2]);
    p.map_height = static_cast<int>(values[3]);
    p.start = Eigen::Vector2i(static_cast<int>(values[4]), static_cast<int>(values[5]));
    p.goal = Eigen::Vector2i(static_cast<int>(values[6]), static_cast<int>(values[7]));
    for (const auto& [cell, name] : {std::pair{p.start, "start"}, std::pair{p.goal, "goal"}}) {
      if (cell.x() >= p.map_width || cell.y() >= p.map_height) {
        fail(number, std::string(name) + " cell (" + std::to_string(cell.x()) + ", " +
                         std::to_string(cell.y()) + ") outside the map's " +
                         std::to_string(p.map_width) + " x " + std::to_string(p.map_height) +
                         " cells");
      }
    }
    const acd::internal::NumberStatus status =
        acd::internal::ParseDouble(fields[8], p.optimal_length);
    if (status != acd::internal::NumberStatus::kOk) {
      fail(number, "optimal length: " + acd::internal::NumberProblem(status, fields[8]));
    }
    if (p.optimal_length < 0) fail(number, "optimal length: expected a number >= 0");
    problems.push_back(std::move(p));
  }
  if (problems.empty()) throw InputError(path + ": no problem in file");
  return problems;
}

std::string ResolveMovingAiMap(const std::string& scenario_path, const std::string& map) {
  const std::filesystem::path folder = std::filesystem::path(scenario_path).parent_path();
  const std::filesystem::path named(map);
  if (named.is_absolute() && IsScenarioMapFile(named)) return named.string();
  if (!named.is_absolute() && IsScenarioMapFile(folder / named)) return (folder / named).string();
  return (folder / named.filename()).string();
}

Eigen::Vector2d MovingAiCellCentre(const Eigen::Vector2i& cell, int height) {
  return Eigen::Vector2d(cell.x() + 0.5, height - cell.y() - 0.5);
}

}  // namespace acdplan::envs
