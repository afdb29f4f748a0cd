// The pool that hosts the trials (contract §Pool), and its extents along each DOF: wall to
// wall, and free (less the margin kept clear at both ends); for a rotation, the twist a
// tethered vehicle's tether takes (max_turns full turns).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::model {

struct Pool {
  std::string name;
  double length = 0.0;  ///< m, along the surge axis of the trials
  double width = 0.0;   ///< m, along sway
  double depth = 0.0;   ///< m
  double margin = 0.0;  ///< m kept clear of every wall, the floor and the surface
  /// Largest rotation (full turns, 2π rad each) of a trial about roll, pitch or yaw: the twist
  /// the vehicle's tether takes. CHOSEN default 3 turns (docs/formats.md): a tether's slack
  /// takes a few turns before it kinks; an untethered vehicle gives a large value.
  double max_turns = kDefaultMaxTurns;
  static constexpr double kDefaultMaxTurns = 3.0;

  /// Wall-to-wall extent along a DOF (m): length, width or depth; infinite for rotations.
  double WallToWall(Dof dof) const {
    switch (dof) {
      case Dof::kSurge:
        return length;
      case Dof::kSway:
        return width;
      case Dof::kHeave:
        return depth;
      default:
        return std::numeric_limits<double>::infinity();
    }
  }
  /// Free travel along a DOF: wall to wall less the margin at both ends (m); for a rotation
  /// the tether's twist, 2π·max_turns (rad).
  double FreeTravel(Dof dof) const {
    return IsRotational(dof) ? 2 * M_PI * max_turns : WallToWall(dof) - 2 * margin;
  }
  /// The wall-to-wall extent (m) a pool needs to offer `free_travel` m: plus both margins.
  double WallToWallFor(double free_travel) const { return free_travel + 2 * margin; }
  /// What a pool must offer along `dof` for a free travel `free`: wall to wall (m) for a
  /// translation, full turns of the tether for a rotation.
  double ExtentFor(Dof dof, double free) const {
    return IsRotational(dof) ? free / (2 * M_PI) : WallToWallFor(free);
  }
  /// The pool side a translation travels along ("length", "width", "depth"); "" otherwise.
  static std::string_view SideName(Dof dof) {
    constexpr EnumNames<Dof, 3> kSideNames{
        {{{Dof::kSurge, "length"}, {Dof::kSway, "width"}, {Dof::kHeave, "depth"}}}};
    return IsRotational(dof) ? "" : kSideNames.Name(dof);
  }
};

}  // namespace uuvplan::model
