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
  /// Half-width, in σ, of the box about an identified model the vehicle file gives
  /// (model::DofParameters): ± 3σ holds the true value of a Gaussian estimate with 99.7%
  /// probability, so a robust design over it holds for the vehicle as identified.
  double estimate_sigmas = 3.0;
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

/// EstimateBox about the estimates that `apriori` (a box over `parameter_names`) has a value
/// for, with every axis whose parameters have no estimate with a σ kept at `apriori`'s range.
ParameterBox BoxAboutEstimates(const ParameterBox& apriori,
                               const std::vector<std::string>& parameter_names,
                               const ParameterValues& estimates, const ParameterValues& sigmas,
                               double n_sigma, const BoxOptions& options);

/// The least inertia `dof` can physically have: a submerged body's added mass matrix is positive
/// definite (Fossen 2011 §6.3.1), so a translation's m is at least the weighed dry mass; a
/// rotational inertia in a vehicle file is computed from an assumed mass distribution and errs
/// by tens of percent (ROMEO's file gives 93.75 kg·m², seed 000 §IV-D measured 84 ± 5 with the
/// added inertia), so CHOSEN half of it is the rotations' floor.
double LeastInertia(const model::Vehicle& vehicle, model::Dof dof);

/// No inertia below LeastInertia in `box`, whose design points are simulated with steps of a
/// fraction of the box's shortest time constant: an estimate of m far too low (a loop's early
/// fit) would make that milliseconds and a design minutes. The m axis starts at the floor (its
/// centre moved inside); when all of it lies below, it is `apriori`'s m axis and nominal, with a
/// note.
void ClampToLeastInertia(const model::Vehicle& vehicle, model::Dof dof, const ParameterBox& apriori,
                         ParameterBox* box, std::vector<std::string>* notes);

/// The box a design of `dof` starts from: about the identified model the vehicle file gives
/// for it (vehicle.models, ± options.estimate_sigmas σ) when it has one, with a note naming
/// the estimates; else APrioriBox.
ParameterBox PlanningBox(const model::Vehicle& vehicle, model::Dof dof,
                         const std::vector<std::string>& parameter_names, const BoxOptions& options,
                         std::vector<std::string>* notes);

}  // namespace uuvplan::planner
