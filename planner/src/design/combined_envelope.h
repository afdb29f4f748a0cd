// The constraints side of a combined design (combined_design.h): its travel over the box's
// points, its thrusters, the constraint values the optimiser sees and the reasons a design does
// not fit. Planner library only.
#pragma once

#include <vector>

#include "uuvplan/model/excitation.h"
#include "uuvplan/planner/design/combined_design.h"

namespace uuvplan::planner::internal {

/// Each moved DOF's input as an excitation, the joint conditions pointing at them.
struct CombinedInputs {
  std::vector<std::unique_ptr<model::Excitation>> excitations;
  model::JointConditions conditions;
};
CombinedInputs InputsOf(const model::MultiDofModel& model, const model::Vehicle& vehicle,
                        const model::CombinedTrialDesign& trial);

/// t_k = k·dt over [0, duration].
std::vector<double> Grid(double duration, double dt);

/// The travel and turns of `trial` over `thetas` from rest, simulated every `o.step_s`.
CombinedEnvelope TrackEnvelope(const model::MultiDofModel& model, const CombinedInputs& inputs,
                               const model::CombinedTrialDesign& trial,
                               const std::vector<Eigen::VectorXd>& thetas,
                               const CombinedDesignOptions& o);

/// The thrusters' margin and load bounded from the sines' offsets and amplitudes, and the
/// closed-water force (for the optimiser: exact where the sines line up).
void ThrustBound(const model::Vehicle& vehicle, const model::CombinedTrialDesign& trial,
                 CombinedEnvelope* e);

/// The constraints g <= 0 of a design, each scaled to O(1): thrust margin, thrust load, one per
/// DOF of the model (travel or turns), closed-water force.
std::vector<double> Constraints(const model::MultiDofModel& model, const CombinedEnvelope& e,
                                const model::Vehicle& vehicle, const model::Pool& pool);

/// Why a design with envelope `e` does not fit, with figures (empty: it fits).
std::vector<std::string> Reasons(const model::MultiDofModel& model, const CombinedEnvelope& e,
                                 const model::Vehicle& vehicle, const model::Pool& pool);

}  // namespace uuvplan::planner::internal
