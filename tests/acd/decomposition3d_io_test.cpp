#include "acd/decomposition3d_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "acd/decomposition3d.h"
#include "acd/triangle_mesh.h"
#include "tests/occurrences.h"

namespace acdplan::acd {
namespace {

using nlohmann::json;

TriangleMesh Translated(TriangleMesh mesh, const Eigen::Vector3d& offset) {
  mesh.vertices.rowwise() += offset.transpose();
  return mesh;
}

// Two unit cubes sharing the face x = 1 (a solid ACD of the box [0, 2] x [0, 1] x [0, 1])
// and their opening, the unit square at x = 1. Some values need 17 significant digits.
Decomposition3d TwoCubes() {
  Decomposition3d d;
  d.tau = 0.1;
  Component3d a;
  a.mesh = Translated(Cube(1.0), {0.5, 0.5, 0.5});
  a.hull = a.mesh;
  a.centroid = {0.5, 0.5, 0.5};
  a.volume = 1.0;
  a.hull_volume = 1.0;
  a.concavity = 0.0;
  Component3d b = a;
  b.mesh = Translated(Cube(1.0), {1.5, 0.5, 0.5});
  b.hull = b.mesh;
  b.centroid = {1.5, 0.5, 0.5};
  b.concavity = 0.1 + 0.2;  // 0.30000000000000004
  d.components = {a, b};
  Opening3d opening;
  opening.polygon = {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}};
  opening.normal = {1, 0, 0};
  opening.area = 1.0;
  opening.component_a = 0;
  opening.component_b = 1;
  d.openings = {opening};

  HierarchyNode3d root;
  root.concavity = 0.5;
  root.witness = {1, 1, 0.5};
  root.cut.normal = {1, 0, 0};
  root.cut.offset = 1.0;
  root.children = {1, 2};
  HierarchyNode3d leaf_a;
  leaf_a.parent = 0;
  leaf_a.component = 0;
  leaf_a.depth = 1;
  HierarchyNode3d leaf_b = leaf_a;
  leaf_b.component = 1;
  d.tree = {root, leaf_a, leaf_b};
  d.roots = {0};

  d.stats.vertices = 12;
  d.stats.triangles = 20;
  d.stats.components = 2;
  d.stats.volume = 2.0;
  d.stats.hull_volume = 2.0;
  d.stats.max_concavity = 0.30000000000000004;
  d.stats.time_ms = 1.25;
  return d;
}

// A surface ACD: an open "L" of two unit squares (floor z = 0, wall x = 0), one patch each,
// sharing the edge x = 0, z = 0; two triangles each. The wall faces -x, away from the
// preview's viewer: an open surface shows its back side too.
Decomposition3d OpenL() {
  Decomposition3d d;
  d.tau = 0.05;
  d.max_hulls = 4;
  Component3d floor;
  floor.mesh =
      MakeTriangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  floor.hull = floor.mesh;
  floor.centroid = {0.5, 0.5, 0};
  Component3d wall;
  wall.mesh =
      MakeTriangleMesh({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {{0, 2, 1}, {0, 3, 2}});
  wall.hull = wall.mesh;
  wall.centroid = {0, 0.5, 0.5};
  wall.source = 0;
  d.components = {floor, wall};
  Opening3d edge;
  edge.polygon = {{0, 0, 0}, {0, 1, 0}};
  edge.component_a = 0;
  edge.component_b = 1;
  d.openings = {edge};
  d.stats.vertices = 6;
  d.stats.triangles = 4;
  d.stats.components = 2;
  d.stats.surface = true;
  d.stats.time_ms = 0.5;
  return d;
}

bool IsVector3(const json& p) {
  return p.is_array() && p.size() == 3 && p[0].is_number() && p[1].is_number() && p[2].is_number();
}

/// The mesh JSON {"vertices", "triangles"} holds exactly `mesh`.
void ExpectMesh(const json& j, const TriangleMesh& mesh) {
  ASSERT_EQ(j.size(), 2u);
  const json& vertices = j.at("vertices");
  const json& triangles = j.at("triangles");
  ASSERT_EQ(vertices.size(), static_cast<size_t>(mesh.vertices.rows()));
  ASSERT_EQ(triangles.size(), static_cast<size_t>(mesh.triangles.rows()));
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    ASSERT_TRUE(IsVector3(vertices[i]));
    for (int c = 0; c < 3; ++c) EXPECT_EQ(vertices[i][c].get<double>(), mesh.vertices(i, c));
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    ASSERT_TRUE(triangles[f].is_array());
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(triangles[f][c].is_number_integer());
      EXPECT_EQ(triangles[f][c].get<int>(), mesh.triangles(f, c));
    }
  }
}

