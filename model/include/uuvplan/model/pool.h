// The pool that hosts the trials (contract §Pool), and its extents along each DOF: wall to
// wall, and free (less the margin kept clear at both ends).
#pragma once

#include <limits>
#include <string>
#include <string_view>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

struct Pool {
  std::string name;
  double length = 0.0;  ///< m, along the surge axis of the trials
  double width = 0.0;   ///< m, along sway
  double depth = 0.0;   ///< m
  double margin = 0.0;  ///< m kept clear of every wall, the floor and the surface

  /// Wall-to-wall extent along a DOF (m): length, width or depth; infinite for rotations.
  double WallToWall(Dof dof) const {
    switch (dof) {
      case Dof::kSurge: return length;
      case Dof::kSway: return width;
      case Dof::kHeave: return depth;
      default: return std::numeric_limits<double>::infinity();
    }
  }
  /// Free travel along a DOF (m): wall to wall less the margin at both ends; infinite for
  /// rotations.
  double FreeTravel(Dof dof) const { return WallToWall(dof) - 2 * margin; }
  /// The wall-to-wall extent (m) a pool needs to offer `free_travel` m: plus both margins.
  double WallToWallFor(double free_travel) const { return free_travel + 2 * margin; }
  /// The pool side a translation travels along ("length", "width", "depth"); "" otherwise.
  static std::string_view SideName(Dof dof) {
    switch (dof) {
      case Dof::kSurge: return "length";
      case Dof::kSway: return "width";
      case Dof::kHeave: return "depth";
      default: return "";
    }
  }
};

}  // namespace uuvplan::model
