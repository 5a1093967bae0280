#include "acd/decomposition3d_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/svg.h"

namespace acdplan::acd {
namespace {

// ordered_json keeps the keys in the README's order, so the file reads like the contract.
// nlohmann writes a non-finite double as null (JSON has no NaN), as the 2D writer relies on.
using Json = nlohmann::ordered_json;

Json VectorToJson(const Eigen::Vector3d& p) { return Json::array({p.x(), p.y(), p.z()}); }

Json MeshToJson(const TriangleMesh& mesh) {
  Json vertices = Json::array();
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    vertices.push_back(
        Json::array({mesh.vertices(i, 0), mesh.vertices(i, 1), mesh.vertices(i, 2)}));
  }
  Json triangles = Json::array();
  for (Eigen::Index i = 0; i < mesh.triangles.rows(); ++i) {
    triangles.push_back(
        Json::array({mesh.triangles(i, 0), mesh.triangles(i, 1), mesh.triangles(i, 2)}));
  }
  Json json;
  json["vertices"] = std::move(vertices);
  json["triangles"] = std::move(triangles);
  return json;
}

/// The k-th component's colour as RGB in [0, 1] (sRGB), from the same table as the 2D
/// pictures (base/svg.h ComponentFill), so a component has one colour in every output.
Eigen::Vector3d ComponentRgb(int k) {
  const std::string hex = ComponentFill(k);  // "#rrggbb"
  Eigen::Vector3d rgb;
  for (int c = 0; c < 3; ++c) {
    rgb[c] = std::strtol(hex.substr(1 + 2 * c, 2).c_str(), nullptr, 16) / 255.0;
  }
  return rgb;
}

/// sRGB -> linear, as glTF's baseColorFactor is linear (glTF 2.0 spec, 3.9.2).
double SrgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// Opacity of the hulls in the OBJ and glTF outputs: enough to see the component inside.
constexpr double kHullOpacity = 0.3;

/// A mesh that glTF can hold (an accessor needs count >= 1).
bool HasTriangles(const TriangleMesh& mesh) {
  return mesh.triangles.rows() > 0 && mesh.vertices.rows() > 0;
}

// ---- Binary glTF --------------------------------------------------------------------------

/// Appends `value` to `bytes` little-endian, whatever the host's byte order (glTF 2.0, 4.4.1).
void PutU32(std::vector<std::uint8_t>* bytes, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes->push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

void PutF32(std::vector<std::uint8_t>* bytes, float value) {
  std::uint32_t bits = 0;
  static_assert(sizeof bits == sizeof value, "IEEE-754 binary32 expected");
  std::memcpy(&bits, &value, sizeof bits);
  PutU32(bytes, bits);
}

// glTF 2.0 constants (spec 5.1.2, 5.11.3).
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;
constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

/// Builds the glTF document and its binary buffer mesh by mesh.
class GlbBuilder {
 public:
  /// Adds `mesh` as a node named `name` with material `material`; meshes without triangles are
  /// skipped (a glTF accessor needs count >= 1).
  void AddMesh(const std::string& name, const TriangleMesh& mesh, int material) {
    if (!HasTriangles(mesh)) return;
    const Eigen::Index n = mesh.vertices.rows();
    // Positions: float32 as glTF requires; min/max are those of the stored floats, so a
    // validator's comparison with the data is exact.
    const std::size_t positions_offset = bin_.size();
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (Eigen::Index i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) {
        const float v = static_cast<float>(mesh.vertices(i, c));
        PutF32(&bin_, v);
        lo[c] = std::min(lo[c], static_cast<double>(v));
        hi[c] = std::max(hi[c], static_cast<double>(v));
      }
    }
    const int positions = AddView(positions_offset, bin_.size() - positions_offset, kArrayBuffer);
    Json position_accessor;
    position_accessor["bufferView"] = positions;
    position_accessor["componentType"] = kFloat;
    position_accessor["count"] = n;
    position_accessor["type"] = "VEC3";
    position_accessor["min"] = VectorToJson(lo);
    position_accessor["max"] = VectorToJson(hi);
    accessors_.push_back(std::move(position_accessor));
    const int position_index = static_cast<int>(accessors_.size()) - 1;

    const std::size_t indices_offset = bin_.size();
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      for (int c = 0; c < 3; ++c) PutU32(&bin_, static_cast<std::uint32_t>(mesh.triangles(f, c)));
    }
    const int indices = AddView(indices_offset, bin_.size() - indices_offset, kElementArrayBuffer);
    Json index_accessor;
    index_accessor["bufferView"] = indices;
    index_accessor["componentType"] = kUnsignedInt;
    index_accessor["count"] = 3 * mesh.triangles.rows();
    index_accessor["type"] = "SCALAR";
    accessors_.push_back(std::move(index_accessor));
    const int index_index = static_cast<int>(accessors_.size()) - 1;

    Json primitive;
    primitive["attributes"] = {{"POSITION", position_index}};
    primitive["indices"] = index_index;
    primitive["material"] = material;
    primitive["mode"] = kTriangles;
    Json gltf_mesh;
    gltf_mesh["name"] = name;
    gltf_mesh["primitives"] = Json::array({std::move(primitive)});
    meshes_.push_back(std::move(gltf_mesh));
    Json node;
    node["name"] = name;
    node["mesh"] = static_cast<int>(meshes_.size()) - 1;
    nodes_.push_back(std::move(node));
  }