TEST(Decomposition3dToJsonTest, FollowsTheContract) {
  const Decomposition3d d = TwoCubes();
  const json j = json::parse(Decomposition3dToJson(d, {"shapes/box.obj", 0.025}));

  EXPECT_EQ(j.at("format"), "acdplan.decomposition3d/1");
  EXPECT_EQ(j.at("input"), "shapes/box.obj");
  EXPECT_EQ(j.at("tau").get<double>(), 0.1);
  EXPECT_EQ(j.at("tau_rel").get<double>(), 0.025);
  EXPECT_EQ(j.at("max_hulls"), 0);

  const json& components = j.at("components");
  ASSERT_EQ(components.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    const json& c = components[k];
    ExpectMesh(c.at("mesh"), d.components[k].mesh);
    ExpectMesh(c.at("hull"), d.components[k].hull);
    EXPECT_EQ(c.at("volume").get<double>(), 1.0);
    EXPECT_EQ(c.at("hull_volume").get<double>(), 1.0);
    ASSERT_TRUE(IsVector3(c.at("centroid")));
    EXPECT_EQ(c.at("source"), 0);
  }
  EXPECT_EQ(components[1].at("centroid"), json::array({1.5, 0.5, 0.5}));
  EXPECT_EQ(components[0].at("concavity").get<double>(), 0.0);
  EXPECT_EQ(components[1].at("concavity").get<double>(), 0.1 + 0.2);  // full precision

  const json& openings = j.at("openings");
  ASSERT_EQ(openings.size(), 1u);
  ASSERT_EQ(openings[0].at("polygon").size(), 4u);
  EXPECT_EQ(openings[0].at("polygon")[2], json::array({1.0, 1.0, 1.0}));
  EXPECT_EQ(openings[0].at("normal"), json::array({1.0, 0.0, 0.0}));
  EXPECT_EQ(openings[0].at("area").get<double>(), 1.0);
  EXPECT_EQ(openings[0].at("components"), json::array({0, 1}));
  EXPECT_EQ(openings[0].at("holes"), json::array());

  const json& stats = j.at("stats");
  EXPECT_EQ(stats.size(), 8u);
  EXPECT_EQ(stats.at("vertices"), 12);
  EXPECT_EQ(stats.at("triangles"), 20);
  EXPECT_TRUE(stats.at("components").is_number_integer());
  EXPECT_EQ(stats.at("components"), 2);
  EXPECT_EQ(stats.at("volume").get<double>(), 2.0);
  EXPECT_EQ(stats.at("hull_volume").get<double>(), 2.0);
  EXPECT_EQ(stats.at("max_concavity").get<double>(), 0.30000000000000004);
  EXPECT_EQ(stats.at("surface"), false);
  EXPECT_EQ(stats.at("time_ms").get<double>(), 1.25);

  // Extension, as in 2D.
  EXPECT_EQ(j.at("graph"), json::parse("[[1], [0]]"));
}

