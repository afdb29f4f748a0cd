// `loop --diagnose` on a truth with hidden effects (planner::LoopOptions::diagnose): the truth
// made, the loop run, and its end judged against the truth. Shared by
// tests/planner/loop_diagnose_test.cc (seeded subset) and tests/validation/
// loop_diagnose_validation.cc (full size, docs/validation.md).
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/planner/loop/design_loop.h"

namespace uuvplan::testing {

/// `truth` with, on `dof`, a first-order thruster lag (s) and a thrust map wrong in shape: the
/// delivered force u0·(|u0|/reference)^exponent, so |force|^(1 + exponent) where the vehicle
/// file's map says |force|^1 (exponent −0.3: force ∝ |command|^0.7 for a map linear in the
/// command).
model::Truth WithLagAndThrustMap(model::Truth truth, model::Dof dof, double lag, double exponent,
                                 double reference);

/// A parameter of the loop's final model against the truth restated at the estimate's thrust
/// reference (model/thrust_reference.h); a parameter the truth lacks is compared with its null
/// value (η 1, others 0).
struct ParameterCheck {
  std::string name;
  double value = 0.0, sigma = 0.0, truth = 0.0;
  double Sigmas() const { return (value - truth) / sigma; }
};

struct DiagnosedLoopOutcome {
  planner::LoopResult result;
  std::set<std::string> effects;  ///< in the DOF's final model (entered and not left)
  std::vector<ParameterCheck> params;
  /// Converged, every effect in `expected` named, no other, every parameter within 3σ.
  bool Pass(const std::set<std::string>& expected) const;
  std::string Line() const;  ///< one line for a log: status, trials, effects, worst parameter
};

/// RunLoop on `dof` of `truth` in `pool` with LoopOptions::diagnose (default options) and
/// `seed`, judged against `truth`.
DiagnosedLoopOutcome RunDiagnosedLoop(const model::Truth& truth, const model::Pool& pool,
                                      model::Dof dof, std::uint64_t seed);

}  // namespace uuvplan::testing