  /// Adds a PBR material of sRGB colour `rgb` and opacity `alpha`; returns its index.
  int AddMaterial(const std::string& name, const Eigen::Vector3d& rgb, double alpha,
                  bool double_sided) {
    Json pbr;
    pbr["baseColorFactor"] =
        Json::array({SrgbToLinear(rgb[0]), SrgbToLinear(rgb[1]), SrgbToLinear(rgb[2]), alpha});
    pbr["metallicFactor"] = 0.0;
    pbr["roughnessFactor"] = 0.8;
    Json material;
    material["name"] = name;
    material["pbrMetallicRoughness"] = std::move(pbr);
    if (alpha < 1.0) material["alphaMode"] = "BLEND";
    if (double_sided) material["doubleSided"] = true;
    materials_.push_back(std::move(material));
    return static_cast<int>(materials_.size()) - 1;
  }

  /// The .glb file: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros).
  std::vector<std::uint8_t> Finish() const {
    Json gltf;
    gltf["asset"] = {{"version", "2.0"}, {"generator", "acdplan"}};
    gltf["scene"] = 0;
    // glTF arrays, when present, are not empty (spec 5.x, minItems 1): an empty decomposition
    // is one empty scene.
    Json scene = Json::object();
    if (!nodes_.empty()) {
      Json scene_nodes = Json::array();
      for (std::size_t i = 0; i < nodes_.size(); ++i) scene_nodes.push_back(i);
      scene["nodes"] = std::move(scene_nodes);
    }
    gltf["scenes"] = Json::array({std::move(scene)});
    if (!nodes_.empty()) {
      gltf["nodes"] = nodes_;
      gltf["meshes"] = meshes_;
      gltf["materials"] = materials_;
      gltf["accessors"] = accessors_;
      gltf["bufferViews"] = views_;
      gltf["buffers"] = Json::array({{{"byteLength", bin_.size()}}});
    }
    std::string text = gltf.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::vector<std::uint8_t> bin = bin_;  // Every view is a multiple of 4 bytes already.
    while (bin.size() % 4 != 0) bin.push_back(0);

    const bool has_bin = !bin.empty();
    const std::size_t total = 12 + 8 + text.size() + (has_bin ? 8 + bin.size() : 0);
    std::vector<std::uint8_t> glb;
    glb.reserve(total);
    PutU32(&glb, kGlbMagic);
    PutU32(&glb, 2);
    PutU32(&glb, static_cast<std::uint32_t>(total));
    PutU32(&glb, static_cast<std::uint32_t>(text.size()));
    PutU32(&glb, kChunkJson);
    glb.insert(glb.end(), text.begin(), text.end());
    if (has_bin) {
      PutU32(&glb, static_cast<std::uint32_t>(bin.size()));
      PutU32(&glb, kChunkBin);
      glb.insert(glb.end(), bin.begin(), bin.end());
    }
    return glb;
  }

