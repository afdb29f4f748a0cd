// Scoring a given parameter set on a campaign: the free-run simulation of each trial with the
// model's parameters (no fit), scored by the velocity MAE of ref 002 eq. 37 and the position
// RMS (validation.h). Two models of the same vehicle are compared on the same data by their
// scores; `diagnose` measures its held-out gains with the same pooled MAE, so `uuvplan score`
// on a vehicle written by `diagnose --write-vehicle` reproduces them.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/validation.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::ident {

/// The parameters of an identification as a model of its DOF: every parameter of its θ
/// layout with its value, σ (0 for a parameter held, not estimated) and the structure's
/// settings — what `diagnose --write-vehicle` writes into the vehicle file.
model::DofTruth ModelOf(const struct DofIdentification& identification);

/// "" when every parameter of `model` lies in its family's admissible range (a file reader
/// would accept it), else the first that does not, e.g. "k = -0.31 (expected a number >= 0)".
std::string Inadmissible(const model::DofParameters& model);

/// `vehicle` with the model of each DOF `result` identified (ModelOf), as the file `identify
/// --write-vehicle` writes it: the planner's box of such a DOF is then the estimates'
/// (planner/design/parameter_box.h, PlanningBox). A DOF that failed or whose model is
/// inadmissible keeps what `vehicle` had.
model::Vehicle WithIdentifiedModels(model::Vehicle vehicle, const struct IdentifyResult& result);

/// Velocity MAE of the free runs of `trials` pooled over their samples (trials without a
/// velocity sample add nothing). NaN, with the reason in `why`, when a free run cannot be
/// simulated or no sample is left; `samples` (optional) receives the number pooled.
double PooledVelocityMae(const model::DofModel& model, const Eigen::VectorXd& theta,
                         const std::vector<const TrialData*>& trials, double step_s,
                         std::string* why, int* samples = nullptr);

struct ScoreOptions {
  TrialDataOptions data;         ///< trial preparation, as identify's and diagnose's default
  double step_s = 0.02;          ///< RK4 step of the free runs (OutputErrorOptions::step_s)
  std::vector<model::Dof> dofs;  ///< DOFs to score; empty: every DOF the model gives
  int curve_points = 0;  ///< keep each free run for figures (ValidationOptions::curve_points)
  bool IsValid(std::string* error) const;
};

/// One DOF's pooled scores (NaN when it has no trial of that use, or one cannot be simulated).
struct DofScore {
  model::Dof dof = model::Dof::kSurge;
  double velocity_mae_fit = 0.0, velocity_mae_validate = 0.0, velocity_mae_all = 0.0;
  int samples_fit = 0, samples_validate = 0;
  std::string problem;  ///< why a pooled score is NaN (empty when all are numbers)
};

struct TrialScore {
  model::Dof dof = model::Dof::kSurge;
  TrialFit fit;  ///< the free run's scores (validation.h)
};

/// What a ScoreNote says.
enum class ScoreNoteKind {
  kNoModelForDof,  ///< the trial's DOF has no dofs.<dof>.params in the model scored
};

inline constexpr model::EnumNames<ScoreNoteKind, 1> kScoreNoteKindNames{{{
    {ScoreNoteKind::kNoModelForDof, "no_model_for_dof"},
}}};

/// A remark on the scoring (text/score_notes_text.h words it).
struct ScoreNote {
  ScoreNoteKind kind = ScoreNoteKind::kNoModelForDof;
  std::string trial;  ///< the trial's file
  model::Dof dof = model::Dof::kSurge;
};

struct ScoreResult {
  std::vector<TrialScore> trials;  ///< campaign order, trials of the scored DOFs
  std::vector<DofScore> dofs;
  std::vector<ScoreNote> notes;  ///< trials skipped (no model for their DOF)
};

/// Scores `given` (a vehicle with dofs.<dof>.params and effects, model/truth.h) on every trial
/// of `campaign` whose DOF it gives. Throws model::InputError for unusable input.
ScoreResult ScoreCampaign(const model::Campaign& campaign, const model::Truth& given,
                          const ScoreOptions& options);

}  // namespace uuvplan::ident