TEST(Decomposition3dToJsonTest, SurfaceDecomposition) {
  const json j = json::parse(Decomposition3dToJson(OpenL(), {"l.obj", -1.0}));
  EXPECT_TRUE(j.at("tau_rel").is_null());
  EXPECT_EQ(j.at("max_hulls"), 4);
  EXPECT_EQ(j.at("stats").at("surface"), true);
  EXPECT_EQ(j.at("components")[1].at("volume").get<double>(), 0.0);
  const json& edge = j.at("openings")[0];
  EXPECT_EQ(edge.at("polygon").size(), 2u);
  EXPECT_EQ(edge.at("area").get<double>(), 0.0);
  EXPECT_EQ(edge.at("normal"), json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(edge.at("holes"), json::array());
}

TEST(Decomposition3dToJsonTest, OpeningHolesAreListsOfPoints) {
  Decomposition3d d = TwoCubes();
  d.openings[0].holes = {{{1, 0.6, 0.4}, {1, 0.4, 0.4}, {1, 0.4, 0.6}}};
  const json j = json::parse(Decomposition3dToJson(d, {"shapes/box.obj", 0.025}));
  const json& holes = j.at("openings")[0].at("holes");
  ASSERT_EQ(holes.size(), 1u);
  ASSERT_EQ(holes[0].size(), 3u);
  EXPECT_EQ(holes[0][1], json::array({1.0, 0.4, 0.4}));
}

TEST(Decomposition3dToJsonTest, NonFiniteNumbersAreNull) {
  Decomposition3d d = TwoCubes();
  d.components[0].concavity = std::numeric_limits<double>::quiet_NaN();
  d.components[1].centroid.x() = std::numeric_limits<double>::infinity();
  d.stats.max_concavity = std::numeric_limits<double>::quiet_NaN();
  const json j = json::parse(Decomposition3dToJson(d, {"box.obj", -1.0}));
  EXPECT_TRUE(j.at("components")[0].at("concavity").is_null());
  EXPECT_TRUE(j.at("components")[1].at("centroid")[0].is_null());
  EXPECT_EQ(j.at("components")[1].at("centroid")[1].get<double>(), 0.5);
  EXPECT_TRUE(j.at("stats").at("max_concavity").is_null());
}

TEST(Decomposition3dToJsonTest, KeysAppearInTheContractOrder) {
  const std::string text = Decomposition3dToJson(TwoCubes(), {"box.obj", -1.0});
  size_t last = 0;
  for (const char* key :
       {"\"format\"", "\"input\"", "\"tau\"", "\"tau_rel\"", "\"components\"", "\"mesh\"",
        "\"hull\"", "\"volume\"", "\"hull_volume\"", "\"centroid\"", "\"concavity\"",
        "\"openings\"", "\"polygon\"", "\"normal\"", "\"area\"", "\"stats\""}) {
    const size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GT(at, last) << key;
    last = at;
  }
}

TEST(Decomposition3dToJsonTest, EmptyDecompositionIsValid) {
  const json j = json::parse(Decomposition3dToJson(Decomposition3d{}, {}));
  EXPECT_TRUE(j.at("components").empty());
  EXPECT_TRUE(j.at("openings").empty());
  EXPECT_TRUE(j.at("graph").empty());
  EXPECT_EQ(j.at("stats").at("components"), 0);
}

// ---- OBJ ----------------------------------------------------------------------------------

struct ObjObject {
  std::string name, material;
  int first_vertex = 0;  ///< 1-based index of its first vertex.
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;  ///< As written: 1-based, global.
};

/// The objects of an OBJ text, checking on the way that every line is one we write.
std::vector<ObjObject> ParseObj(const std::string& text, std::string* mtllib) {
  std::vector<ObjObject> objects;
  std::istringstream in(text);
  std::string line;
  int vertex_count = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag.empty() || tag[0] == '#') continue;
    if (tag == "mtllib") {
      words >> *mtllib;
    } else if (tag == "o") {
      objects.emplace_back();
      words >> objects.back().name;
      objects.back().first_vertex = vertex_count + 1;
    } else if (tag == "usemtl") {
      EXPECT_FALSE(objects.empty());
      if (!objects.empty()) words >> objects.back().material;
    } else if (tag == "v") {
      Eigen::Vector3d p;
      words >> p.x() >> p.y() >> p.z();
      EXPECT_FALSE(words.fail()) << line;
      if (!objects.empty()) objects.back().vertices.push_back(p);
      ++vertex_count;
    } else if (tag == "f") {
      Eigen::Vector3i f;
      words >> f.x() >> f.y() >> f.z();
      EXPECT_FALSE(words.fail()) << line;
      if (!objects.empty()) objects.back().faces.push_back(f);
    } else {
      ADD_FAILURE() << "unexpected OBJ line: " << line;
    }
  }
  return objects;
}