 private:
  int AddView(std::size_t offset, std::size_t length, int target) {
    Json view;
    view["buffer"] = 0;
    view["byteOffset"] = offset;
    view["byteLength"] = length;
    view["target"] = target;
    views_.push_back(std::move(view));
    return static_cast<int>(views_.size()) - 1;
  }

  std::vector<std::uint8_t> bin_;
  Json nodes_ = Json::array(), meshes_ = Json::array(), materials_ = Json::array();
  Json accessors_ = Json::array(), views_ = Json::array();
};

// ---- SVG preview --------------------------------------------------------------------------

/// The oblique view of the preview: the viewer's direction from the object (azimuth 35
/// degrees about +y from +z, elevation 25 degrees), with +y up as in OBJ and glTF files.
struct View {
  Eigen::Vector3d toward_viewer, right, up, light;
  View() {
    const double azimuth = 35.0 * M_PI / 180.0, elevation = 25.0 * M_PI / 180.0;
    toward_viewer = Eigen::Vector3d(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                    std::cos(elevation) * std::cos(azimuth));
    right = Eigen::Vector3d::UnitY().cross(toward_viewer).normalized();
    up = toward_viewer.cross(right);
    // A key light from above left of the viewer, so the three visible sides of a box get
    // three different shades.
    light = (toward_viewer + 0.6 * up - 0.45 * right).normalized();
  }
};

/// A triangle of the preview, projected to picture pixels.
struct Facet {
  double depth = 0.0;  ///< Larger is nearer to the viewer.
  int component = 0;
  Eigen::Index triangle = 0;
  Eigen::Vector2d corners[3];
  double shade = 1.0;  ///< Lambert factor in [0, 1].
};

/// `value` rounded to 0.1 px: the picture cannot show more, and the file stays small.
double Tenth(double value) { return std::round(value * 10.0) / 10.0; }

std::string Hex(const Eigen::Vector3d& rgb) {
  char buffer[8];
  auto channel = [](double c) {
    return static_cast<int>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
  };
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", channel(rgb[0]), channel(rgb[1]),
                channel(rgb[2]));
  return buffer;
}

/// The openings of a solid decomposition as a test "does this triangle of component k lie in
/// one of its openings?". Such a triangle is part of a cut face inside the union of the
/// components, never seen from outside: the preview drops it, so that a large cut triangle
/// cannot poke through the surface in front of it (the painter's algorithm orders triangles by
/// their centroids only).
class InteriorFaces {
 public:
  InteriorFaces(const Decomposition3d& decomposition, double length)
      : by_component_(decomposition.components.size()), tolerance_(1e-7 * length) {
    const int n = static_cast<int>(decomposition.components.size());
    for (const Opening3d& opening : decomposition.openings) {
      const double norm = opening.normal.norm();
      if (opening.polygon.size() < 3 || !(norm > 0.0)) continue;  // Surface ACD: polylines.
      Flat flat;
      flat.normal = opening.normal / norm;
      flat.offset = flat.normal.dot(opening.polygon[0]);
      // An orthonormal basis of the plane, for the 2D point-in-polygon test.
      flat.u = flat.normal.unitOrthogonal();
      flat.v = flat.normal.cross(flat.u);
      auto in_plane = [&flat](const std::vector<Eigen::Vector3d>& ring) {
        std::vector<Eigen::Vector2d> points;
        for (const Eigen::Vector3d& p : ring) points.emplace_back(p.dot(flat.u), p.dot(flat.v));
        return points;
      };
      flat.rings.push_back(in_plane(opening.polygon));
      for (const std::vector<Eigen::Vector3d>& hole : opening.holes) {
        flat.rings.push_back(in_plane(hole));
      }
      const int index = static_cast<int>(flats_.size());
      flats_.push_back(std::move(flat));
      for (int k : {opening.component_a, opening.component_b}) {
        if (k >= 0 && k < n) by_component_[k].push_back(index);
      }
    }
  }

