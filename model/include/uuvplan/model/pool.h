// The pool that hosts the trials (contract §Pool).
#pragma once

#include <limits>
#include <string>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

struct Pool {
  std::string name;
  double length = 0.0;  ///< m, along the surge axis of the trials
  double width = 0.0;   ///< m, along sway
  double depth = 0.0;   ///< m
  double margin = 0.0;  ///< m kept clear of every wall, the floor and the surface

  /// Free travel available to a DOF (m): length/width/depth less twice the margin;
  /// infinite for rotations.
  double Available(Dof dof) const {
    switch (dof) {
      case Dof::kSurge: return length - 2 * margin;
      case Dof::kSway: return width - 2 * margin;
      case Dof::kHeave: return depth - 2 * margin;
      default: return std::numeric_limits<double>::infinity();
    }
  }
};

}  // namespace uuvplan::model