/// newmtl name -> its lines' values ("Kd" -> "r g b", "d" -> "0.3").
std::map<std::string, std::map<std::string, std::string>> ParseMtl(const std::string& text) {
  std::map<std::string, std::map<std::string, std::string>> materials;
  std::istringstream in(text);
  std::string line, current;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag.empty() || tag[0] == '#') continue;
    std::string rest;
    std::getline(words >> std::ws, rest);
    if (tag == "newmtl") {
      current = rest;
      EXPECT_EQ(materials.count(current), 0u) << "material defined twice: " << current;
      materials[current];
    } else {
      EXPECT_FALSE(current.empty()) << line;
      materials[current][tag] = rest;
    }
  }
  return materials;
}

TEST(Decomposition3dToObjTest, OneObjectAndMaterialPerComponentAndHull) {
  const Decomposition3d d = TwoCubes();
  const ObjFiles files = Decomposition3dToObj(d, "box.mtl");
  std::string mtllib;
  const std::vector<ObjObject> objects = ParseObj(files.obj, &mtllib);
  EXPECT_EQ(mtllib, "box.mtl");
  ASSERT_EQ(objects.size(), 4u);
  const std::vector<std::string> names = {"component_0", "component_1", "hull_0", "hull_1"};
  const std::vector<const TriangleMesh*> meshes = {&d.components[0].mesh, &d.components[1].mesh,
                                                   &d.components[0].hull, &d.components[1].hull};
  for (size_t i = 0; i < objects.size(); ++i) {
    SCOPED_TRACE(names[i]);
    const ObjObject& object = objects[i];
    EXPECT_EQ(object.name, names[i]);
    EXPECT_EQ(object.material, names[i]);
    const TriangleMesh& mesh = *meshes[i];
    ASSERT_EQ(object.vertices.size(), static_cast<size_t>(mesh.vertices.rows()));
    for (size_t v = 0; v < object.vertices.size(); ++v) {
      EXPECT_EQ(object.vertices[v], mesh.vertices.row(v).transpose());  // read back exactly
    }
    ASSERT_EQ(object.faces.size(), static_cast<size_t>(mesh.triangles.rows()));
    const int last = object.first_vertex + static_cast<int>(object.vertices.size()) - 1;
    for (size_t f = 0; f < object.faces.size(); ++f) {
      for (int c = 0; c < 3; ++c) {
        // 1-based, and inside the object's own vertices.
        EXPECT_GE(object.faces[f][c], object.first_vertex);
        EXPECT_LE(object.faces[f][c], last);
        EXPECT_EQ(object.faces[f][c] - object.first_vertex, mesh.triangles(f, c));
      }
    }
  }

  const auto materials = ParseMtl(files.mtl);
  ASSERT_EQ(materials.size(), 4u);
  for (const std::string& name : names) {
    ASSERT_EQ(materials.count(name), 1u) << name;
    const auto& m = materials.at(name);
    ASSERT_EQ(m.count("Kd"), 1u);
    std::istringstream kd(m.at("Kd"));
    double r = -1, g = -1, b = -1;
    kd >> r >> g >> b;
    for (double c : {r, g, b}) {
      EXPECT_GE(c, 0.0);
      EXPECT_LE(c, 1.0);
    }
    EXPECT_EQ(std::stod(m.at("d")), name.rfind("hull", 0) == 0 ? 0.3 : 1.0);
  }
  // A component and its hull share a colour; the two components differ.
  EXPECT_EQ(materials.at("component_1").at("Kd"), materials.at("hull_1").at("Kd"));
  EXPECT_NE(materials.at("component_0").at("Kd"), materials.at("component_1").at("Kd"));
}

TEST(Decomposition3dToObjTest, EmptyDecomposition) {
  const ObjFiles files = Decomposition3dToObj(Decomposition3d{}, "empty.mtl");
  std::string mtllib;
  EXPECT_TRUE(ParseObj(files.obj, &mtllib).empty());
  EXPECT_TRUE(ParseMtl(files.mtl).empty());
}

// ---- GLB ----------------------------------------------------------------------------------

std::uint32_t U32(const std::vector<std::uint8_t>& bytes, size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(bytes.at(at + i)) << (8 * i);
  return v;
}