  /// True when the triangle `p` of component `k` lies in the plane of one of k's openings,
  /// with its centroid inside that opening.
  bool Contains(int k, const Eigen::Vector3d p[3]) const {
    for (int index : by_component_[k]) {
      const Flat& flat = flats_[index];
      bool on_plane = true;
      for (int c = 0; c < 3; ++c) {
        on_plane = on_plane && std::abs(flat.normal.dot(p[c]) - flat.offset) <= tolerance_;
      }
      if (!on_plane) continue;
      const Eigen::Vector3d centroid = (p[0] + p[1] + p[2]) / 3.0;
      if (Inside(flat.rings, Eigen::Vector2d(centroid.dot(flat.u), centroid.dot(flat.v)))) {
        return true;
      }
    }
    return false;
  }

 private:
  struct Flat {
    Eigen::Vector3d normal, u, v;
    double offset = 0.0;
    std::vector<std::vector<Eigen::Vector2d>> rings;  // The outline, then the holes.
  };

  /// Crossing-number test over all rings (even-odd: inside the outline, in no hole); a
  /// centroid is never on a ring for a non-degenerate triangle inside the region, so the
  /// boundary convention does not matter here.
  static bool Inside(const std::vector<std::vector<Eigen::Vector2d>>& rings,
                     const Eigen::Vector2d& q) {
    bool inside = false;
    for (const std::vector<Eigen::Vector2d>& ring : rings) {
      for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Eigen::Vector2d& a = ring[i];
        const Eigen::Vector2d& b = ring[j];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
          inside = !inside;
        }
      }
    }
    return inside;
  }

  std::vector<std::vector<int>> by_component_;
  std::vector<Flat> flats_;
  double tolerance_;
};

/// The preview's caption line naming the view.
std::string ViewCaption(bool z_up) {
  return std::string("orthographic view from azimuth 35, elevation 25 degrees (") +
         (z_up ? "+z" : "+y") + " up)";
}

