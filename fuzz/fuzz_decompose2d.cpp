// libFuzzer target: whatever a polygon reader (.poly, WKT, GeoJSON) accepts and
// PreparePolygons() validates is decomposed by Decompose2d(), convex (tau = 0) and
// approximate (tau = 5% of the polygon's reference radius), and CheckDecomposition() must pass;
// otherwise the problems are printed and the target aborts. InputError from a reader or from
// PreparePolygons() is the expected answer to bad input; from Decompose2d() it is a finding
// (its options are valid).
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/geojson_reader.h"
#include "acd/poly_reader.h"
#include "acd/prepare_polygon.h"
#include "acd/wkt_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

namespace {

using acdplan::acd::Polygon2d;
using Reader = std::function<std::vector<Polygon2d>(std::istream&, const std::string&)>;

// The prepared polygons of `text` read by `reader`, or none if the reader or the preparation
// rejects it.
std::vector<Polygon2d> ReadPrepared(const std::string& text, const Reader& reader) {
  std::vector<Polygon2d> prepared;
  try {
    std::istringstream in(text);
    for (const Polygon2d& raw : reader(in, "fuzz")) {
      for (Polygon2d& piece : acdplan::acd::PreparePolygons(raw, "fuzz")) {
        prepared.push_back(std::move(piece));
      }
    }
  } catch (const acdplan::InputError&) {
    return {};
  }
  return prepared;
}

void DecomposeAndCheck(const Polygon2d& polygon, double tau) {
  acdplan::acd::Decompose2dOptions options;
  options.tau = tau;
  const acdplan::acd::Decomposition2d decomposition = acdplan::acd::Decompose2d(polygon, options);
  const acdplan::acd::DecompositionCheck check =
      acdplan::acd::CheckDecomposition({polygon}, decomposition);
  if (!check.ok()) {
    std::fprintf(stderr, "CheckDecomposition failed (tau = %.17g):\n", tau);
    for (const std::string& problem : check.problems) {
      std::fprintf(stderr, "  %s\n", problem.c_str());
    }
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  const Reader readers[] = {[](std::istream& in, const std::string& source) {
                              std::vector<std::string> warnings;
                              return acdplan::acd::ReadPoly(in, source, &warnings);
                            },
                            &acdplan::acd::ReadWkt, &acdplan::acd::ReadGeoJson};
  for (const Reader& reader : readers) {
    for (const Polygon2d& polygon : ReadPrepared(text, reader)) {
      DecomposeAndCheck(polygon, 0.0);
      DecomposeAndCheck(polygon, 0.05 * acdplan::acd::ReferenceRadius(polygon));
    }
  }
  return 0;
}
