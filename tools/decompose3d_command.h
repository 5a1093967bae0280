#pragma once
// `acdplan decompose MESH`: the 3D approximate convex decomposition of a mesh file
// (dissertation Ch. V), its report and its outputs.

#include <optional>
#include <string>

#include "acd/decompose3d.h"

namespace acdplan::tools {

/// What `acdplan decompose MESH` was asked.
struct Decompose3dArguments {
  std::string input;                   ///< A mesh file (envs::IsMeshFile()).
  double tau = -1.0;                   ///< Absolute tolerance [mesh units]; < 0: not given.
  double tau_rel = -1.0;               ///< Relative to acd::ReferenceRadius(); < 0: not given.
  bool surface = false;                ///< The surface ACD even for a solid.
  int max_hulls = 0;                   ///< Merge down to at most this many components; 0: no cap.
  std::optional<double> merge_growth;  ///< Solid ACD's merge pass; unset: its default.
  bool repair = false;                 ///< Close holes and remove self-intersections first.
  bool check = false;                  ///< acd::CheckDecomposition3d() before writing anything.
  std::string json_path, obj_path, glb_path, svg_path;
};

/// tau_rel when neither --tau nor --tau-rel is given: a part of about 5% of the mesh's
/// enclosing radius may stay concave (between the dissertation's Table 5 settings 0.2 and
/// 0.02).
constexpr double kDefaultTauRel3d = 0.05;

/// The material file written beside the OBJ file `obj_path`: its extension replaced by .mtl.
std::string MtlPathFor(const std::string& obj_path);

/// Runs `acdplan decompose MESH`: reads and prepares the mesh, chooses the solid or the surface
/// ACD, decomposes, prints a report on stdout and writes the outputs asked for, each atomically.
/// Which ACD runs (README "The decompose command on meshes"):
///  - the prepared mesh is a solid (closed, manifold, no self-intersections; after repair with
///    --repair) and --surface is not given: the solid ACD;
///  - --surface, or the prepared mesh is open (boundary edges), or --repair could not make it
///    a solid: the surface ACD;
///  - otherwise (closed, but non-manifold or self-intersecting, no --repair): an InputError
///    naming the defect (acd::RequireSolid()).
/// @return the exit status: 0 done; 1 when --check finds a problem (nothing is written).
/// @throws InputError for an unreadable or unusable mesh, a bad option or an unwritable
///         output path (exit status 2).
int RunDecompose3d(const Decompose3dArguments& args);

}  // namespace acdplan::tools
