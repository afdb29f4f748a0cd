// What the single sine (sine_design.cc) and the mapping-switched designs (switched_design.cc)
// optimise: a trial's criterion at each design point of the box, on its information as the
// optimisers see it (DofPlanningProblem::DesignInformation) plus the prior; its travel over those
// points within the pool's free travel less the sine family's margin; and the frequency
// variable v of their waves, ω = ω_lo·(ω_hi/ω_lo)^v over SineFrequencyRange.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "uuvplan/model/excitation.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/sine_design.h"

namespace uuvplan::planner {

class SineFamilyObjective {
 public:
  /// `force_abs`: the force level whose optimal frequencies span ω; `duration`: the longest
  /// trial (s), which must hold min_periods periods of ω_lo; `harmonics`: the wave's highest
  /// harmonic of ω (the sensors bound it, SineFrequencyRange).
  SineFamilyObjective(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                      const std::vector<Eigen::MatrixXd>& prior, double force_abs, double duration,
                      int harmonics = 1);

  /// The trial `input` of `duration` s in its model `tm`: the criterion at design point j into
  /// phi[j]. Returns the span of its position over the design points (m or rad).
  double Criteria(const DofPlanningProblem::TrialModel& tm, const model::Excitation& input,
                  double duration, double* phi) const;
  /// The travel constraint (<= 0: met) of a span: its excess over the free travel less the
  /// margin, relative to the free travel; −1 when the pool does not limit the DOF.
  double TravelExcess(double span) const;

  /// ω of the design variable v (clamped to [0, 1]).
  double Omega(double v) const;
  const std::array<double, 2>& omega_range() const { return omega_; }
  /// False when the sensors resolve no wave of min_periods periods in the trial's duration
  /// (SineFrequencyRange empty): the family has no design there.
  bool Resolvable() const { return omega_[1] >= omega_[0]; }

 private:
  const DofPlanningProblem& ctx_;
  Criterion criterion_;
  const std::vector<Eigen::MatrixXd>& prior_;
  std::vector<int> interest_;
  std::array<double, 2> omega_;
};

}  // namespace uuvplan::planner
