#pragma once
// Writing a 3D decomposition: the acdplan.decomposition3d/1 JSON, OBJ (+ MTL), binary glTF
// and an SVG preview a person can look at without a 3D viewer.

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

}  // namespace acdplan::acd
