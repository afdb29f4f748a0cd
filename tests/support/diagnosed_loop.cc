#include "support/diagnosed_loop.h"

#include <cmath>
#include <sstream>

#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/thrust_reference.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::testing {
namespace {

std::set<std::string> FinalEffects(const planner::LoopResult& r) {
  std::set<std::string> effects;
  for (const auto& it : r.iterations) {
    for (const auto& e : it.effects_entered) effects.insert(e.effect);
    for (const auto& e : it.effects_left) effects.erase(e);
  }
  return effects;
}

std::vector<ParameterCheck> Checks(model::Truth truth, model::Dof dof,
                                   const ident::DofIdentification& id) {
  const double ref = id.structure.Setting(model::param::kThrustReference, 0.0);
  if (ref > 0) model::RestateThrustReference(ref, &truth.dofs.at(dof));
  std::vector<ParameterCheck> out;
  for (const auto& e : id.params) {
    if (e.state != ident::ParameterState::kEstimated) continue;
    out.push_back({e.name, e.value, e.sigma, ident::TrueParameter(truth, dof, e.name)});
  }
  return out;
}

}  // namespace

model::Truth WithLagAndThrustMap(model::Truth truth, model::Dof dof, double lag, double exponent,
                                 double reference) {
  model::DofTruth& t = truth.dofs.at(dof);
  t.params[model::param::kLag] = lag;
  t.params[model::param::kThrustExponent] = exponent;
  t.settings[model::param::kThrustReference] = reference;
  return truth;
}

bool DiagnosedLoopOutcome::Pass(const std::set<std::string>& expected) const {
  if (!result.converged || effects != expected || params.empty()) return false;
  for (const auto& p : params) {
    if (!(std::abs(p.Sigmas()) <= 3.0)) return false;
  }
  return true;
}

std::string DiagnosedLoopOutcome::Line() const {
  std::ostringstream s;
  s << planner::LoopStatusName(result.status) << " after " << result.iterations.size()
    << " trials; effects {" << model::Join(effects, ", ") << "}";
  const ParameterCheck* worst = nullptr;
  for (const auto& p : params) {
    if (worst == nullptr || !(std::abs(p.Sigmas()) <= std::abs(worst->Sigmas()))) worst = &p;
  }
  if (worst != nullptr) {
    s << "; worst " << worst->name << " " << model::Significant(worst->value, 4) << " ± "
      << model::Significant(worst->sigma, 2) << " (truth " << model::Significant(worst->truth, 4)
      << ", " << model::Significant(worst->Sigmas(), 2) << "σ)";
  }
  return s.str();
}

DiagnosedLoopOutcome RunDiagnosedLoop(const model::Truth& truth, const model::Pool& pool,
                                      model::Dof dof, std::uint64_t seed) {
  planner::LoopOptions o;
  o.step.dofs = {dof};
  o.seed = seed;
  o.diagnose.emplace();
  DiagnosedLoopOutcome out;
  out.result = planner::RunLoop(truth, pool, o);
  out.effects = FinalEffects(out.result);
  if (const ident::DofIdentification* id = out.result.estimates.Find(dof)) {
    out.params = Checks(truth, dof, *id);
  }
  return out;
}

}  // namespace uuvplan::testing
