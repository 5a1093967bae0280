#pragma once
// The ACD tolerance of a planning world, given relative to the diagonal of the world's bounds
// so that one value suits worlds of any size (scenario YAML `acd.tau_diag`,
// `acdplan env --tau-diag`).

#include <Eigen/Geometry>

namespace acdplan::planning {

/// The tau_diag of a scenario that gives none.
inline constexpr double kDefaultTauDiag = 0.02;

/// The absolute ACD tolerance of a world with `bounds`: tau_diag x the bounds' diagonal.
template <int Dim>
double TauOfBounds(double tau_diag, const Eigen::AlignedBox<double, Dim>& bounds) {
  return tau_diag * bounds.sizes().norm();
}

}  // namespace acdplan::planning
