#pragma once
// Writing a decomposition: DESIGN.md's JSON contract, GeoJSON and an SVG picture.

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

/// The components as GeoJSON (RFC 7946), a polygon layer for GIS tools: a FeatureCollection of
/// one Polygon feature per component, in order (outer ring counter-clockwise, holes clockwise,
/// rings closed), in the input's coordinates (planar; longitude/latitude only if the input
/// was). A component's properties are its input feature's attributes (`feature_properties`, per
/// feature as ReadPolygonsOptions gives them, joined through `input_features`), then acdplan's,
/// which replace input attributes of the same name, named to fit a shapefile's 10 characters
/// (ogr2ogr keeps them): "acd_id" (the component's index, as in the decomposition JSON, whose
/// "openings" name it), "acd_concav" (its concavity), "acd_poly" and "acd_feat" (its input
/// polygon and feature: the JSON's "input_polygon" and "input_feature"; null where not given).
/// The foreign member "acdplan" names the format ("acdplan.decomposition2d.geojson/1"), input,
/// measure, tau and tau_rel. ReadGeoJson() reads it back.
std::string DecompositionToGeoJson(const Decomposition2d& decomposition,
                                   const DecompositionLabels& labels,
                                   const std::vector<int>& input_polygons = {},
                                   const std::vector<int>& input_features = {},
                                   const std::vector<std::string>& feature_properties = {});

/// The openings as GeoJSON (RFC 7946), a line layer beside DecompositionToGeoJson()'s polygons:
/// a FeatureCollection of one LineString feature (from a to b) per opening, in the JSON's order,
/// with properties "acd_id" (the opening's index in the JSON's "openings"), "acd_a" and "acd_b"
/// (the two components it joins, their "acd_id" in the polygon layer) and "acd_length" (its
/// length, the passage's width, in input units). The foreign member "acdplan" names the format
/// ("acdplan.openings2d.geojson/1") and what was decomposed, as in the polygon layer.
std::string OpeningsToGeoJson(const Decomposition2d& decomposition,
                              const DecompositionLabels& labels);

/// An SVG a person reads at a glance: components in distinct fills, openings drawn, the most
/// concave notches of the input marked, and a caption with tau, measure, components and time.
std::string DecompositionToSvg(const Decomposition2d& decomposition,
                               const DecompositionLabels& labels);

}  // namespace acdplan::acd
