#pragma once
// The searches behind a hole's link (Eqn. 4.2), kept so that the pieces cut from a polygon
// inherit them instead of searching again.

#include <array>
#include <limits>
#include <vector>

namespace acdplan::acd::internal {

/// The antipodal pair of a hole (indices into the hole ring) and the distance between them.
struct HoleAntipodes {
  int a, b;
  double distance;
};

/// A vertex nearest to a point, and whether another lies exactly as near.
struct NearestVertex {
  int vertex = -1;
  double d2 = std::numeric_limits<double>::infinity();  // Squared distance.
  bool tie = false;

  /// Takes vertex `id` at squared distance `d2` if nearer, the lower id on equal distance.
  void Offer(int id, double offered_d2) {
    if (offered_d2 < d2) {
      vertex = id;
      d2 = offered_d2;
      tie = false;
    } else if (offered_d2 == d2) {
      tie = true;
      if (id < vertex) vertex = id;
    }
  }
};

/// A vertex of a hole nearest to a point: ring (hole index; INT_MAX none), index, squared
/// distance and distance.
struct HoleVertex {
  int ring = std::numeric_limits<int>::max();
  int vertex = 0;
  double d2 = std::numeric_limits<double>::infinity();
  double distance = std::numeric_limits<double>::infinity();
};

/// What the link search of one antipode found: the nearest outer vertex and the nearest vertex
/// of another hole. The latter holds only when it lies within the outer vertex's distance;
/// otherwise every vertex of the other holes lies farther than the outer vertex.
struct AntipodeNeighbours {
  NearestVertex outer;
  HoleVertex hole;
};

/// Per hole of a measured piece: its antipodes and what each one's search found.
struct HoleNeighbours {
  HoleAntipodes antipodes;
  std::array<AntipodeNeighbours, 2> ends;
};

/// What a piece cut from a measured parent inherits of the parent's hole searches: a hole of
/// the piece is a hole of the parent, unchanged, so its antipodes stand, and so does a nearest
/// vertex that the piece still has, when the piece's new vertices lie no nearer. Both null:
/// nothing is inherited.
struct InheritedHoles {
  const std::vector<HoleNeighbours>* parent = nullptr;  ///< Per hole of the parent.
  /// Per hole of the piece, the parent's hole it copies, increasing.
  const std::vector<int>* origin = nullptr;
};

}  // namespace acdplan::acd::internal