/// The SVG of `scene` in the oblique view, painter's algorithm: every triangle flat-shaded in
/// its mesh's colour and opacity; a one-sided (closed) mesh's back faces are dropped, and so is
/// any triangle `hidden(k, corners)` names. With `z_up` the scene is turned so that its +z
/// points up. `group`: the id of the SVG group of triangles.
template <typename Hidden>
std::string RenderSvg(const std::vector<SceneMesh3d>& scene, const Hidden& hidden, bool z_up,
                      const std::string& group, const std::vector<std::string>& caption,
                      const std::string& title) {
  const View view;
  // (x, y, z) -> (x, z, -y): a turn about x that brings +z to the view's +y (up).
  auto turned = [z_up](const Eigen::Vector3d& p) {
    return z_up ? Eigen::Vector3d(p.x(), p.z(), -p.y()) : p;
  };
  std::vector<Facet> facets;
  Eigen::AlignedBox2d bounds;
  const int n = static_cast<int>(scene.size());
  for (int k = 0; k < n; ++k) {
    const TriangleMesh& mesh = scene[k].mesh;
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      Eigen::Vector3d p[3];
      bool valid = true;
      for (int c = 0; c < 3 && valid; ++c) {
        const int v = mesh.triangles(f, c);
        valid = v >= 0 && v < mesh.vertices.rows();
        if (valid) p[c] = turned(mesh.vertices.row(v).transpose());
        valid = valid && p[c].allFinite();
      }
      if (!valid) continue;
      const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
      const double length = normal.norm();
      if (!(length > 0.0)) continue;
      const double facing = normal.dot(view.toward_viewer);
      if (!scene[k].two_sided && !(facing > 0.0)) continue;  // A closed mesh's back faces.
      if (hidden(k, p)) continue;
      Facet facet;
      facet.component = k;
      facet.triangle = f;
      facet.depth = (p[0] + p[1] + p[2]).dot(view.toward_viewer) / 3.0;
      const Eigen::Vector3d seen = (facing >= 0.0 ? 1.0 : -1.0) / length * normal;
      facet.shade = std::max(0.0, seen.dot(view.light));
      for (int c = 0; c < 3; ++c) {
        facet.corners[c] = Eigen::Vector2d(p[c].dot(view.right), p[c].dot(view.up));
        bounds.extend(facet.corners[c]);
      }
      facets.push_back(facet);
    }
  }
  // Far triangles first. Ties are broken by mesh and triangle, so the picture is the same on
  // every standard library.
  std::sort(facets.begin(), facets.end(), [](const Facet& a, const Facet& b) {
    if (a.depth != b.depth) return a.depth < b.depth;
    if (a.component != b.component) return a.component < b.component;
    return a.triangle < b.triangle;
  });

  // Pixels are computed here, rounded to 0.1 px, and the canvas maps them 1:1, so every
  // length is in picture pixels whatever the mesh's units.
  const double pixels = 900.0;
  const double size = bounds.isEmpty() ? 0.0 : bounds.sizes().maxCoeff();
  const double scale = size > 0.0 ? pixels / size : 1.0;
  auto to_pixels = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d(Tenth((p.x() - bounds.min().x()) * scale),
                           Tenth((p.y() - bounds.min().y()) * scale));
  };
  Eigen::AlignedBox2d picture(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero());
  if (!bounds.isEmpty()) picture.extend(to_pixels(bounds.max()));
  SvgCanvasOptions options;
  options.pixels = std::max(1.0, picture.sizes().maxCoeff());
  options.margin = 36.0;
  options.font = 23.0;
  SvgCanvas canvas(picture, options);
  std::ostringstream svg;
  // An opaque triangle gets a hairline stroke of its own colour, which closes the
  // anti-aliasing seams between neighbouring triangles.
  svg << "<g id=\"" << group << "\" stroke-width=\"0.5\" stroke-linejoin=\"round\">\n";
  for (const Facet& facet : facets) {
    const SceneMesh3d& item = scene[facet.component];
    const std::string fill = Hex(item.rgb * (0.35 + 0.65 * facet.shade));
    svg << "<polygon points=\"";
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector2d q = to_pixels(facet.corners[c]);
      svg << (c ? " " : "") << canvas.X(q.x()) << "," << canvas.Y(q.y());
    }
    svg << "\" fill=\"" << fill << "\"";
    if (item.opacity < 1.0) {
      svg << " fill-opacity=\"" << FormatSignificant(item.opacity, 3) << "\" stroke=\"none\"";
    } else {
      svg << " stroke=\"" << fill << "\"";
    }
    svg << "/>\n";
  }
  svg << "</g>\n";
  canvas.Add(svg.str());
  return canvas.Finish(caption, title);
}

}  // namespace

