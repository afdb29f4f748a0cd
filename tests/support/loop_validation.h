// The loop's validation (docs/validation.md "The loop on every vehicle"): one case
// (a truth and a pool) through the pool verdict and the loop, and the tallies over cases that
// the full-size program (tests/validation/loop_validation.cc) prints and the CI subset
// (tests/planner/loop_validation_test.cc) asserts:
//   - feasibility: JudgePool's verdict at the loop's target against the loop's end (a hosted
//     pool never ends infeasible nor stuck; a pool not hosted is refused by `loop` with exit 1
//     before any trial, and RunLoop itself, run anyway, must not converge there);
//   - on converged cases, each final estimate of a parameter of interest within 3σ of the truth
//     (|θ̂ − θ| ≤ 3σ; required ≥ 95% of them over all cases);
//   - the stop reason of the others; the most runs of one design without new information
//     (required ≤ LoopOptions::max_repeats = 2).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::testing {

/// One final estimate against its truth.
struct EstimateCheck {
  model::Dof dof = model::Dof::kSurge;
  std::string name;
  double value = 0.0, sigma = 0.0, truth = 0.0;
  double z = 0.0;  ///< (value − truth)/σ
  bool within3 = false;
};

struct LoopCaseOutcome {
  std::string name;
  std::vector<model::Dof> dofs;
  bool hosted = false;  ///< JudgePool's verdict on the loop's DOFs: hosted over the whole box
  planner::Hostability hostability = planner::Hostability::kNone;  ///< all / part / none
  std::string verdict;                                             ///< its sentence
  /// Per DOF of the verdict: the loop's trials to the target predicted at the worst point of
  /// the box (TargetReach: bottleneck, n, per-trial and needed percentile errors).
  std::string reach;
  /// The verdict for the true vehicle itself (a degenerate box at the truth, box_points.h).
  bool hosted_at_truth = false;
  planner::LoopStatus status = planner::LoopStatus::kInfeasible;  ///< RunLoop's end
  std::string message;
  int trials = 0;
  double pool_time_s = 0.0;
  double wall_s = 0.0;
  /// hosted ⇒ neither infeasible nor stuck; not hosted ⇒ not converged (the `loop` command exits 1
  /// before any trial there, RunLoop must not claim the contrary).
  bool agree = false;
  std::vector<EstimateCheck> interest;  ///< final parameters of interest (estimated, not held)
  /// Every parameter the last fit estimated, of every DOF (not those held or dropped).
  std::vector<EstimateCheck> every;
  int most_repeats = 0;  ///< planner::MostUninformativeRepeats
};

/// Runs the verdict and the loop (seed `seed`, defaults otherwise) on `truth` in `pool`.
LoopCaseOutcome RunLoopCase(const std::string& name, const model::Truth& truth,
                            const model::Pool& pool, std::uint64_t seed);

struct LoopTally {
  int cases = 0, hosted = 0, agree = 0, converged = 0;
  int hosted_agree = 0;    ///< hosted pools whose loop ended neither infeasible nor stuck
  int refused_agree = 0;   ///< pools hosted for no point of the box whose RunLoop did not converge
  int part = 0, none = 0;  ///< pools hosted for part of the box, for none
  int part_converged = 0, part_outside = 0;  ///< part pools: converged, infeasible (outside)
  /// The verdict at the true vehicle (box_points.h) against the loop: [hosted at the truth?]
  /// [converged?] counts (the measurement behind choosing the three-valued verdict).
  int at_truth[2][2] = {{0, 0}, {0, 0}};
  int interest = 0, within3 = 0;     ///< over converged cases
  int every = 0, every_within3 = 0;  ///< every estimated parameter, over converged cases
  int most_repeats = 0;
  std::vector<std::string> failures;  ///< every broken claim, one sentence each

  void Add(const LoopCaseOutcome& c, int max_repeats);
  /// Every claim holds: all agree, ≥ 95% within 3σ, repeats ≤ max_repeats (checked in Add).
  bool Pass() const;
};

/// One line per case and the tally, units on every number.
std::string CaseLine(const LoopCaseOutcome& c);
std::string TallyText(const LoopTally& t);

}  // namespace uuvplan::testing
