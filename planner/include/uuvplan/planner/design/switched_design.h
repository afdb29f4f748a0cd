// Robust optimal mapping-switched trials: the inertia trial in the input families
// beyond the single-mapping sine, and the choice among them by the robust criterion.
//
// A switched trial pushes each sign of phi_n with the mapping that works in open water for it
// (ref 000 Table I: surge-front forward, surge-rear backward; yaw-fl-rr clockwise, yaw-fr-rl
// counter-clockwise; sway-left / sway-right), so the vehicle oscillates about its start instead
// of crossing the pool, with no propeller ever reversing. Thrusters built to reverse (a T200)
// push both signs in one mapping: the same families about zero, the input of the 2016 BlueROV
// thesis (a random telegraph signal) kept in the middle of a small tank. Families
// (model::InputFamily):
//
//   switched-square  ±levels in the two mappings, period P, duty δ (the positive share of a
//                    period), phase ψ (the share of a period elapsed at t = 0): a `segments`
//                    trial; x = (level+, level-, P, δ, ψ)
//   switched-sine    w = offset + A·sin(ωt + p), |phi_n| >= each mapping's floor φ_min
//                    (min_thrust / smallest share): a `switched` trial; x = (A, offset, ω, p)
//   multisine        w = offset + s·Σ_{i=1..3} r_i·sin(i·ω·t + p_i), scaled so that its crest
//                    stays within both mappings' thrust ranges; x = (ω, r_1..3, p_1..3, s,
//                    offset)
//
// Every variable lies in [0, 1] and the thrust limits are bounds (levels and crests within
// [φ_min, φ_max] of each mapping; the wave is clamped to φ_min at its zero crossings). The pool
// is a constraint: the travel's span over the design points of the box within the free travel
// (less 5 mm), the start position then centring that span in the pool (trial_envelope.h
// StartOf). The criterion and robustness are the single sine's (SineDesignOptions); the duration
// is the fixed one, else the longest allowed (an oscillation does not cross the pool).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/model/trial_design.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/sine_design.h"

namespace uuvplan::planner {

/// A pair of mappings that can alternate: `pos` pushes phi_n > 0 and `neg` phi_n < 0 without
/// any thruster working in both with opposite signs, at least one of them in open water (the
/// other's eta is then estimated jointly and enters the information); or one mapping whose
/// thrusters are all reversible (model::Vehicle::Reverses), pos == neg: the zero-mean families,
/// each working thruster crossing from +min_thrust to −min_thrust at once (never idling in its
/// dead band).
struct SwitchPair {
  int pos = -1, neg = -1;
  ForceRange pos_range, neg_range;
  /// 0: a switched pair. ±1: no switch — mapping pos (== neg) in this direction only, both
  /// halves of the square (and the whole wave) within its force range.
  int one_way = 0;
};
std::vector<SwitchPair> SwitchPairs(const DofPlanningProblem& ctx);

/// What the one-way families take from the single sine (DesignInertiaTrial): its duration
/// (s; it fits the vehicle's drift to the pool), mapping and direction. Empty: every
/// open-water direction of every mapping, at the longest duration allowed.
struct OneWayHint {
  double duration_s = 0.0;
  std::string mapping;
  int sign = 0;  ///< +1, -1, or 0 for both
};
/// Every mapping and direction of ctx's DOF in open water (eta known) whose force range is
/// feasible, as one-way "pairs" (restricted to the hint's mapping and direction where it gives
/// them): the families of a DOF that has no switch pair.
std::vector<SwitchPair> OneWayPairs(const DofPlanningProblem& ctx, const OneWayHint& hint = {});

/// The best trial of one switched family over every switch pair of ctx's DOF (status kFailed
/// with a message when the DOF has no pair or no feasible design). A DOF without a switch pair
/// gets, when options.one_way_families, the square one way (family `piecewise`: two levels in
/// one direction) over OneWayPairs(ctx, hint), at the fixed duration, else at the hint's, else
/// the longest allowed.
SineDesignResult DesignSwitched(const DofPlanningProblem& ctx, model::InputFamily family,
                                const SineDesignOptions& options,
                                const std::vector<Eigen::MatrixXd>& prior, const std::string& id,
                                const OneWayHint& hint = {});

/// The inertia trial: the single-mapping sine (ref 000, the fallback) and every family of
/// options.families, the one with the largest robust criterion that passes its checks. The
/// notes say what each family reached.
SineDesignResult DesignInertiaTrial(const DofPlanningProblem& ctx, const SineDesignOptions& options,
                                    const std::vector<Eigen::MatrixXd>& prior,
                                    const std::string& id);

}  // namespace uuvplan::planner