float F32(const std::vector<std::uint8_t>& bytes, size_t at) {
  const std::uint32_t bits = U32(bytes, at);
  float v = 0;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

/// A parsed .glb: its JSON and BIN chunks, after the container checks (glTF 2.0, 4.4).
struct Glb {
  json gltf;
  std::vector<std::uint8_t> bin;
};

Glb ParseGlb(const std::vector<std::uint8_t>& bytes) {
  Glb glb;
  EXPECT_GE(bytes.size(), 20u);
  if (bytes.size() < 20) return glb;
  EXPECT_EQ(U32(bytes, 0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(U32(bytes, 4), 2u);
  EXPECT_EQ(U32(bytes, 8), bytes.size());
  EXPECT_EQ(bytes.size() % 4, 0u);
  const std::uint32_t json_length = U32(bytes, 12);
  EXPECT_EQ(U32(bytes, 16), 0x4E4F534Au);  // "JSON"
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_LE(20 + json_length, bytes.size());
  glb.gltf = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
  const size_t bin_at = 20 + json_length;
  if (bin_at < bytes.size()) {
    const std::uint32_t bin_length = U32(bytes, bin_at);
    EXPECT_EQ(U32(bytes, bin_at + 4), 0x004E4942u);  // "BIN\0"
    EXPECT_EQ(bin_length % 4, 0u);
    EXPECT_EQ(bin_at + 8 + bin_length, bytes.size());
    glb.bin.assign(bytes.begin() + bin_at + 8, bytes.begin() + bin_at + 8 + bin_length);
  }
  return glb;
}

/// Checks that `node` of `glb` holds exactly `mesh` (positions as float32) and returns the
/// index of its material.
int ExpectGlbMesh(const Glb& glb, const json& node, const TriangleMesh& mesh) {
  const json& gltf = glb.gltf;
  const json& primitive = gltf.at("meshes").at(node.at("mesh").get<int>()).at("primitives").at(0);
  EXPECT_EQ(primitive.at("mode"), 4);
  const json& positions =
      gltf.at("accessors").at(primitive.at("attributes").at("POSITION").get<int>());
  const json& indices = gltf.at("accessors").at(primitive.at("indices").get<int>());
  EXPECT_EQ(positions.at("componentType"), 5126);
  EXPECT_EQ(positions.at("type"), "VEC3");
  EXPECT_EQ(positions.at("count"), mesh.vertices.rows());
  EXPECT_EQ(indices.at("componentType"), 5125);
  EXPECT_EQ(indices.at("type"), "SCALAR");
  EXPECT_EQ(indices.at("count"), 3 * mesh.triangles.rows());

  const size_t buffer_length = gltf.at("buffers").at(0).at("byteLength").get<size_t>();
  EXPECT_LE(buffer_length, glb.bin.size());
  const json& position_view = gltf.at("bufferViews").at(positions.at("bufferView").get<int>());
  const json& index_view = gltf.at("bufferViews").at(indices.at("bufferView").get<int>());
  for (const json* view : {&position_view, &index_view}) {
    EXPECT_EQ(view->at("buffer"), 0);
    EXPECT_EQ(view->at("byteOffset").get<size_t>() % 4, 0u);
    EXPECT_LE(view->at("byteOffset").get<size_t>() + view->at("byteLength").get<size_t>(),
              buffer_length);
  }
  EXPECT_EQ(position_view.at("target"), 34962);
  EXPECT_EQ(index_view.at("target"), 34963);
  EXPECT_EQ(position_view.at("byteLength"), 12 * mesh.vertices.rows());
  EXPECT_EQ(index_view.at("byteLength"), 12 * mesh.triangles.rows());

  const size_t p0 = position_view.at("byteOffset").get<size_t>();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = F32(glb.bin, p0 + 12 * i + 4 * c);
      EXPECT_EQ(v, static_cast<float>(mesh.vertices(i, c)));
      lo[c] = std::min(lo[c], static_cast<double>(v));
      hi[c] = std::max(hi[c], static_cast<double>(v));
    }
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(positions.at("min")[c].get<double>(), lo[c]);
    EXPECT_EQ(positions.at("max")[c].get<double>(), hi[c]);
  }
  const size_t i0 = index_view.at("byteOffset").get<size_t>();
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(U32(glb.bin, i0 + 12 * f + 4 * c),
                static_cast<std::uint32_t>(mesh.triangles(f, c)));
    }
  }
  return primitive.at("material").get<int>();
}

