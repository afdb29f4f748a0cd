// The policy of the design–identify loop (design_loop.h): which DOF gets the next trial and
// which trial it is — the a priori schedule's next one, or DesignNextTrial's. Shared by
// NextStep (`uuvplan next`) and RunLoop; internal to the planner library.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/ident/identify.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/planner/loop/design_loop.h"

namespace uuvplan::planner::internal {

/// Whether the vehicle has a sensor and a mapping on `dof`.
bool Plannable(const model::Vehicle& v, model::Dof dof);
/// Throws model::InputError (at `where`) unless Plannable, saying what is missing.
void RequirePlannable(const model::Vehicle& v, model::Dof dof, const std::string& where);

/// (mapping, direction ±1) of an installation coefficient "eta.<mapping>.<pos|neg>".
std::pair<std::string, int> EtaDirection(const std::string& name);

/// State shared by the steps of one loop (or the single step of `next`): the a priori schedule
/// of each DOF, planned once.
struct Planner {
  const model::Vehicle& vehicle;
  const model::Pool& pool;
  const DesignLoopOptions& options;
  std::map<model::Dof, ScheduleResult> schedules;
  /// The trials the loop ran, by DOF (RunLoop records them): the information of a DOF's first
  /// trials about a model the vehicle file gives, before identification can use them.
  std::map<model::Dof, std::vector<PlannedTrial>> run;

  const ScheduleResult& APriori(model::Dof dof);
  /// Plans the a priori schedules of `dofs` not planned yet, on Threads() threads.
  void Prepare(const std::vector<model::Dof>& dofs);
  /// PlannerOptions::Threads of the loop's schedule options.
  int Threads() const { return options.schedule.planner.Threads(); }
};

/// Why a DOF gets no further trial: infeasible (the pool cannot host what it needs), stuck (no
/// trial adds enough information), refused (estimates no trial of this model can make right).
struct DofStop {
  model::Dof dof = model::Dof::kSurge;
  NextStatus kind = NextStatus::kStuck;
  std::string reason;
};

/// What the policy decided for the next trial (the fields of NextStepResult it fills).
struct Decision {
  NextStatus status = NextStatus::kInfeasible;
  std::string message;
  std::vector<DofProgress> progress;
  model::Dof dof = model::Dof::kSurge;
  std::string source;
  PlannedTrial trial;
  PredictedPrecision predicted;     ///< the design's: the worst over its box
  PredictedPrecision at_estimates;  ///< at the current estimates (the box's centre)
  std::vector<CandidateGain> candidates;
  std::vector<DofStop> stops;  ///< the DOFs that get no trial, and why
  std::vector<std::string> notes;
};

/// What the loop remembers between decisions: each DOF's identification before its newest
/// trial (the consistency test's reference) and the DOFs it has stopped (stuck or refused).
struct LoopMemory {
  std::map<model::Dof, ident::DofIdentification> previous;
  std::map<model::Dof, DofStop> stopped;
  /// Why a DOF's model itself is in doubt (`loop --diagnose`: the diagnosis cannot tell an
  /// effect of the model from another): its estimates are not trusted while these stand.
  std::map<model::Dof, std::vector<std::string>> model_doubts;
};

/// Adds the DOF's model doubts of `memory` to `p`: not trusted, not converged.
void AddModelDoubts(const LoopMemory& memory, DofProgress* p);

/// The next trial of `campaign` among `dofs` given its identification `estimates`: the DOF
/// furthest above the target (ties in the order of `dofs`) whose candidate trial adds
/// information (CandidateGain); DOFs that are stopped, refused or stuck are skipped with
/// their reason in `stops`.
Decision Decide(Planner& planner, const model::Campaign& campaign,
                const std::vector<model::Dof>& dofs, const ident::IdentifyResult& estimates,
                const LoopMemory& memory = {});

/// The trial the policy plans for one DOF (into `d`) and its gain; false with `why` when none.
bool PlanCandidate(Planner& planner, const model::Campaign& campaign, const DofProgress& progress,
                   const ident::DofIdentification* id, Decision* d, CandidateGain* gain,
                   std::string* why);

/// The sentence of a stuck DOF (stuck_limit.cc): its bottleneck, the candidate's gain, the
/// limit that binds (pool size, thrust range, rotation-rate limit, no reversal within a trial)
/// and what would lift it, checked by planning the DOF again with the limit relaxed.
std::string StuckReason(Planner& planner, const model::Campaign& campaign,
                        const DofProgress& progress, const ident::DofIdentification* id,
                        const PlannedTrial& trial, const CandidateGain& gain);

/// `asked`, or when it is empty every DOF the truth has parameters for (what the loop and the
/// paper procedure run on a virtual vehicle).
std::vector<model::Dof> DofsOrTruths(const model::Truth& truth,
                                     const std::vector<model::Dof>& asked);

/// Fit trials of `dof` in the campaign.
int FitTrials(const model::Campaign& campaign, model::Dof dof);

/// The trials of `dof` in `campaign` (fit and validate, in order), as a campaign of `vehicle`.
model::Campaign DofCampaign(const model::Campaign& campaign, const model::Vehicle& vehicle,
                            model::Dof dof);

}  // namespace uuvplan::planner::internal
