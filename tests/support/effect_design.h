// Designs for effects: payload60's frame with a hidden thruster lag in surge, the
// vehicle file that `identify --write-vehicle` would write for it, and the lag identified on a
// schedule's trials run in the virtual pool. Shared by tests/planner/effect_design_test.cc (10
// seeds) and tests/validation/effect_design_validation.cc (full size, docs/validation.md).
#pragma once

#include <cstdint>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::testing {

struct LagCase {
  model::Truth truth;         ///< the frame's truth, surge with `lag`
  model::Vehicle identified;  ///< its vehicle with the surge truth as a model with σ
  model::Pool pool;
};

/// `frame` (cases/payload60/frame/truth.yaml) with a surge thruster lag `lag` (s), in `pool`;
/// the identified vehicle gives the lag σ 0.015 s and every other parameter 3% of itself.
LagCase MakeFrameLagCase(model::Truth frame, model::Pool pool, double lag);

/// The surge lag identified (its value and σ) on `designs` run in the virtual pool with seeds
/// first .. first + n − 1, by `identify` reading the identified vehicle file.
struct LagEstimate {
  double value = 0.0, sigma = 0.0;
};
std::vector<LagEstimate> IdentifiedLags(const LagCase& c,
                                        const std::vector<model::TrialDesign>& designs,
                                        std::uint64_t first, int n);

}  // namespace uuvplan::testing
