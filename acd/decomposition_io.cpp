#include "acd/decomposition_io.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/svg.h"

namespace acdplan::acd {
namespace {

// ordered_json keeps the keys in DESIGN.md's order, so the file reads like the contract.
using Json = nlohmann::ordered_json;

Json PointToJson(const Point2d& p) { return Json::array({p.x(), p.y()}); }

Json RingToJson(const Ring2d& ring) {
  Json array = Json::array();
  for (const Point2d& p : ring) array.push_back(PointToJson(p));
  return array;
}

// What `map` holds for the input polygon `source` (a component's), or -1 if nothing.
int Mapped(const std::vector<int>& map, int source) {
  return source >= 0 && source < static_cast<int>(map.size()) ? map[static_cast<size_t>(source)]
                                                              : -1;
}

// A JSON object written member by member, each member's value dumped as it comes: the same
// text as ordered_json's compact dump() of the whole object, without holding the whole document
// (for a layer of 200,000 components, building it took most of the time and memory of writing).
class JsonObjectText {
 public:
  JsonObjectText() : text_("{") {}

  void Member(const std::string& key, const Json& value) {
    Key(key);
    text_ += value.dump();
  }
  // An array member of `count` elements, element k being `element(k)`.
  template <typename Element>
  void ArrayMember(const std::string& key, size_t count, Element element) {
    Key(key);
    text_ += '[';
    for (size_t k = 0; k < count; ++k) {
      if (k > 0) text_ += ',';
      text_ += Json(element(k)).dump();
    }
    text_ += ']';
  }
  // The object's text, closed, and a newline; once, after the last member.
  std::string Finish() {
    text_ += "}\n";
    return std::move(text_);
  }

