// repair_areas: what `--repair` makes of polygons, a line each, for comparing it with another
// implementation of make-valid (tools/compare_repair_with_geos.py). Not a test.
//
//   repair_areas [--check] < polygons.wkt
//       Reads one WKT geometry per line from standard input and prints per line
//       "ok AREA PARTS CHECK" (AREA: the summed area of what RepairPolygon() made of its
//       polygons, to 17 digits; PARTS: how many polygons; CHECK: "-", or with --check
//       "checked" when Decompose2d() at tau 0 passes CheckDecomposition() and "check-failed:
//       <first problem>" when not) or "error MESSAGE" for input that is refused.
// Exit status: 0 done (whatever the lines say); 2 bad usage.

#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/polygon2d.h"
#include "acd/repair_polygon.h"
#include "acd/wkt_reader.h"

namespace {

namespace acd = acdplan::acd;

std::string OneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n') c = ' ';
  }
  return text;
}

// The line's answer (see the header).
std::string Answer(const std::string& line, bool check) {
  std::istringstream in(line);
  std::vector<acd::Polygon2d> repaired;
  for (const acd::Polygon2d& polygon : acd::ReadWkt(in, "line")) {
    for (acd::Polygon2d& part : acd::RepairPolygon(polygon, "line").polygons) {
      repaired.push_back(std::move(part));
    }
  }
  double area = 0.0;
  for (const acd::Polygon2d& part : repaired) area += acd::Area(part);
  std::string verdict = "-";
  if (check && !repaired.empty()) {
    acd::Decompose2dOptions options;
    options.tau = 0.0;
    const acd::DecompositionCheck result =
        acd::CheckDecomposition(repaired, acd::Decompose2d(repaired, options));
    verdict = result.ok() ? "checked" : "check-failed: " + OneLine(result.problems.front());
  }
  char number[32];
  std::snprintf(number, sizeof number, "%.17g", area);
  return std::string("ok ") + number + " " + std::to_string(repaired.size()) + " " + verdict;
}

}  // namespace

int main(int argc, char** argv) {
  bool check = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--check") == 0) {
      check = true;
    } else {
      std::fprintf(stderr, "usage: repair_areas [--check] < polygons.wkt\n");
      return 2;
    }
  }
  std::string line;
  while (std::getline(std::cin, line)) {
    std::string answer;
    try {
      answer = Answer(line, check);
    } catch (const std::exception& error) {
      answer = "error " + OneLine(error.what());
    }
    std::printf("%s\n", answer.c_str());
  }
  return 0;
}