std::string Decomposition3dToJson(const Decomposition3d& decomposition,
                                  const DecompositionLabels& labels) {
  Json json;
  json["format"] = "acdplan.decomposition3d/1";
  json["input"] = labels.input;
  json["tau"] = decomposition.tau;
  json["tau_rel"] = labels.tau_rel >= 0 ? Json(labels.tau_rel) : Json(nullptr);
  json["max_hulls"] = decomposition.max_hulls;
  json["merge_growth"] =
      decomposition.merge_growth >= 0 ? Json(decomposition.merge_growth) : Json(nullptr);

  Json components = Json::array();
  for (const Component3d& component : decomposition.components) {
    Json c;
    c["mesh"] = MeshToJson(component.mesh);
    c["hull"] = MeshToJson(component.hull);
    c["volume"] = component.volume;
    c["hull_volume"] = component.hull_volume;
    c["centroid"] = VectorToJson(component.centroid);
    c["concavity"] = component.concavity;
    c["source"] = component.source;
    components.push_back(std::move(c));
  }
  json["components"] = std::move(components);

  Json openings = Json::array();
  for (const Opening3d& opening : decomposition.openings) {
    Json o;
    auto ring_json = [](const std::vector<Eigen::Vector3d>& ring) {
      Json points = Json::array();
      for (const Eigen::Vector3d& p : ring) points.push_back(VectorToJson(p));
      return points;
    };
    o["polygon"] = ring_json(opening.polygon);
    Json holes = Json::array();
    for (const std::vector<Eigen::Vector3d>& hole : opening.holes) holes.push_back(ring_json(hole));
    o["holes"] = std::move(holes);
    o["normal"] = VectorToJson(opening.normal);
    o["area"] = opening.area;
    o["components"] = Json::array({opening.component_a, opening.component_b});
    openings.push_back(std::move(o));
  }
  json["openings"] = std::move(openings);

  const DecompositionStats3d& stats = decomposition.stats;
  json["stats"] = {{"vertices", stats.vertices},       {"triangles", stats.triangles},
                   {"components", stats.components},   {"volume", stats.volume},
                   {"hull_volume", stats.hull_volume}, {"max_concavity", stats.max_concavity},
                   {"surface", stats.surface},         {"time_ms", stats.time_ms}};

  // Extension, as in 2D: the component adjacency graph of the openings.
  json["graph"] = ComponentGraph(decomposition);
  return json.dump() + "\n";
}

ObjFiles Decomposition3dToObj(const Decomposition3d& decomposition, const std::string& mtl_name) {
  std::vector<SceneMesh3d> scene;
  const int n = static_cast<int>(decomposition.components.size());
  for (int k = 0; k < n; ++k) {
    scene.push_back({"component_" + std::to_string(k), decomposition.components[k].mesh,
                     ComponentRgb(k), 1.0, false});
  }
  for (int k = 0; k < n; ++k) {
    scene.push_back({"hull_" + std::to_string(k), decomposition.components[k].hull, ComponentRgb(k),
                     kHullOpacity, false});
  }
  ObjFiles files = SceneToObj(
      scene, mtl_name,
      "acdplan 3D decomposition: " + std::to_string(n) + " components and their convex hulls");
  files.mtl = "# acdplan 3D decomposition: component colours; hulls translucent\n" + files.mtl;
  return files;
}

ObjFiles SceneToObj(const std::vector<SceneMesh3d>& scene, const std::string& mtl_name,
                    const std::string& title) {
  ObjFiles files;
  std::ostringstream obj, mtl;
  obj << "# " << title << "\n";
  if (!mtl_name.empty()) obj << "mtllib " << mtl_name << "\n";
  // OBJ vertex indices are 1-based and global to the file: each object's faces refer to the
  // vertices written just before them.
  long long written = 0;
  for (const SceneMesh3d& item : scene) {
    const TriangleMesh& mesh = item.mesh;
    obj << "o " << item.name << "\nusemtl " << item.name << "\n";
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
      obj << "v " << FormatShortest(mesh.vertices(i, 0)) << " "
          << FormatShortest(mesh.vertices(i, 1)) << " " << FormatShortest(mesh.vertices(i, 2))
          << "\n";
    }
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      obj << "f " << written + mesh.triangles(f, 0) + 1 << " " << written + mesh.triangles(f, 1) + 1
          << " " << written + mesh.triangles(f, 2) + 1 << "\n";
    }
    written += mesh.vertices.rows();
  }
  for (const SceneMesh3d& item : scene) {
    const Eigen::Vector3d& rgb = item.rgb;
    const std::string kd = FormatSignificant(rgb[0], 4) + " " + FormatSignificant(rgb[1], 4) + " " +
                           FormatSignificant(rgb[2], 4);
    mtl << "newmtl " << item.name << "\nKa " << kd << "\nKd " << kd << "\nKs 0 0 0\n"
        << "d " << FormatSignificant(item.opacity, 4) << "\nTr "
        << FormatSignificant(1.0 - item.opacity, 4) << "\nillum 1\n\n";
  }
  files.obj = obj.str();
  files.mtl = mtl.str();
  return files;
}