 private:
  void Key(const std::string& key) {
    if (text_.back() != '{') text_ += ',';
    text_ += Json(key).dump();
    text_ += ':';
  }
  std::string text_;
};

/// Path data of a polygon with holes.
std::string PathData(const SvgCanvas& canvas, const Polygon2d& polygon) {
  std::vector<Ring2d> rings{polygon.outer};
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  return canvas.PathData(rings);
}

// A GeoJSON FeatureCollection of `count` features, feature k being `feature(k)`, with the
// foreign member (RFC 7946 6.1) "acdplan" that names `format` and what was decomposed, and how.
template <typename Feature>
std::string GeoJsonLayer(const Decomposition2d& decomposition, const DecompositionLabels& labels,
                         const std::string& format, size_t count, Feature feature) {
  JsonObjectText json;
  json.Member("type", "FeatureCollection");
  json.Member("acdplan", {{"format", format},
                          {"input", labels.input},
                          {"measure", ToString(decomposition.measure)},
                          {"tau", decomposition.tau},
                          {"tau_rel", labels.tau_rel >= 0 ? Json(labels.tau_rel) : Json(nullptr)}});
  json.ArrayMember("features", count, feature);
  return json.Finish();
}

}  // namespace

std::string DecompositionToJson(const Decomposition2d& decomposition,
                                const DecompositionLabels& labels,
                                const std::vector<int>& input_polygons,
                                const std::vector<int>& input_features) {
  JsonObjectText json;
  json.Member("format", "acdplan.decomposition2d/1");
  json.Member("input", labels.input);
  json.Member("measure", ToString(decomposition.measure));
  json.Member("tau", decomposition.tau);
  json.Member("tau_rel", labels.tau_rel >= 0 ? Json(labels.tau_rel) : Json(nullptr));

  const std::vector<Component2d>& components = decomposition.components;
  json.ArrayMember("components", components.size(), [&](size_t k) {
    const Component2d& component = components[k];
    Json c;
    c["boundary"] = RingToJson(component.polygon.outer);
    Json holes = Json::array();
    for (const Ring2d& hole : component.polygon.holes) holes.push_back(RingToJson(hole));
    c["holes"] = std::move(holes);
    c["hull"] = RingToJson(component.hull);
    c["centroid"] = PointToJson(component.centroid);
    c["concavity"] = component.concavity;
    c["source"] = component.source;  // Extension: index of the input polygon.
    if (const int polygon = Mapped(input_polygons, component.source); polygon >= 0) {
      c["input_polygon"] = polygon;
    }
    if (const int feature = Mapped(input_features, component.source); feature >= 0) {
      c["input_feature"] = feature;
    }
    return c;
  });

  const std::vector<Opening2d>& openings = decomposition.openings;
  json.ArrayMember("openings", openings.size(), [&](size_t k) {
    const Opening2d& opening = openings[k];
    Json o;
    o["a"] = PointToJson(opening.a);
    o["b"] = PointToJson(opening.b);
    o["components"] = Json::array({opening.component_a, opening.component_b});
    return o;
  });

  const DecompositionStats2d& stats = decomposition.stats;
  json.Member("stats", {{"vertices", stats.vertices},
                        {"notches", stats.notches},
                        {"components", stats.components},
                        {"max_concavity", stats.max_concavity},
                        {"convexity", stats.convexity},
                        {"time_ms", stats.time_ms}});

  // Extensions (DESIGN.md: extend, never change).
  if (decomposition.min_convexity > 0) {
    json.Member("min_convexity", decomposition.min_convexity);
  }
  const std::vector<std::vector<int>> graph = ComponentGraph(decomposition);
  json.ArrayMember("graph", graph.size(), [&](size_t k) { return graph[k]; });

  // nlohmann writes doubles with the shortest text that reads back to the same value.
  return json.Finish();
}

std::string DecompositionToGeoJson(const Decomposition2d& decomposition,
                                   const DecompositionLabels& labels,
                                   const std::vector<int>& input_polygons,
                                   const std::vector<int>& input_features,
                                   const std::vector<std::string>& feature_properties) {
  // RFC 7946 3.1.6: a linear ring repeats its first position last.
  auto closed = [](const Ring2d& ring) {
    Json positions = RingToJson(ring);
    if (!ring.empty()) positions.push_back(PointToJson(ring.front()));
    return positions;
  };
  // Each feature's attributes parsed once, however many components it gives.
  std::vector<std::optional<Json>> attributes(feature_properties.size());
  auto attributes_of = [&](int feature) {
    if (feature < 0 || feature >= static_cast<int>(attributes.size())) return Json::object();
    std::optional<Json>& parsed = attributes[static_cast<size_t>(feature)];
    if (!parsed) {
      parsed = Json::parse(feature_properties[static_cast<size_t>(feature)]);
      if (!parsed->is_object()) parsed = Json::object();
    }
    return *parsed;
  };
  auto feature = [&](size_t k) {
    const Component2d& component = decomposition.components[k];
    // Counter-clockwise outer rings and clockwise holes: RFC 7946's right-hand rule.
    Json rings = Json::array({closed(component.polygon.outer)});
    for (const Ring2d& hole : component.polygon.holes) rings.push_back(closed(hole));
    const int polygon = Mapped(input_polygons, component.source);
    const int feature = Mapped(input_features, component.source);
    Json properties = attributes_of(feature);
    properties["acd_id"] = k;
    properties["acd_concav"] = component.concavity;
    properties["acd_poly"] = polygon >= 0 ? Json(polygon) : Json(nullptr);
    properties["acd_feat"] = feature >= 0 ? Json(feature) : Json(nullptr);
    return Json{{"type", "Feature"},
                {"geometry", {{"type", "Polygon"}, {"coordinates", std::move(rings)}}},
                {"properties", std::move(properties)}};
  };
  return GeoJsonLayer(decomposition, labels, "acdplan.decomposition2d.geojson/1",
                      decomposition.components.size(), feature);
}

std::string OpeningsToGeoJson(const Decomposition2d& decomposition,
                              const DecompositionLabels& labels) {
  auto feature = [&](size_t k) {
    const Opening2d& opening = decomposition.openings[k];
    Json line = Json::array({PointToJson(opening.a), PointToJson(opening.b)});
    return Json{{"type", "Feature"},
                {"geometry", {{"type", "LineString"}, {"coordinates", std::move(line)}}},
                {"properties",
                 {{"acd_id", k},
                  {"acd_a", opening.component_a},
                  {"acd_b", opening.component_b},
                  {"acd_length", (opening.b - opening.a).norm()}}}};
  };
  return GeoJsonLayer(decomposition, labels, "acdplan.openings2d.geojson/1",
                      decomposition.openings.size(), feature);
}

std::string DecompositionToSvg(const Decomposition2d& decomposition,
                               const DecompositionLabels& labels) {
  Eigen::AlignedBox2d bounds;
  auto add = [&bounds](const Ring2d& ring) {
    for (const Point2d& p : ring) {
      if (p.allFinite()) bounds.extend(p);
    }
  };
  for (const Component2d& component : decomposition.components) add(component.polygon.outer);
  if (bounds.isEmpty()) {
    for (int root : decomposition.roots) {
      if (root >= 0 && root < static_cast<int>(decomposition.tree.size())) {
        add(decomposition.tree[root].piece.outer);
      }
    }
  }
  // Every length is in picture pixels, so the picture looks the same for a polygon measured
  // in millimetres or in kilometres.
  SvgCanvasOptions options;
  options.pixels = 900.0;
  options.margin = 36.0;
  options.font = 23.0;
  SvgCanvas canvas(bounds, options);
  using N = SvgCanvas;
  const double thin = 1.35;
  // The marks (notches, openings) shrink where many share the picture, as on a map of many
  // polygons, so that neighbours stay apart: with the spacing they would have spread evenly over
  // the drawing; full size from 64 px on, down to a quarter of it.
  int marks = 0;
  for (const HierarchyNode2d& node : decomposition.tree) marks += node.children[0] >= 0 ? 1 : 0;
  const Eigen::Vector2d drawing = bounds.sizes() * canvas.scale();
  const double spacing = std::sqrt(drawing.x() * drawing.y() / std::max(marks, 1));
  const double mark = std::clamp(spacing / 64.0, 0.25, 1.0);
  const double opening_width = 5.4 * mark, notch_radius = 5.4 * mark, root_radius = 14.4 * mark;

  // Components: filled, semi-transparent, thin dark boundaries; even-odd fill leaves the
  // unresolved holes open.
  std::ostringstream svg;
  svg << "<g id=\"components\" stroke=\"#222222\" stroke-width=\"" << N::Number(thin)
      << "\" stroke-linejoin=\"round\" fill-opacity=\"0.6\" fill-rule=\"evenodd\">\n";
  for (size_t k = 0; k < decomposition.components.size(); ++k) {
    const Component2d& component = decomposition.components[k];
    svg << "<path class=\"component\" fill=\"" << ComponentFill(static_cast<int>(k)) << "\" d=\""
        << PathData(canvas, component.polygon) << "\"><title>component " << k << ": concavity "
        << FormatSignificant(component.concavity, 4) << "</title></path>\n";
  }
  svg << "</g>\n";

  // Openings: the passages between components.
  svg << "<g id=\"openings\" stroke=\"#f07800\" stroke-width=\"" << N::Number(opening_width)
      << "\" stroke-linecap=\"round\">\n";
  for (const Opening2d& opening : decomposition.openings) {
    svg << "<line x1=\"" << canvas.X(opening.a.x()) << "\" y1=\"" << canvas.Y(opening.a.y())
        << "\" x2=\"" << canvas.X(opening.b.x()) << "\" y2=\"" << canvas.Y(opening.b.y())
        << "\"/>\n";
  }
  svg << "</g>\n";

  // Notches: every split node's witness is a resolved notch (a small dot); a root's witness
  // is the most concave point of its input polygon (a red ring). A leaf's witness means
  // nothing (HierarchyNode2d), so only split nodes are drawn.
  svg << "<g id=\"notches\">\n";
  const int node_count = static_cast<int>(decomposition.tree.size());
  for (const HierarchyNode2d& node : decomposition.tree) {
    if (node.children[0] < 0) continue;
    svg << "<circle class=\"resolved-notch\" cx=\"" << canvas.X(node.witness.x()) << "\" cy=\""
        << canvas.Y(node.witness.y()) << "\" r=\"" << N::Number(notch_radius)
        << "\" fill=\"#111111\"/>\n";
  }
  for (int root : decomposition.roots) {
    if (root < 0 || root >= node_count) continue;
    const HierarchyNode2d& node = decomposition.tree[root];
    if (node.children[0] < 0) continue;
    svg << "<circle class=\"most-concave-notch\" cx=\"" << canvas.X(node.witness.x()) << "\" cy=\""
        << canvas.Y(node.witness.y()) << "\" r=\"" << N::Number(root_radius)
        << "\" fill=\"none\" stroke=\"#d01010\" stroke-width=\"" << N::Number(2.5 * thin * mark)
        << "\"><title>most concave notch: concavity " << FormatSignificant(node.concavity, 4)
        << "</title></circle>\n";
  }
  svg << "</g>\n";
  canvas.Add(svg.str());

  std::vector<std::string> caption;
  caption.push_back(labels.input.empty() ? std::string("(unnamed input)") : labels.input);
  std::string line = "tau " + FormatSignificant(decomposition.tau, 4);
  if (labels.tau_rel >= 0) line += " (tau_rel " + FormatSignificant(labels.tau_rel, 4) + ")";
  if (decomposition.min_convexity > 0) {
    line += ", min convexity " + FormatSignificant(decomposition.min_convexity, 4);
  }
  line += ", measure " + ToString(decomposition.measure) + ", " +
          std::to_string(decomposition.components.size()) + " components, convexity " +
          FormatSignificant(decomposition.stats.convexity, 4) + ", " +
          FormatSignificant(decomposition.stats.time_ms, 4) + " ms";
  caption.push_back(line);
  caption.push_back(
      "red rings: most concave notches of the input; dots: resolved notches (where cuts "
      "start); orange: openings");
  return canvas.Finish(caption, caption[0] + ": " + caption[1]);
}

}  // namespace acdplan::acd
