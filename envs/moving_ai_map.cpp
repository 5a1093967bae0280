#include "envs/moving_ai_map.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::envs {
namespace {

[[noreturn]] void Fail(const std::string& path, int line, const std::string& rule) {
  throw InputError(path + ":" + std::to_string(line) + ": " + rule);
}

// Removes a trailing '\r' (maps written on Windows).
void Chomp(std::string& text) {
  if (!text.empty() && text.back() == '\r') text.pop_back();
}

}  // namespace

OccupancyGrid ReadMovingAiMap(const std::string& path) {
  const std::string text = ReadFile(path);
  std::istringstream in(text);
  acd::internal::SkipByteOrderMark(in);
  int width = -1, height = -1;
  bool has_type = false;
  int line_number = 0;
  std::string line;
  // Header: "type octile", "height H", "width W" in any order, then "map".
  while (true) {
    if (!std::getline(in, line)) {
      Fail(path, line_number + 1, "unexpected end of file: expected the 'map' line");
    }
    ++line_number;
    Chomp(line);
    std::istringstream words(line);
    std::string key, extra;
    if (!(words >> key)) continue;  // Blank line.
    if (key == "map") {
      if (words >> extra) Fail(path, line_number, "unexpected text after 'map'");
      break;
    }
    if (key == "type") {
      std::string type;
      if (!(words >> type) || (words >> extra)) Fail(path, line_number, "expected 'type octile'");
      if (type != "octile") {
        Fail(path, line_number, "unsupported map type '" + type + "' (expected octile)");
      }
      has_type = true;
    } else if (key == "height" || key == "width") {
      long long value = 0;
      if (!(words >> value) || (words >> extra) || value <= 0 || value > 100000) {
        Fail(path, line_number, "expected '" + key + " N' with N an integer in [1, 100000]");
      }
      (key == "height" ? height : width) = static_cast<int>(value);
    } else {
      Fail(path, line_number,
           "unknown header line '" + line + "' (expected type, height, width or map)");
    }
  }
  if (!has_type) Fail(path, line_number, "missing 'type octile' before 'map'");
  if (height < 0) Fail(path, line_number, "missing 'height N' before 'map'");
  if (width < 0) Fail(path, line_number, "missing 'width N' before 'map'");

  OccupancyGrid grid;
  grid.width = width;
  grid.height = height;
  grid.resolution = 1.0;
  // Up to 10^10 cells by the header; memory grows with the rows the file holds.
  grid.blocked.reserve(std::min(static_cast<size_t>(width) * height, text.size()));
  for (int row = 0; row < height; ++row) {
    if (!std::getline(in, line)) {
      Fail(path, line_number + 1,
           "unexpected end of file: expected " + std::to_string(height) + " map rows, found " +
               std::to_string(row));
    }
    ++line_number;
    Chomp(line);
    if (static_cast<int>(line.size()) != width) {
      Fail(path, line_number,
           "row " + std::to_string(row) + " has " + std::to_string(line.size()) +
               " cells, expected " + std::to_string(width));
    }
    for (int column = 0; column < width; ++column) {
      const char c = line[column];
      bool blocked;
      switch (c) {
        case '.':
        case 'G':
        case 'S':
          blocked = false;
          break;
        case '@':
        case 'O':
        case 'T':
        case 'W':
          blocked = true;
          break;
        default: {
          const bool printable = c >= 32 && c < 127;
          Fail(path, line_number,
               "unknown terrain '" +
                   (printable ? std::string(1, c)
                              : "\\x" + std::to_string(static_cast<unsigned char>(c))) +
                   "' in column " + std::to_string(column) + " (free: . G S; blocked: @ O T W)");
        }
      }
      grid.blocked.push_back(blocked ? 1 : 0);
    }
  }
  while (std::getline(in, line)) {
    ++line_number;
    Chomp(line);
    if (line.find_first_not_of(" \t") != std::string::npos) {
      Fail(path, line_number, "unexpected text after the " + std::to_string(height) + " map rows");
    }
  }
  return grid;
}

Workspace2d LoadMovingAiMap(const std::string& path) {
  Workspace2d workspace = GridWorkspace(ReadMovingAiMap(path));
  workspace.description = "Moving AI map " + path;
  return workspace;
}

}  // namespace acdplan::envs
