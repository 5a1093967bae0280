// libFuzzer target: whatever a polygon reader (.poly, WKT, GeoJSON, shapefile, WKB, KML) accepts is
// decomposed by Decompose2d(), convex (tau = 0) and approximate (tau = 5% of the polygon's
// reference radius), and CheckDecomposition() must pass; otherwise the problems are printed and the
// target aborts. A polygon PreparePolygons() rejects is made valid by RepairPolygon() first, as
// `--repair` does; a valid one must come back from RepairPolygon() unchanged. The concavity measure
// is chosen by the input's bytes, so mutations explore each. InputError from a reader, from
// PreparePolygons() or from RepairPolygon() is the expected answer to bad input; from
// Decompose2d() it is a finding (its options are valid).
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <numeric>
#include <sstream>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/geojson_reader.h"
#include "acd/kml_reader.h"
#include "acd/poly_reader.h"
#include "acd/prepare_polygon.h"
#include "acd/repair_polygon.h"
#include "acd/shapefile_reader.h"
#include "acd/wkb_reader.h"
#include "acd/wkt_reader.h"
#include "base/input_error.h"
#include "fuzz/fuzz_input.h"

namespace {

using acdplan::acd::Polygon2d;
using Reader = std::function<std::vector<Polygon2d>(std::istream&, const std::string&)>;

[[noreturn]] void Fail(const char* what) {
  std::fprintf(stderr, "%s\n", what);
  std::abort();
}

bool SamePolygons(const std::vector<Polygon2d>& a, const std::vector<Polygon2d>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].outer != b[i].outer || a[i].holes != b[i].holes) return false;
  }
  return true;
}

// The polygons of `text` read by `reader`: prepared where valid, repaired where not; none
// where the reader or the repair rejects the text.
std::vector<Polygon2d> ReadValid(const std::string& text, const Reader& reader) {
  std::vector<Polygon2d> raws;
  try {
    std::istringstream in(text);
    raws = reader(in, "fuzz");
  } catch (const acdplan::InputError&) {
    return {};
  }
  std::vector<Polygon2d> valid;
  for (const Polygon2d& raw : raws) {
    std::vector<Polygon2d> prepared;
    bool was_valid = true;
    try {
      prepared = acdplan::acd::PreparePolygons(raw, "fuzz");
    } catch (const acdplan::InputError&) {
      was_valid = false;
    }
    acdplan::acd::RepairedPolygon repaired;
    try {
      repaired = acdplan::acd::RepairPolygon(raw, "fuzz");
    } catch (const acdplan::InputError& e) {
      if (was_valid) {
        std::fprintf(stderr, "%s\n", e.what());
        Fail("RepairPolygon() rejected a polygon that PreparePolygons() accepts");
      }
      continue;
    }
    if (was_valid && (!repaired.changes.empty() || !SamePolygons(repaired.polygons, prepared))) {
      Fail("RepairPolygon() changed a polygon that PreparePolygons() accepts");
    }
    valid.insert(valid.end(), repaired.polygons.begin(), repaired.polygons.end());
  }
  return valid;
}

void DecomposeAndCheck(const Polygon2d& polygon, acdplan::acd::ConcavityMeasure measure,
                       double tau) {
  acdplan::acd::Decompose2dOptions options;
  options.measure = measure;
  options.tau = tau;
  const acdplan::acd::Decomposition2d decomposition = acdplan::acd::Decompose2d(polygon, options);
  const acdplan::acd::DecompositionCheck check =
      acdplan::acd::CheckDecomposition({polygon}, decomposition);
  if (!check.ok()) {
    std::fprintf(stderr, "CheckDecomposition failed (measure %d, tau = %.17g):\n",
                 static_cast<int>(measure), tau);
    for (const std::string& problem : check.problems) {
      std::fprintf(stderr, "  %s\n", problem.c_str());
    }
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = acdplan::fuzz::InputText(data, size);
  using acdplan::acd::ConcavityMeasure;
  constexpr ConcavityMeasure kMeasures[] = {ConcavityMeasure::kStraightLine,
                                            ConcavityMeasure::kShortestPath,
                                            ConcavityMeasure::kHybrid1, ConcavityMeasure::kHybrid2};
  const ConcavityMeasure measure = kMeasures[std::accumulate(data, data + size, 0u) % 4];
  const Reader readers[] = {
      [](std::istream& in, const std::string& source) {
        std::vector<std::string> warnings;
        return acdplan::acd::ReadPoly(in, source, &warnings);
      },
      [](std::istream& in, const std::string& source) { return acdplan::acd::ReadWkt(in, source); },
      [](std::istream& in, const std::string& source) {
        return acdplan::acd::ReadGeoJson(in, source);
      },
      [](std::istream& in, const std::string& source) {
        return acdplan::acd::ReadShapefile(in, source);
      },
      [](std::istream& in, const std::string& source) {
        const std::string bytes(std::istreambuf_iterator<char>(in), {});
        return acdplan::acd::ReadWkb(reinterpret_cast<const unsigned char*>(bytes.data()),
                                     bytes.size(), source)
            .polygons;
      },
      [](std::istream& in, const std::string& source) {
        acdplan::acd::KmlExtras extras;
        return acdplan::acd::ReadKml(in, source, /*skip_non_areal=*/true, &extras);
      }};
  for (const Reader& reader : readers) {
    for (const Polygon2d& polygon : ReadValid(text, reader)) {
      DecomposeAndCheck(polygon, measure, 0.0);
      DecomposeAndCheck(polygon, measure, 0.05 * acdplan::acd::ReferenceRadius(polygon));
    }
  }
  return 0;
}
