#pragma once
// How far from a plane a point of a solid still counts as in it. Internal.

namespace acdplan::acd::internal {

/// How far from a plane, relative to a mesh's size, a point still counts as in it. Meshes are
/// mostly stored in single precision (STL always; every format assimp reads), which rounds a
/// coordinate by up to 6e-8 of its size: a planar face of a model turned off the axes is flat
/// only to about 1e-7 of the mesh's size (measured: 1.4e-6 on wall.obj turned at random, size
/// 19). At 1e-9 such a face was a dozen hull facets with pockets between them, and the turned
/// wall fell into 23 components instead of 10. Used alike by the hull's facets
/// (MakeCanonicalHull), the concavity (MeasureSolidConcavity), the plane cut (SplitByPlane),
/// the openings (ComputeOpenings) and CheckDecomposition3d.
constexpr double kInPlaneTolerance = 1e-6;

}  // namespace acdplan::acd::internal
