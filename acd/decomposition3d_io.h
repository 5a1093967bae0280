#pragma once
// Writing a 3D decomposition: the acdplan.decomposition3d/1 JSON, OBJ (+ MTL), binary glTF
// and an SVG preview a person can look at without a 3D viewer.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "acd/decomposition3d.h"
#include "acd/decomposition_io.h"

namespace acdplan::acd {

/// The decomposition JSON ("format": "acdplan.decomposition3d/1", README and DESIGN.md).
std::string Decomposition3dToJson(const Decomposition3d& decomposition,
                                  const DecompositionLabels& labels);

/// Wavefront OBJ: one object per component ("component_<i>") and per hull ("hull_<i>"), each
/// with its own material from the MTL text (component colours as in the SVG; hulls the same
/// colour, translucent). `mtl_name` is the file name the OBJ's mtllib line refers to.
struct ObjFiles {
  std::string obj;
  std::string mtl;
};
ObjFiles Decomposition3dToObj(const Decomposition3d& decomposition, const std::string& mtl_name);

/// Binary glTF 2.0 (.glb): one node per component and per hull, coloured materials (hulls
/// translucent), so any viewer shows the parts apart.
std::vector<std::uint8_t> Decomposition3dToGlb(const Decomposition3d& decomposition);

/// An SVG preview: the components in distinct flat-shaded colours, seen from an oblique
/// direction in orthographic projection, with a caption (input, tau, components, time).
std::string Decomposition3dToSvg(const Decomposition3d& decomposition,
                                 const DecompositionLabels& labels);

/// A coloured mesh of a 3D scene (a planning picture: obstacles, openings, robot, path).
struct SceneMesh3d {
  std::string name;                                      ///< OBJ object / glTF node name.
  TriangleMesh mesh;                                     ///< Its triangles.
  Eigen::Vector3d rgb = Eigen::Vector3d::Constant(0.6);  ///< sRGB colour in [0, 1].
  double opacity = 1.0;                                  ///< In (0, 1].
  bool two_sided = false;  ///< Open or flat (both sides show; no back-face culling).
};

/// The scene as a Wavefront OBJ (one object and one material per mesh), the writer of
/// Decomposition3dToObj(); `title` is the first comment line.
ObjFiles SceneToObj(const std::vector<SceneMesh3d>& scene, const std::string& mtl_name,
                    const std::string& title);

/// The scene as binary glTF 2.0 (one node and material per mesh).
std::vector<std::uint8_t> SceneToGlb(const std::vector<SceneMesh3d>& scene);

/// An SVG of the scene in the preview's oblique orthographic view (Decomposition3dToSvg()),
/// painter's algorithm, each mesh flat-shaded in its colour and opacity; with `z_up` the scene
/// is turned so that its +z axis points up in the picture. `caption`: lines under the picture.
std::string SceneToSvg(const std::vector<SceneMesh3d>& scene,
                       const std::vector<std::string>& caption, bool z_up);

}  // namespace acdplan::acd
