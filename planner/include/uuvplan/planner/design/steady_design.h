// Steady-state runs for the drag and installation coefficients (ref 000 §III-A, eqs. 7-10),
// and their packing into pool trials as back-and-forth legs (ref 000 Table I).
//
// A leg holds a constant nominal force phi in one mapping until the speed has settled
// (|xi - xi*| <= tol·|xi*| at every point of the a priori box, xi* the steady speed of eq. 7)
// and then for a hold window long enough to measure xi* to speed_rel_sigma (LS slope of the
// positions: σ_xi = σ·sqrt(12/(rate·T_h³)); mean of velocities: σ/sqrt(rate·T_h)).
//
// 1. Candidates: for every mapping and direction that can hold a force without reversal,
//    `levels` forces geometrically spaced from the no-reversal minimum to the largest force
//    whose run from rest still fits the pool over the box (and the thrusters can give).
// 2. Approximate design (Kiefer): weights w_c >= 0, Σ w_c <= 1, maximising the robust criterion
//    of M_j(w) = N·Σ_c w_c·M_cj + M_prior,j (M_cj: information of candidate c from rest at box
//    point j) with m a nuisance; concave in w, so Ipopt (epigraph of maximin) or NLopt SLSQP
//    find its global optimum. Analytic gradient: ∂ log det M/∂w_c = N·tr(M⁻¹ M_c).
// 3. Exact design: efficient rounding of N·w (Pukelsheim & Rieder 1992), then every direction
//    the approximate design uses keeps at least one leg.
// 4. Legs: alternately forward and backward, in mappings whose working thrusters never push
//    both ways (e.g. forward in surge-front, backward in surge-rear), chained into one trial
//    while the travel over the box stays inside the pool (a campaign fits a pool that single
//    runs would overflow); a leg that starts moving settles from its predecessor's speed.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/sine_design.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::planner {

struct SteadyDesignOptions {
  Criterion criterion = Criterion::kDs;  ///< interest: every parameter but m
  int legs = 0;                          ///< number of legs N; 0: informed parameters + 2
  int levels = 4;                        ///< candidate forces per mapping and direction
  /// Settled: |xi - xi*| <= settle_tolerance·|xi*|. CHOSEN 2%, the usual settling band.
  double settle_tolerance = 0.02;
  double min_hold_s = 10.0;  ///< CHOSEN: a few sonar samples per metre at pool speeds
  /// Hold long enough for σ(xi*)/xi* <= this. Ref 000 §III: "lower than 3%"; CHOSEN 2%.
  double speed_rel_sigma = 0.02;
  int max_legs_per_trial = 4;

  bool IsValid(std::string* error) const;
};

struct SteadyLeg {
  std::string mapping;
  double force = 0.0;     ///< phi_n (N or N·m), signed
  double settle_s = 0.0;  ///< from rest (candidates) or from the previous leg (in a trial)
  double hold_s = 0.0;
  double speed = 0.0;   ///< steady speed at the box centre
  double travel = 0.0;  ///< |travel| from rest over the check grid at settle + hold (m)
  double duration() const { return settle_s + hold_s; }
};

struct SteadyDesignResult {
  DesignStatus status = DesignStatus::kFailed;
  std::string message;
  std::vector<SteadyLeg> candidates;
  std::vector<double> weights;               ///< approximate design over the candidates
  std::vector<SteadyLeg> legs;               ///< the exact design (leg durations from rest)
  std::vector<PlannedTrial> trials;          ///< legs packed into steady / segments trials
  std::vector<TrialCheck> checks;            ///< hard constraints of each trial
  std::vector<Eigen::MatrixXd> information;  ///< Σ over trials, at each design point
  double criterion = 0.0;                    ///< robust criterion of the trials (with the prior)
  std::vector<double> criterion_per_point;
  SolverSummary summary;         ///< of the approximate design
  double required_travel = 0.0;  ///< see SteadyCandidates
  std::vector<std::string> notes;
};

/// A leg as a trial of its own: a steady run from rest of `dof` named `id`.
model::TrialDesign LegDesign(const SteadyLeg& leg, model::Dof dof, const std::string& id);

/// Step 1 alone: the candidate legs (from rest) of every mapping and direction that fits.
struct SteadyCandidates {
  std::vector<SteadyLeg> legs;
  /// The largest travel (m or rad) among the smallest runs of every direction that the
  /// thrusters allow: the free travel a pool must offer to run each direction at least once.
  double required_travel = 0.0;
  std::string infeasible;  ///< why some directions cannot be run, or empty
  std::vector<std::string> notes;
};
SteadyCandidates MakeSteadyCandidates(const DofPlanningProblem& ctx,
                                      const SteadyDesignOptions& options);

/// Designs the steady runs of ctx's DOF; trial ids are `id_prefix` + "-1", "-2", ...
SteadyDesignResult DesignSteady(const DofPlanningProblem& ctx, const SteadyDesignOptions& options,
                                const std::vector<Eigen::MatrixXd>& prior,
                                const std::string& id_prefix);

/// The approximate design problem of step 2 for candidate informations M[c][j] (absolute),
/// N legs: the same problem for either backend (tests cross-check NLopt and Ipopt on it).
DesignProblem SteadyWeightsProblem(const DofPlanningProblem& ctx,
                                   const std::vector<std::vector<Eigen::MatrixXd>>& M, int N,
                                   const std::vector<Eigen::MatrixXd>& prior, Criterion criterion);

/// Efficient rounding of an approximate design to N runs (Pukelsheim & Rieder 1992). Weights
/// below 1e-3 of the largest are not support points; without any positive weight, no runs.
std::vector<int> EfficientRounding(const std::vector<double>& weights, int N);

}  // namespace uuvplan::planner
