// How far a DOF is from the loop's target: its parameters of interest and their percentile
// errors (design_loop.h, EvaluateProgress).
#include <cmath>

#include "next_trial_policy.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design_loop.h"
#include "uuvplan/planner/thrust_limits.h"

namespace uuvplan::planner {

using model::Dof;

namespace {

// A parameter as the identification left it: estimated with a finite σ, or not (+inf error).
InterestParameter Interest(const ident::DofIdentification* id, const std::string& name) {
  InterestParameter q;
  q.name = name;
  if (id == nullptr || id->status == ident::IdentifyStatus::kFailed) return q;
  const ident::ParameterEstimate* e = id->Param(name);
  if (e == nullptr || e->state != ident::ParameterState::kEstimated) return q;
  if (!(std::isfinite(e->sigma) && std::isfinite(e->value) && e->value != 0.0)) return q;
  q.estimated = true;
  q.value = e->value;
  q.sigma = e->sigma;
  q.percent = 100.0 * e->sigma / std::abs(e->value);
  return q;
}

// Contract issue #5: "m, k (or kq where significant) and every η" — every η of the DOF's
// mappings in a direction the thrusters can hold (the planner's model).
std::vector<InterestParameter> InterestParameters(const model::Vehicle& vehicle, Dof dof,
                                                  const ident::DofIdentification* id) {
  std::vector<InterestParameter> out = {Interest(id, model::param::kMass)};
  const InterestParameter kq = Interest(id, model::param::kQuadraticDrag);
  const ident::ParameterEstimate* kq_est = id ? id->Param(model::param::kQuadraticDrag) : nullptr;
  const bool kq_significant = kq.estimated && kq.percent < kInsignificantPercent &&
                              (kq_est == nullptr || kq_est->significant);
  out.push_back(kq_significant ? kq : Interest(id, model::param::kLinearDrag));
  std::vector<std::string> mappings;
  for (int i : vehicle.MappingsOf(dof)) mappings.push_back(vehicle.mappings[i].name);
  const model::DofModel full(vehicle,
                             model::ModelStructure::Standard(vehicle, dof, mappings, false));
  for (const auto& n : full.parameter_names()) {
    if (!model::StartsWith(n, model::param::kEtaPrefix)) continue;
    const auto [mapping, sign] = internal::EtaDirection(n);
    const int mi = vehicle.MappingIndex(mapping);
    if (mi >= 0 && !DirectionForceRange(vehicle, mi, sign).feasible) continue;
    out.push_back(Interest(id, n));
  }
  return out;
}

}  // namespace

DofProgress EvaluateProgress(const model::Vehicle& vehicle, Dof dof,
                             const ident::DofIdentification* id, int trials,
                             const DesignLoopOptions& options) {
  DofProgress p;
  p.dof = dof;
  p.trials = trials;
  p.status = id == nullptr ? "no trial"
                           : std::string(ident::IdentifyStatusName(id->status)) +
                                 (id->message.empty() ? "" : ": " + id->message);
  p.interest = InterestParameters(vehicle, dof, id);
  p.worst_percent = 0.0;
  for (const auto& q : p.interest) {
    if (q.percent > p.worst_percent || p.worst.empty()) {
      p.worst_percent = q.percent;
      p.worst = q.name;
    }
  }
  p.converged = p.worst_percent <= options.target_percent;
  p.usable = p.interest[0].percent < options.usable_percent &&
             p.interest[1].percent < options.usable_percent;
  return p;
}

}  // namespace uuvplan::planner
