#pragma once
// Writing a decomposition: DESIGN.md's JSON contract and an SVG picture.

#include <string>
#include <vector>

#include "acd/decomposition2d.h"

namespace acdplan::acd {

/// Labels that go into the JSON and the picture's caption.
struct DecompositionLabels {
  std::string input;      ///< Input file name as given.
  double tau_rel = -1.0;  ///< tau relative to ReferenceRadius(); < 0 when tau was absolute.
};

/// The decomposition JSON ("format": "acdplan.decomposition2d/1"), exactly as in DESIGN.md.
/// `input_polygons`: per polygon decomposed, the file's polygon it comes from
/// (ReadPolygonsOptions::sources), written as each component's "input_polygon"; empty: not
/// written. `input_features` likewise, the file's feature (ReadPolygonsOptions::features), as
/// "input_feature".
std::string DecompositionToJson(const Decomposition2d& decomposition,
                                const DecompositionLabels& labels,
                                const std::vector<int>& input_polygons = {},
                                const std::vector<int>& input_features = {});

/// An SVG a person reads at a glance: components in distinct fills, openings drawn, the most
/// concave notches of the input marked, and a caption with tau, measure, components and time.
std::string DecompositionToSvg(const Decomposition2d& decomposition,
                               const DecompositionLabels& labels);

}  // namespace acdplan::acd