TEST(Decomposition3dToGlbTest, OneNodePerComponentAndHull) {
  const Decomposition3d d = TwoCubes();
  const Glb glb = ParseGlb(Decomposition3dToGlb(d));
  const json& gltf = glb.gltf;
  EXPECT_EQ(gltf.at("asset").at("version"), "2.0");
  EXPECT_EQ(gltf.at("scene"), 0);
  const json& nodes = gltf.at("nodes");
  ASSERT_EQ(nodes.size(), 4u);
  EXPECT_EQ(gltf.at("scenes").at(0).at("nodes"), json::array({0, 1, 2, 3}));
  EXPECT_EQ(gltf.at("meshes").size(), 4u);
  EXPECT_EQ(gltf.at("accessors").size(), 8u);
  EXPECT_EQ(gltf.at("bufferViews").size(), 8u);
  ASSERT_EQ(gltf.at("buffers").size(), 1u);
  EXPECT_FALSE(gltf.at("buffers").at(0).contains("uri"));  // the GLB's own BIN chunk
  const std::vector<std::string> names = {"component_0", "component_1", "hull_0", "hull_1"};
  const std::vector<const TriangleMesh*> meshes = {&d.components[0].mesh, &d.components[1].mesh,
                                                   &d.components[0].hull, &d.components[1].hull};
  std::set<int> materials_used;
  for (size_t i = 0; i < nodes.size(); ++i) {
    SCOPED_TRACE(names[i]);
    EXPECT_EQ(nodes[i].at("name"), names[i]);
    const int m = ExpectGlbMesh(glb, nodes[i], *meshes[i]);
    materials_used.insert(m);
    const json& material = gltf.at("materials").at(m);
    EXPECT_EQ(material.at("name"), names[i]);
    const json& color = material.at("pbrMetallicRoughness").at("baseColorFactor");
    ASSERT_EQ(color.size(), 4u);
    for (const json& c : color) {
      EXPECT_GE(c.get<double>(), 0.0);
      EXPECT_LE(c.get<double>(), 1.0);
    }
    if (i < 2) {
      EXPECT_EQ(color[3].get<double>(), 1.0);
      EXPECT_FALSE(material.contains("alphaMode"));  // OPAQUE, the default
    } else {
      EXPECT_LT(color[3].get<double>(), 1.0);
      EXPECT_EQ(material.at("alphaMode"), "BLEND");
    }
    EXPECT_FALSE(material.contains("doubleSided"));  // closed solids
  }
  EXPECT_EQ(materials_used.size(), 4u);
}

TEST(Decomposition3dToGlbTest, SurfacePatchesAreDoubleSided) {
  const Decomposition3d d = OpenL();
  const Glb glb = ParseGlb(Decomposition3dToGlb(d));
  ASSERT_EQ(glb.gltf.at("nodes").size(), 4u);
  const int m = ExpectGlbMesh(glb, glb.gltf.at("nodes")[1], d.components[1].mesh);
  EXPECT_EQ(glb.gltf.at("materials").at(m).at("doubleSided"), true);
}

TEST(Decomposition3dToGlbTest, EmptyMeshesAreLeftOut) {
  Decomposition3d d = TwoCubes();
  d.components[1].hull = TriangleMesh{};
  const Glb glb = ParseGlb(Decomposition3dToGlb(d));
  EXPECT_EQ(glb.gltf.at("nodes").size(), 3u);
  EXPECT_EQ(glb.gltf.at("accessors").size(), 6u);

  const std::vector<std::uint8_t> empty = Decomposition3dToGlb(Decomposition3d{});
  const Glb none = ParseGlb(empty);
  EXPECT_TRUE(none.bin.empty());
  EXPECT_FALSE(none.gltf.contains("buffers"));
  ASSERT_EQ(none.gltf.at("scenes").size(), 1u);
  EXPECT_FALSE(none.gltf.at("scenes").at(0).contains("nodes"));  // glTF: no empty arrays
  EXPECT_FALSE(none.gltf.contains("nodes"));
}

