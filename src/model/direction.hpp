#pragma once
// A DOF direction as its scene numbers it. Plane scenes (dimension 1 or 2) number x 0, y 1 and
// the rotation about z 2; 3-D scenes number x 0, y 1, z 2 and the rotations about x, y, z 3, 4,
// 5 (the order of the 12-DOF beam-column, assembly/beam_3d.hpp). What names, measures or excites
// a direction asks here rather than testing an index, so that a plane model keeps its numbering,
// its result columns and its messages whatever 3-D adds.
#include <array>

namespace pound::model {

struct Direction {
  const char* symbol;  // in result columns and labels: "x", "rz"
  const char* words;   // in messages: "x", "rotation", "rotation about x"
  bool rotation;       // a rotation [rad], else a translation [L]
  int axis;            // 0 x, 1 y, 2 z: along it, or about it for a rotation
};

// Directions a node can have in a scene of `dimension` (1, 2 or 3): 3 or 6.
int direction_count(int dimension);
// Direction `index` (0 <= index < direction_count(dimension)) of a scene of `dimension`.
Direction direction(int index, int dimension);

// A vector (x, y, z) over a node's directions in a scene of `dimension`: its component along each
// translation's axis (about each rotation's axis, for `rotations`), 0 on the others. A plane
// scene's (nx, ny, 0) gives (nx, ny, 0); a rotation about z gives (0, 0, 1).
std::array<double, 6> over_directions(const std::array<double, 3>& vector, bool rotations,
                                      int dimension);

}  // namespace pound::model
