#include "acd/decomposition_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "acd/decomposition2d.h"
#include "tests/occurrences.h"

namespace acdplan::acd {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// An L-shape split at its notch (2, 1) into two rectangles, plus a square with an unresolved
// hole from a second input polygon. Values chosen to need 17 significant digits.
Decomposition2d HandBuilt() {
  Decomposition2d d;
  d.measure = ConcavityMeasure::kStraightLine;
  d.tau = 0.1;

  Component2d bottom;
  bottom.polygon.outer = {{0, 0}, {4, 0}, {4, 1}, {2, 1}, {0, 1}};
  bottom.hull = {{0, 0}, {4, 0}, {4, 1}, {0, 1}};
  bottom.centroid = {2, 0.5};
  bottom.concavity = 0.0;
  Component2d top;
  top.polygon.outer = {{0, 1}, {2, 1}, {2, 3}, {0, 3}};
  top.hull = top.polygon.outer;
  top.centroid = {1, 2};
  top.concavity = 0.1 + 0.2;  // 0.30000000000000004
  Component2d ring;
  ring.polygon.outer = {{10, 0}, {14, 0}, {14, 4}, {10, 4}};
  ring.polygon.holes = {{{11, 1}, {11, 2}, {12, 2}, {12, 1}}};
  ring.hull = ring.polygon.outer;
  ring.centroid = {12.033333333333333, 2.0333333333333332};
  ring.concavity = 0.05;
  ring.source = 1;
  d.components = {bottom, top, ring};
  d.openings = {{Point2d(0, 1), Point2d(2, 1), 0, 1}};

  HierarchyNode2d root;
  root.piece.outer = {{0, 0}, {4, 0}, {4, 1}, {2, 1}, {2, 3}, {0, 3}};
  root.concavity = 1.0;
  root.witness = {2, 1};
  root.cuts = {{Point2d(2, 1), Point2d(0, 1)}};
  root.children[0] = 1;
  root.children[1] = 2;
  HierarchyNode2d leaf0;
  leaf0.piece = bottom.polygon;
  leaf0.parent = 0;
  leaf0.component = 0;
  leaf0.depth = 1;
  HierarchyNode2d leaf1 = leaf0;
  leaf1.piece = top.polygon;
  leaf1.component = 1;
  HierarchyNode2d root2;
  root2.piece = ring.polygon;
  root2.component = 2;
  d.tree = {root, leaf0, leaf1, root2};
  d.roots = {0, 3};

  d.stats.vertices = 14;
  d.stats.notches = 5;
  d.stats.components = 3;
  d.stats.max_concavity = 0.30000000000000004;
  d.stats.convexity = 0.99;
  d.stats.time_ms = 1.25;
  return d;
}

bool IsPoint(const json& p) {
  return p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number();
}

bool IsRing(const json& r) {
  if (!r.is_array()) return false;
  for (const json& p : r) {
    if (!IsPoint(p)) return false;
  }
  return true;
}

TEST(DecompositionToJsonTest, FollowsTheContract) {
  const Decomposition2d d = HandBuilt();
  const json j = json::parse(DecompositionToJson(d, {"shapes/l.poly", 0.025}));

  EXPECT_EQ(j.at("format"), "acdplan.decomposition2d/1");
  EXPECT_EQ(j.at("input"), "shapes/l.poly");
  EXPECT_EQ(j.at("measure"), "sl");
  ASSERT_TRUE(j.at("tau").is_number_float());
  EXPECT_EQ(j.at("tau").get<double>(), 0.1);
  ASSERT_TRUE(j.at("tau_rel").is_number());
  EXPECT_EQ(j.at("tau_rel").get<double>(), 0.025);

  const json& components = j.at("components");
  ASSERT_TRUE(components.is_array());
  ASSERT_EQ(components.size(), 3u);
  for (const json& c : components) {
    EXPECT_TRUE(IsRing(c.at("boundary")));
    ASSERT_TRUE(c.at("holes").is_array());
    for (const json& hole : c.at("holes")) EXPECT_TRUE(IsRing(hole));
    EXPECT_TRUE(IsRing(c.at("hull")));
    EXPECT_TRUE(IsPoint(c.at("centroid")));
    EXPECT_TRUE(c.at("concavity").is_number());
  }
  EXPECT_EQ(components[0].at("boundary").size(), 5u);
  EXPECT_EQ(components[0].at("boundary")[3], json::array({2.0, 1.0}));
  EXPECT_EQ(components[0].at("hull").size(), 4u);
  EXPECT_TRUE(components[0].at("holes").empty());
  ASSERT_EQ(components[2].at("holes").size(), 1u);
  EXPECT_EQ(components[2].at("holes")[0].size(), 4u);
  EXPECT_EQ(components[2].at("holes")[0][1], json::array({11.0, 2.0}));
  // Full precision: the values read back exactly.
  EXPECT_EQ(components[1].at("concavity").get<double>(), 0.1 + 0.2);
  EXPECT_EQ(components[2].at("centroid")[0].get<double>(), 12.033333333333333);
  EXPECT_EQ(components[2].at("centroid")[1].get<double>(), 2.0333333333333332);

  const json& openings = j.at("openings");
  ASSERT_EQ(openings.size(), 1u);
  EXPECT_EQ(openings[0].at("a"), json::array({0.0, 1.0}));
  EXPECT_EQ(openings[0].at("b"), json::array({2.0, 1.0}));
  EXPECT_EQ(openings[0].at("components"), json::array({0, 1}));
  EXPECT_TRUE(openings[0].at("components")[0].is_number_integer());

  const json& stats = j.at("stats");
  EXPECT_EQ(stats.size(), 6u);
  EXPECT_TRUE(stats.at("vertices").is_number_integer());
  EXPECT_EQ(stats.at("vertices"), 14);
  EXPECT_TRUE(stats.at("notches").is_number_integer());
  EXPECT_EQ(stats.at("notches"), 5);
  EXPECT_TRUE(stats.at("components").is_number_integer());
  EXPECT_EQ(stats.at("components"), 3);
  EXPECT_EQ(stats.at("max_concavity").get<double>(), 0.30000000000000004);
  EXPECT_EQ(stats.at("convexity").get<double>(), 0.99);
  EXPECT_EQ(stats.at("time_ms").get<double>(), 1.25);

  // Extensions.
  EXPECT_EQ(j.at("graph"), json::parse("[[1], [0], []]"));
  EXPECT_FALSE(j.contains("min_convexity"));
  EXPECT_EQ(components[2].at("source"), 1);
}

TEST(DecompositionToJsonTest, TauRelIsNullWhenTauWasAbsolute) {
  const json j = json::parse(DecompositionToJson(HandBuilt(), {"l.poly", -1.0}));
  ASSERT_TRUE(j.contains("tau_rel"));
  EXPECT_TRUE(j.at("tau_rel").is_null());
}

// With the file's polygon (and feature) of each polygon decomposed, every component says which
// it came from.
TEST(DecompositionToJsonTest, InputPolygonAndFeatureOnlyWhenKnown) {
  const DecompositionLabels labels{"l.poly", -1.0};
  const json without = json::parse(DecompositionToJson(HandBuilt(), labels));
  EXPECT_FALSE(without.at("components")[0].contains("input_polygon"));
  EXPECT_FALSE(without.at("components")[0].contains("input_feature"));
  const json with = json::parse(DecompositionToJson(HandBuilt(), labels, {7, 3}, {2, 1}));
  for (const json& c : with.at("components")) {
    EXPECT_EQ(c.at("input_polygon"), c.at("source") == 0 ? 7 : 3);
    EXPECT_EQ(c.at("input_feature"), c.at("source") == 0 ? 2 : 1);
  }
}

TEST(DecompositionToJsonTest, MinConvexityOnlyWhenUsed) {
  Decomposition2d d = HandBuilt();
  d.min_convexity = 0.9;
  const json j = json::parse(DecompositionToJson(d, {"l.poly", -1.0}));
  EXPECT_EQ(j.at("min_convexity").get<double>(), 0.9);
}

TEST(DecompositionToJsonTest, KeysAppearInTheContractOrder) {
  const std::string text = DecompositionToJson(HandBuilt(), {"l.poly", -1.0});
  size_t last = 0;
  for (const char* key : {"\"format\"", "\"input\"", "\"measure\"", "\"tau\"", "\"tau_rel\"",
                          "\"components\"", "\"openings\"", "\"stats\""}) {
    const size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GT(at, last == 0 ? 0 : last) << key;
    last = at;
  }
}

// The writers emit member by member; the text must be what one compact dump of the whole
// document gives (the same bytes as before they did), ended by a newline.
TEST(DecompositionToJsonTest, TextIsOneCompactDumpOfTheDocument) {
  const Decomposition2d d = HandBuilt();
  for (const std::string& text :
       {DecompositionToJson(d, {"l.poly", 0.025}, {7, 3}, {2, 1}), DecompositionToJson({}, {}),
        DecompositionToGeoJson(d, {"l.poly", 0.025}), OpeningsToGeoJson(d, {"l.poly", -1.0}),
        OpeningsToGeoJson({}, {})}) {
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n');
    EXPECT_EQ(nlohmann::ordered_json::parse(text).dump() + "\n", text);
  }
}

TEST(DecompositionToJsonTest, EmptyDecompositionIsValid) {
  const json j = json::parse(DecompositionToJson(Decomposition2d{}, {}));
  EXPECT_TRUE(j.at("components").empty());
  EXPECT_TRUE(j.at("openings").empty());
  EXPECT_TRUE(j.at("graph").empty());
  EXPECT_EQ(j.at("measure"), "sp");
}

TEST(DecompositionToGeoJsonTest, OnePolygonFeaturePerComponentAsRfc7946Asks) {
  const Decomposition2d d = HandBuilt();
  const json j = json::parse(DecompositionToGeoJson(d, {"shapes/l.poly", 0.025}));
  EXPECT_EQ(j.at("type"), "FeatureCollection");
  EXPECT_EQ(j.at("acdplan").at("format"), "acdplan.decomposition2d.geojson/1");
  EXPECT_EQ(j.at("acdplan").at("input"), "shapes/l.poly");
  EXPECT_EQ(j.at("acdplan").at("measure"), "sl");
  EXPECT_EQ(j.at("acdplan").at("tau").get<double>(), 0.1);
  EXPECT_EQ(j.at("acdplan").at("tau_rel").get<double>(), 0.025);
  const json& features = j.at("features");
  ASSERT_EQ(features.size(), d.components.size());
  for (size_t k = 0; k < features.size(); ++k) {
    const Polygon2d& polygon = d.components[k].polygon;
    const json& feature = features[k];
    EXPECT_EQ(feature.at("type"), "Feature");
    EXPECT_EQ(feature.at("geometry").at("type"), "Polygon");
    const json& rings = feature.at("geometry").at("coordinates");
    ASSERT_EQ(rings.size(), 1 + polygon.holes.size());
    for (size_t r = 0; r < rings.size(); ++r) {
      const Ring2d& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
      ASSERT_EQ(rings[r].size(), ring.size() + 1) << "closed";
      for (size_t i = 0; i <= ring.size(); ++i) {
        const Point2d& p = ring[i % ring.size()];
        EXPECT_EQ(rings[r][i], json::array({p.x(), p.y()}));
      }
    }
    const json& properties = feature.at("properties");
    EXPECT_EQ(properties.at("acd_id"), k);
    EXPECT_EQ(properties.at("acd_concav").get<double>(), d.components[k].concavity);  // Exact.
    EXPECT_TRUE(properties.at("acd_poly").is_null());
    EXPECT_TRUE(properties.at("acd_feat").is_null());
  }
}

// Each component carries its input feature's attributes, then acdplan's (which win a clash).
TEST(DecompositionToGeoJsonTest, ComponentsCarryTheirInputFeaturesAttributes) {
  const std::vector<std::string> attributes = {R"({"NAME":"Ashe","AREA":0.114})",
                                               R"({"NAME":"Wake","acd_id":"theirs"})"};
  const json j = json::parse(
      DecompositionToGeoJson(HandBuilt(), {"nc.shp", -1.0}, {4, 9}, {1, 0}, attributes));
  EXPECT_TRUE(j.at("acdplan").at("tau_rel").is_null());
  const json& features = j.at("features");
  ASSERT_EQ(features.size(), 3u);
  for (int k : {0, 1}) {  // Source 0: input polygon 4, feature 1.
    const json& properties = features[k].at("properties");
    EXPECT_EQ(properties.at("NAME"), "Wake");
    EXPECT_EQ(properties.at("acd_id"), k);
    EXPECT_EQ(properties.at("acd_poly"), 4);
    EXPECT_EQ(properties.at("acd_feat"), 1);
  }
  const json& third = features[2].at("properties");  // Source 1: input polygon 9, feature 0.
  EXPECT_EQ(third.at("NAME"), "Ashe");
  EXPECT_EQ(third.at("AREA").get<double>(), 0.114);
  EXPECT_EQ(third.at("acd_feat"), 0);
  // The input's attributes come first, in their order.
  const nlohmann::ordered_json ordered = nlohmann::ordered_json::parse(
      DecompositionToGeoJson(HandBuilt(), {}, {4, 9}, {1, 0}, attributes));
  EXPECT_EQ(ordered.at("features")[2].at("properties").begin().key(), "NAME");
}

TEST(OpeningsToGeoJsonTest, OneLineStringFeaturePerOpening) {
  Decomposition2d d = HandBuilt();
  d.openings.push_back({Point2d(0.1, 0.2), Point2d(0.30000000000000004, 0.2), 1, 2});
  const json j = json::parse(OpeningsToGeoJson(d, {"shapes/l.poly", 0.025}));
  EXPECT_EQ(j.at("type"), "FeatureCollection");
  EXPECT_EQ(j.at("acdplan").at("format"), "acdplan.openings2d.geojson/1");
  EXPECT_EQ(j.at("acdplan").at("input"), "shapes/l.poly");
  EXPECT_EQ(j.at("acdplan").at("tau_rel").get<double>(), 0.025);
  const json& features = j.at("features");
  ASSERT_EQ(features.size(), 2u);
  EXPECT_EQ(features[0].at("type"), "Feature");
  EXPECT_EQ(features[0].at("geometry"),
            json::parse(R"({"type": "LineString", "coordinates": [[0.0, 1.0], [2.0, 1.0]]})"));
  EXPECT_EQ(features[0].at("properties"),
            json::parse(R"({"acd_id": 0, "acd_a": 0, "acd_b": 1, "acd_length": 2.0})"));
  // Coordinates exactly as computed.
  EXPECT_EQ(features[1].at("geometry").at("coordinates")[1][0].get<double>(), 0.30000000000000004);
  EXPECT_EQ(features[1].at("properties").at("acd_id"), 1);
  EXPECT_EQ(features[1].at("properties").at("acd_a"), 1);
  EXPECT_EQ(features[1].at("properties").at("acd_b"), 2);
  EXPECT_EQ(features[1].at("properties").at("acd_length").get<double>(), 0.30000000000000004 - 0.1);
  // No openings: an empty layer.
  d.openings.clear();
  EXPECT_EQ(json::parse(OpeningsToGeoJson(d, {})).at("features"), json::array());
}

TEST(DecompositionToSvgTest, DrawsComponentsOpeningsNotchesAndCaption) {
  const std::string svg = DecompositionToSvg(HandBuilt(), {"shapes/l&r.poly", 0.025});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("viewBox=\""), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(acdplan::test::Occurrences(svg, "<path class=\"component\""), 3);
  EXPECT_EQ(acdplan::test::Occurrences(svg, "<path"), 3);
  EXPECT_EQ(acdplan::test::Occurrences(svg, "<line"), 1);  // the opening
  EXPECT_EQ(acdplan::test::Occurrences(svg, "class=\"most-concave-notch\""),
            1);  // root 0 (root 1 is not split)
  EXPECT_EQ(acdplan::test::Occurrences(svg, "class=\"resolved-notch\""), 1);
  // The hole is its own subpath, left open by the even-odd rule.
  EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
  // Distinct fills.
  EXPECT_NE(svg.find("fill=\"#"), std::string::npos);
  // Caption: input (escaped), tau, tau_rel, measure, components, convexity, time.
  EXPECT_NE(svg.find("shapes/l&amp;r.poly"), std::string::npos);
  EXPECT_EQ(svg.find("l&r"), std::string::npos);
  EXPECT_NE(svg.find("tau 0.1 (tau_rel 0.025)"), std::string::npos);
  EXPECT_NE(svg.find("measure sl"), std::string::npos);
  EXPECT_NE(svg.find("3 components"), std::string::npos);
  EXPECT_NE(svg.find("convexity 0.99"), std::string::npos);
  EXPECT_NE(svg.find("1.25 ms"), std::string::npos);
}

// The radius of the first resolved notch drawn in `svg`.
double FirstNotchRadius(const std::string& svg) {
  const size_t notch = svg.find("class=\"resolved-notch\"");
  const size_t r = svg.find(" r=\"", notch);
  if (notch == std::string::npos || r == std::string::npos) return -1.0;
  return std::stod(svg.substr(r + 4));
}

// A map of many polygons has many notches in one picture: they are drawn smaller, so that
// neighbours stay apart; a single polygon keeps full-size marks.
TEST(DecompositionToSvgTest, MarksShrinkWhereManyShareThePicture) {
  const Decomposition2d few = HandBuilt();
  Decomposition2d many = HandBuilt();
  for (int k = 0; k < 2000; ++k) {  // Split nodes (a child set) on a diagonal.
    HierarchyNode2d node;
    node.children[0] = 1;
    node.witness = {0.001 * k, 0.0015 * k};
    many.tree.push_back(node);
  }
  const double full = FirstNotchRadius(DecompositionToSvg(few, {"few", -1.0}));
  const double small = FirstNotchRadius(DecompositionToSvg(many, {"many", -1.0}));
  EXPECT_DOUBLE_EQ(full, 5.4);
  EXPECT_GT(small, 0.0);
  EXPECT_LT(small, 0.5 * full);
}

TEST(DecompositionToSvgTest, FlipsTheYAxis) {
  // The bottom rectangle (y in [0, 1]) must be drawn below the top one (y in [1, 3]): larger
  // SVG y. The drawing spans [0, 7] x [0, 2] (900 / 7 pixels per unit) after a 36-pixel
  // margin, so y = 0 maps to SVG y 36 + 2 x 900 / 7 = 293.143.
  const std::string svg = DecompositionToSvg(HandBuilt(), {"l.poly", -1.0});
  EXPECT_NE(
      svg.find(
          "d=\"M36,293.143 L293.143,293.143 L293.143,228.857 L164.571,228.857 L36,228.857 Z\""),
      std::string::npos)
      << svg;
  EXPECT_EQ(svg.find("tau_rel"), std::string::npos);
}

TEST(DecompositionToSvgTest, EmptyDecompositionStillRenders) {
  const std::string svg = DecompositionToSvg(Decomposition2d{}, {});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

}  // namespace
}  // namespace acdplan::acd
