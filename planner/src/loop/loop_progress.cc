// How far a DOF is from the loop's target: its parameters of interest and their percentile
// errors (design_loop.h, EvaluateProgress).
#include <cmath>

#include "loop/loop_trust.h"
#include "loop/next_trial_policy.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/thrust_limits.h"
#include "uuvplan/planner/loop/design_loop.h"

namespace uuvplan::planner {

using model::Dof;

namespace {

// A parameter as the identification left it: estimated with a finite σ, or not (+inf error);
// an a priori fallback (held, not reliable) keeps its value and σ but counts as not estimated.
InterestParameter Interest(const model::Vehicle& vehicle, Dof dof,
                           const ident::DofIdentification* id, const std::string& name) {
  InterestParameter q;
  q.name = name;
  if (id == nullptr || id->status == ident::IdentifyStatus::kFailed) return q;
  const ident::ParameterEstimate* e = id->Param(name);
  if (e == nullptr || e->state == ident::ParameterState::kDropped) return q;
  if (!(std::isfinite(e->value) && e->value != 0.0)) return q;
  q.value = e->value;
  q.sigma = e->sigma;
  q.flag = NonPhysical(vehicle, dof, name, e->value);
  q.physical = q.flag.empty();
  if (internal::Held(*id, name) || !std::isfinite(e->sigma)) {
    q.held = true;
    q.flag = (q.flag.empty() ? "" : q.flag + "; ") +
             (e->state == ident::ParameterState::kFixed
                  ? "held at its a priori value: no information"
                  : "not reliable (conditional on parameters held at their a priori values): "
                    "no information");
    return q;
  }
  q.estimated = true;
  q.percent = 100.0 * e->sigma / std::abs(e->value);
  return q;
}

// "m, k (or kq where significant) and every η" — every η of the DOF's
// mappings in a direction the thrusters can hold (the planner's model).
std::vector<InterestParameter> InterestParameters(const model::Vehicle& vehicle, Dof dof,
                                                  const ident::DofIdentification* id) {
  auto interest = [&](const std::string& n) { return Interest(vehicle, dof, id, n); };
  std::vector<InterestParameter> out = {interest(model::param::kMass)};
  const InterestParameter kq = interest(model::param::kQuadraticDrag);
  const ident::ParameterEstimate* kq_est = id ? id->Param(model::param::kQuadraticDrag) : nullptr;
  const bool kq_significant = kq.estimated && kq.percent < kInsignificantPercent &&
                              (kq_est == nullptr || kq_est->significant);
  out.push_back(kq_significant ? kq : interest(model::param::kLinearDrag));
  std::vector<std::string> mappings;
  for (int i : vehicle.MappingsOf(dof)) mappings.push_back(vehicle.mappings[i].name);
  const model::DofModel full(vehicle,
                             model::ModelStructure::Standard(vehicle, dof, mappings, false));
  for (const auto& n : full.parameter_names()) {
    if (!model::StartsWith(n, model::param::kEtaPrefix)) continue;
    const auto [mapping, sign] = internal::EtaDirection(n);
    const int mi = vehicle.MappingIndex(mapping);
    if (mi >= 0 && !DirectionForceRange(vehicle, mi, sign).feasible) continue;
    out.push_back(interest(n));
  }
  return out;
}

// Why the DOF's estimates are not trusted yet, and whether more trials of this
// model can change that (the refusal: precise and consistent, yet non-physical or invalid).
void JudgeTrust(const ident::DofIdentification* id, const ident::DofIdentification* previous,
                const DesignLoopOptions& options, DofProgress* p) {
  if (id == nullptr) return;
  std::vector<std::string> wrong;  // what more trials of this model would not fix
  for (const auto& q : p->interest) {
    if (!q.physical) wrong.push_back(q.flag);
    if (q.held) p->doubts.push_back(q.name + ": " + q.flag);
  }
  for (const auto& v : internal::ValidationDoubts(*id, options.max_residual_lag1)) {
    wrong.push_back(v);
  }
  if (previous != nullptr) {
    p->consistency = internal::TestConsistency(*previous, *id, options.consistency_level);
  }
  if (!p->consistency.tested) {
    p->doubts.push_back(previous == nullptr
                            ? "not confirmed: one estimate so far (one more trial confirms or "
                              "refutes it)"
                            : "not confirmed: " + p->consistency.text);
  } else if (!p->consistency.consistent) {
    p->doubts.push_back(p->consistency.text);
  }
  p->doubts.insert(p->doubts.end(), wrong.begin(), wrong.end());
  p->trusted = p->doubts.empty();
  if (p->precise && p->consistency.consistent && !wrong.empty()) {
    p->refusal = wrong.front() + " with every parameter of interest below " +
                 model::Significant(options.target_percent, 3) +
                 "% and consistent across trials: more trials of this model will not change it "
                 "(the model misses an effect: try `uuvplan diagnose`)";
  }
}

}  // namespace

DofProgress EvaluateProgress(const model::Vehicle& vehicle, Dof dof,
                             const ident::DofIdentification* id, int trials,
                             const DesignLoopOptions& options,
                             const ident::DofIdentification* previous) {
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
  p.precise = p.worst_percent <= options.target_percent;
  p.usable = p.interest[0].percent < options.usable_percent &&
             p.interest[1].percent < options.usable_percent;
  JudgeTrust(id, previous, options, &p);
  p.converged = p.precise && p.trusted;
  return p;
}

}  // namespace uuvplan::planner