// ---- SVG ----------------------------------------------------------------------------------

/// Every element is closed in order, attribute values are quoted and no '&' is left
/// unescaped: a well-formedness check sufficient for what the writer emits.
void ExpectWellFormed(const std::string& svg) {
  std::vector<std::string> open;
  size_t at = 0;
  while ((at = svg.find('<', at)) != std::string::npos) {
    const size_t end = svg.find('>', at);
    ASSERT_NE(end, std::string::npos);
    const std::string tag = svg.substr(at + 1, end - at - 1);
    ASSERT_FALSE(tag.empty());
    ASSERT_EQ(acdplan::test::Occurrences(tag, "\"") % 2, 0) << tag;
    if (tag[0] == '/') {
      ASSERT_FALSE(open.empty()) << tag;
      EXPECT_EQ(open.back(), tag.substr(1));
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find(' ')));
    }
    at = end + 1;
  }
  EXPECT_TRUE(open.empty());
  for (size_t amp = svg.find('&'); amp != std::string::npos; amp = svg.find('&', amp + 1)) {
    const std::string entity = svg.substr(amp, 6);
    EXPECT_TRUE(entity.rfind("&amp;", 0) == 0 || entity.rfind("&lt;", 0) == 0 ||
                entity.rfind("&gt;", 0) == 0 || entity.rfind("&quot;", 0) == 0 ||
                entity.rfind("&apos;", 0) == 0)
        << entity;
  }
}

/// Triangles of `d` that face a viewer at azimuth 35, elevation 25 degrees (+y up).
int FrontFacing(const Decomposition3d& d) {
  const double pi = std::acos(-1.0), az = 35 * pi / 180, el = 25 * pi / 180;
  const Eigen::Vector3d view(std::cos(el) * std::sin(az), std::sin(el),
                             std::cos(el) * std::cos(az));
  int n = 0;
  for (const Component3d& c : d.components) {
    for (Eigen::Index f = 0; f < c.mesh.triangles.rows(); ++f) {
      const Eigen::Vector3d a = c.mesh.vertices.row(c.mesh.triangles(f, 0));
      const Eigen::Vector3d b = c.mesh.vertices.row(c.mesh.triangles(f, 1));
      const Eigen::Vector3d e = c.mesh.vertices.row(c.mesh.triangles(f, 2));
      n += (b - a).cross(e - a).dot(view) > 0;
    }
  }
  return n;
}

/// The fill colours of the polygons, in painting order.
std::vector<std::string> PolygonFills(const std::string& svg) {
  std::vector<std::string> fills;
  const std::regex polygon("<polygon [^>]*fill=\"(#[0-9a-f]{6})\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polygon);
       it != std::sregex_iterator(); ++it) {
    fills.push_back((*it)[1]);
  }
  return fills;
}

TEST(Decomposition3dToSvgTest, OnePolygonPerVisibleTriangleAndACaption) {
  const Decomposition3d d = TwoCubes();
  const std::string svg = Decomposition3dToSvg(d, {"shapes/box&co.obj", 0.025});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  ExpectWellFormed(svg);
  // Back faces dropped: each cube faces the viewer with its +x, +y and +z sides, two
  // triangles each; the first cube's +x side is the opening, inside the box, dropped too.
  EXPECT_EQ(FrontFacing(d), 12);
  EXPECT_EQ(acdplan::test::Occurrences(svg, "<polygon"), 10);
  // Flat shading: the visible sides of a cube get different shades (the first cube shows
  // two, the second three).
  const std::vector<std::string> painted = PolygonFills(svg);
  EXPECT_EQ(std::set<std::string>(painted.begin(), painted.end()).size(), 2u + 3u);
  // Coordinates rounded to 0.1 px.
  const std::regex points("points=\"([^\"]*)\"");
  int checked = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), points); it != std::sregex_iterator();
       ++it, ++checked) {
    EXPECT_TRUE(std::regex_match((*it)[1].str(), std::regex(R"((-?\d+(\.\d)?,-?\d+(\.\d)? ?){3})")))
        << (*it)[1];
  }
  EXPECT_EQ(checked, 10);
  // Caption: input (escaped), tau, tau_rel, ACD kind, components, volume ratio, time.
  EXPECT_NE(svg.find("shapes/box&amp;co.obj"), std::string::npos);
  EXPECT_NE(svg.find("tau 0.1 (tau_rel 0.025)"), std::string::npos);
  EXPECT_NE(svg.find("solid ACD, 2 components"), std::string::npos);
  EXPECT_NE(svg.find("hull volume / volume 1"), std::string::npos);
  EXPECT_NE(svg.find("max concavity 0.3"), std::string::npos);
  EXPECT_NE(svg.find("1.25 ms"), std::string::npos);
}