std::vector<std::uint8_t> Decomposition3dToGlb(const Decomposition3d& decomposition) {
  GlbBuilder glb;
  const int n = static_cast<int>(decomposition.components.size());
  // Surface patches are open: their back sides show, so their material is double sided.
  const bool open = decomposition.stats.surface;
  for (int k = 0; k < n; ++k) {
    const std::string name = "component_" + std::to_string(k);
    glb.AddMesh(name, decomposition.components[k].mesh,
                glb.AddMaterial(name, ComponentRgb(k), 1.0, open));
  }
  for (int k = 0; k < n; ++k) {
    const std::string name = "hull_" + std::to_string(k);
    glb.AddMesh(name, decomposition.components[k].hull,
                glb.AddMaterial(name, ComponentRgb(k), kHullOpacity, false));
  }
  return glb.Finish();
}

std::string Decomposition3dToSvg(const Decomposition3d& decomposition,
                                 const DecompositionLabels& labels) {
  // A solid's components are closed and outward-oriented: a triangle facing away from the
  // viewer is hidden behind the front ones, so it is dropped (half the file). Surface patches
  // are open: both sides show, shaded by the side seen.
  std::vector<SceneMesh3d> scene;
  Eigen::AlignedBox3d extent;
  const int n = static_cast<int>(decomposition.components.size());
  for (int k = 0; k < n; ++k) {
    const TriangleMesh& mesh = decomposition.components[k].mesh;
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
      const Eigen::Vector3d p = mesh.vertices.row(i).transpose();
      if (p.allFinite()) extent.extend(p);
    }
    scene.push_back({"component_" + std::to_string(k), mesh, ComponentRgb(k), 1.0,
                     decomposition.stats.surface});
  }
  const InteriorFaces interior(decomposition, extent.isEmpty() ? 0.0 : extent.diagonal().norm());
  const auto hidden = [&](int k, const Eigen::Vector3d p[3]) {
    return !decomposition.stats.surface && interior.Contains(k, p);
  };

  const DecompositionStats3d& stats = decomposition.stats;
  std::vector<std::string> caption;
  caption.push_back(labels.input.empty() ? std::string("(unnamed input)") : labels.input);
  std::string line = "tau " + FormatSignificant(decomposition.tau, 4);
  if (labels.tau_rel >= 0) line += " (tau_rel " + FormatSignificant(labels.tau_rel, 4) + ")";
  if (decomposition.max_hulls > 0) line += ", max hulls " + std::to_string(decomposition.max_hulls);
  line += ", " + std::string(stats.surface ? "surface" : "solid") + " ACD, " +
          Plural(decomposition.components.size(), "component");
  if (!stats.surface && stats.volume > 0) {
    line += ", hull volume / volume " + FormatSignificant(stats.hull_volume / stats.volume, 4);
  }
  line += ", max concavity " + FormatSignificant(stats.max_concavity, 4) + ", " +
          FormatSignificant(stats.time_ms, 4) + " ms";
  caption.push_back(line);
  const std::string title = caption[0] + ": " + caption[1];
  caption.push_back(ViewCaption(false) + "; one colour per component");
  return RenderSvg(scene, hidden, false, "components", caption, title);
}

std::vector<std::uint8_t> SceneToGlb(const std::vector<SceneMesh3d>& scene) {
  GlbBuilder glb;
  for (const SceneMesh3d& item : scene) {
    glb.AddMesh(item.name, item.mesh,
                glb.AddMaterial(item.name, item.rgb, item.opacity, item.two_sided));
  }
  return glb.Finish();
}

std::string SceneToSvg(const std::vector<SceneMesh3d>& scene,
                       const std::vector<std::string>& caption, bool z_up) {
  std::vector<std::string> lines = caption;
  const std::string title = lines.empty() ? std::string() : lines[0];
  lines.push_back(ViewCaption(z_up));
  return RenderSvg(
      scene, [](int, const Eigen::Vector3d*) { return false; }, z_up, "scene", lines, title);
}

}  // namespace acdplan::acd
