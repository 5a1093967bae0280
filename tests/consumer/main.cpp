// Uses the installed acdplan::acd library: the area of a 2 x 2 square must be 4.
#include <cmath>
#include <cstdio>

#include "acd/polygon2d.h"

int main() {
  acdplan::acd::Polygon2d square;
  square.outer = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {0.0, 2.0}};
  const double area = acdplan::acd::Area(square);
  if (std::abs(area - 4.0) > 1e-12) {
    std::fprintf(stderr, "acdplan_consumer: Area(square) = %.17g, expected 4\n", area);
    return 1;
  }
  std::printf("acdplan_consumer: Area(square) = %g, ok\n", area);
  return 0;
}