TEST(Decomposition3dToSvgTest, OnlyFacesInsideAnOpeningAreInterior) {
  Decomposition3d d = TwoCubes();
  d.openings.clear();
  EXPECT_EQ(acdplan::test::Occurrences(Decomposition3dToSvg(d, {"box.obj", -1.0}), "<polygon"), 12);
  // An opening covering only the half y <= 0.5 of the shared side: of the first cube's two
  // triangles there (acd::Cube), the one with its centroid at y = 1/3 is interior, the one
  // at y = 2/3 is not.
  d = TwoCubes();
  d.openings[0].polygon = {{1, 0, 0}, {1, 0.5, 0}, {1, 0.5, 1}, {1, 0, 1}};
  EXPECT_EQ(acdplan::test::Occurrences(Decomposition3dToSvg(d, {"box.obj", -1.0}), "<polygon"), 11);
  // A plane off by more than the tolerance: nothing is interior.
  d = TwoCubes();
  for (Eigen::Vector3d& p : d.openings[0].polygon) p.x() += 1e-3;
  EXPECT_EQ(acdplan::test::Occurrences(Decomposition3dToSvg(d, {"box.obj", -1.0}), "<polygon"), 12);
}

TEST(Decomposition3dToSvgTest, SurfacePatchesShowBothSides) {
  const Decomposition3d d = OpenL();
  const std::string svg = Decomposition3dToSvg(d, {"l.obj", -1.0});
  ExpectWellFormed(svg);
  EXPECT_EQ(FrontFacing(d), 2);
  EXPECT_EQ(acdplan::test::Occurrences(svg, "<polygon"), 4);
  EXPECT_NE(svg.find("surface ACD, 2 components"), std::string::npos);
  EXPECT_NE(svg.find("max hulls 4"), std::string::npos);
  EXPECT_EQ(svg.find("tau_rel"), std::string::npos);
}

TEST(Decomposition3dToSvgTest, PaintsFarTrianglesFirst) {
  // Two equal triangles facing +z, one behind the other: the far one (z = -5, component 0)
  // must be painted before the near one (z = 0, component 1), whatever the component order.
  Decomposition3d d;
  for (double z : {-5.0, 0.0}) {
    Component3d c;
    c.mesh = MakeTriangleMesh({{0, 0, z}, {1, 0, z}, {1, 1, z}}, {{0, 1, 2}});
    d.components.push_back(c);
  }
  const std::vector<std::string> fills = PolygonFills(Decomposition3dToSvg(d, {"two.obj", -1.0}));
  ASSERT_EQ(fills.size(), 2u);
  EXPECT_NE(fills[0], fills[1]);
  std::swap(d.components[0], d.components[1]);  // now the near one is component 0
  const std::vector<std::string> swapped = PolygonFills(Decomposition3dToSvg(d, {"two.obj", -1.0}));
  ASSERT_EQ(swapped.size(), 2u);
  // Same shading (same normal), colours by component index: painting order follows depth,
  // so the component painted last is the near one in both pictures.
  EXPECT_EQ(swapped[0], fills[1]);
  EXPECT_EQ(swapped[1], fills[0]);
}

TEST(Decomposition3dToSvgTest, EmptyDecompositionStillRenders) {
  const std::string svg = Decomposition3dToSvg(Decomposition3d{}, {});
  ExpectWellFormed(svg);
  EXPECT_EQ(acdplan::test::Occurrences(svg, "<polygon"), 0);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

}  // namespace
}  // namespace acdplan::acd
