// The a priori uncertainty of a DOF's parameters as a box (ref 000 §III-B): the inertia between
// its added-mass bounds, the drag within its relative uncertainty, the installation coefficients
// of non-open-water directions within their plausible range. Robust designs optimise the worst
// case or the average over the box's vertices and centre; hard constraints are checked on a
// denser grid of the box.
//
// Each axis scales a group of parameters by one factor f in [lo, hi] about their nominal values
// (k and kq move together: the a priori drag fit is one curve known to ±rel_sigma).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::planner {

using ParameterValues = std::map<std::string, double>;

struct BoxAxis {
  std::string name;                 ///< "m", "drag", "eta"
  std::vector<std::string> params;  ///< parameters scaled together
  double lo = 1.0;                  ///< smallest factor on the nominal values
  double hi = 1.0;                  ///< largest factor
  /// false: the axis is only varied in constraint checks (CheckPoints), held at the nominal
  /// in design points (keeps robust designs at 2^2 + 1 simulations per evaluation).
  bool in_design = true;
};

struct ParameterBox {
  ParameterValues nominal;
  std::vector<BoxAxis> axes;

  /// Centre first, then the 2^n vertices of the design axes.
  std::vector<ParameterValues> DesignPoints() const;
  /// A grid of `per_axis` (>= 2) values on every axis, design or not (vertices included).
  std::vector<ParameterValues> CheckPoints(int per_axis) const;
  /// Values at given factors (axis order), other parameters nominal.
  ParameterValues At(const std::vector<double>& factors) const;
  /// `n` points drawn uniformly from the box, every axis in turn per point (seeded).
  std::vector<ParameterValues> Sample(int n, std::uint64_t seed) const;
  /// Nominal value of a parameter, or `fallback`.
  double Nominal(const std::string& name, double fallback = 0.0) const;
};

struct BoxOptions {
  /// Half-width of the drag axis in units of the prior's rel_sigma: k, kq × [1 - n·rs, 1 + n·rs].
  double drag_sigmas = 1.0;
  /// Nominal installation coefficient of a non-open-water direction. CHOSEN: ref 000 Tables
  /// II-IV report 0.56-0.89; 0.8 is the middle of that range rounded up.
  double eta_nominal = 0.8;
  /// Range of eta in constraint checks (ref 000: 0.56-0.89; 1 = open water).
  std::array<double, 2> eta_range = {0.5, 1.0};
  /// Relative uncertainty assumed when a DOF has no a priori drag (model::DragOf's fallback).
  double fallback_drag_rel_sigma = 0.5;
};

/// The a priori box of `dof` for a model with parameters `parameter_names` (DofModel order).
/// Without `dofs.<dof>.drag` in the vehicle, the drag is model::DragOf's fallback (the drag
/// that holds the vehicle at 1 m/s or 1 rad/s under its largest thrust) and a note saying so,
/// model::DragAssumption, is appended to `notes`.
ParameterBox APrioriBox(const model::Vehicle& vehicle, model::Dof dof,
                        const std::vector<std::string>& parameter_names, const BoxOptions& options,
                        std::vector<std::string>* notes);

/// The a priori box of a multi-DOF model's global θ: the product of its DOFs' boxes above (each
/// over the DOF's parameters the model does not tie), named as the model names them ("sway.k";
/// axes "sway.m", "sway.drag"). Only the inertia axes are design axes: the criterion at their
/// 2^n vertices and the centre, the drags varying in the check points.
ParameterBox JointAPrioriBox(const model::Vehicle& vehicle, const model::MultiDofModel& model,
                             const BoxOptions& options, std::vector<std::string>* notes);

/// A box about current estimates (for the next trial of a sequential design): m and the drag
/// group each ± `n_sigma`·σ (relative σ capped at 0.9), eta within the a priori range.
ParameterBox EstimateBox(const ParameterValues& estimates, const ParameterValues& sigmas,
                         const std::vector<std::string>& parameter_names, double n_sigma,
                         const BoxOptions& options);

}  // namespace uuvplan::planner
