#pragma once
// A DOF direction as its scene numbers it. Plane scenes (dimension 1 or 2) number x 0, y 1 and
// the rotation about z 2; 3-D scenes number x 0, y 1, z 2 and the rotations about x, y, z 3, 4,
// 5 (the order of the 12-DOF beam-column, assembly/beam_3d.hpp). What names, measures or excites
// a direction asks here rather than testing an index, so that a plane model keeps its numbering,
// its result columns and its messages whatever 3-D adds.
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

}  // namespace pound::model
