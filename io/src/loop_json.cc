// The loop's JSON (loop_json.h).
#include "uuvplan/io/loop_json.h"

#include <cmath>
#include <limits>

#include "uuvplan/io/diagnosis_json.h"
#include "uuvplan/io/identify_json.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/io/pool_verdict_json.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/numbers.h"
#include "uuvplan/text/loop_text.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::io {

using nlohmann::json;

// ---------------------------------------------------------------------------------------------
// Writing.

json CandidatesJson(const std::vector<planner::CandidateGain>& candidates) {
  json j = json::array();
  for (const auto& c : candidates) {
    j.push_back({{"dof", std::string(model::DofName(c.dof))},
                 {"trial", c.trial},
                 {"parameter", c.parameter},
                 {"sigma_now", JsonNumber(c.sigma_now)},
                 {"sigma_after", JsonNumber(c.sigma_after)},
                 {"gain", JsonNumber(c.gain)},
                 {"trials_to_target", JsonNumber(c.trials_to_target)},
                 {"first_estimate", c.first_estimate},
                 {"negligible", c.negligible}});
  }
  return j;
}

json ProgressJson(const std::vector<planner::DofProgress>& progress) {
  json j = json::object();
  for (const auto& p : progress) {
    json interest = json::object();
    for (const auto& q : p.interest) {
      interest[q.name] = std::isfinite(q.value) ? json{{"value", JsonNumber(q.value)},
                                                       {"sigma", JsonNumber(q.sigma)},
                                                       {"percent", JsonNumber(q.percent)},
                                                       {"unit", model::Unit(q.name, p.dof)},
                                                       {"held", q.held},
                                                       {"physical", q.physical},
                                                       {"flag", q.flag}}
                                                : json(nullptr);
    }
    json consistency = nullptr;
    if (p.consistency.tested) {
      consistency = {{"chi2", JsonNumber(p.consistency.chi2)},
                     {"dof", p.consistency.dof},
                     {"p_value", JsonNumber(p.consistency.p_value)},
                     {"level", p.consistency.level},
                     {"consistent", p.consistency.consistent},
                     {"worst", p.consistency.worst},
                     {"worst_sigmas", JsonNumber(p.consistency.worst_sigmas)}};
    }
    j[std::string(model::DofName(p.dof))] = {{"converged", p.converged},
                                             {"worst", p.worst},
                                             {"worst_percent", JsonNumber(p.worst_percent)},
                                             {"trials", p.trials},
                                             {"usable", p.usable},
                                             {"status", p.status},
                                             {"precise", p.precise},
                                             {"trusted", p.trusted},
                                             {"doubts", p.doubts},
                                             {"refusal", p.refusal},
                                             {"consistency", consistency},
                                             {"interest", interest}};
  }
  return j;
}

json PredictedJson(model::Dof dof, const planner::PredictedPrecision& p) {
  return {{std::string(model::DofName(dof)), PredictedToJson(p)}};
}

namespace {

json SigmaJson(const planner::LoopIteration& it) {
  json j = json::object();
  for (const auto& [name, pa] : it.sigma) {
    j[name] = {{"predicted", JsonNumber(pa[0])},
               {"achieved", JsonNumber(pa[1])},
               {"unit", model::Unit(name, it.dof)}};
  }
  return j;
}

json EffectsEnteredJson(const planner::LoopIteration& it) {
  json j = json::array();
  for (const auto& e : it.effects_entered) {
    json params = json::object();
    for (const auto& p : e.params) {
      params[p.name] = {{"value", JsonNumber(p.value)},
                        {"sigma", JsonNumber(p.sigma)},
                        {"unit", model::Unit(p.name, it.dof)}};
    }
    j.push_back({{"effect", e.effect},
                 {"detail", e.detail},
                 {"params", params},
                 {"gain", GainJson(e.gain)}});
  }
  return j;
}

json IterationJson(const planner::LoopIteration& it) {
  json params = json::object();
  for (const auto& [dof, estimates] : it.params) {
    json p = json::object();
    for (const auto& e : estimates)
      p[e.name] = {{"value", JsonNumber(e.value)}, {"sigma", JsonNumber(e.sigma)}};
    params[std::string(model::DofName(dof))] = p;
  }
  return {{"trial", TrialToJson(it.trial)},
          {"params", params},
          {"dof", std::string(model::DofName(it.dof))},
          {"source", it.source},
          {"start", it.start},
          {"pool_time", it.pool_time},
          {"predicted", PredictedJson(it.dof, it.predicted)},
          {"sigma", SigmaJson(it)},
          {"candidates", CandidatesJson(it.candidates)},
          {"new_information", it.new_information},
          {"effects_entered", EffectsEnteredJson(it)},
          {"effects_left", it.effects_left},
          {"progress", ProgressJson(it.progress)},
          {"notes", it.notes}};
}

}  // namespace

json LoopResultJson(const planner::LoopResult& r, const planner::LoopOptions& lo,
                    const planner::PoolVerdict& verdict, const model::Pool& pool, int exit_status) {
  json iterations = json::array();
  for (const auto& it : r.iterations) iterations.push_back(IterationJson(it));
  json dof_time = json::object();
  for (const auto& [dof, t] : r.dof_pool_time) dof_time[std::string(model::DofName(dof))] = t;
  return {{"iterations", iterations},
          {"converged", r.converged},
          {"pool_time", r.pool_time},
          {"status", std::string(planner::LoopStatusName(r.status))},
          {"exit_status", exit_status},
          {"message", text::LoopEndMessage(r, verdict, pool)},
          {"target", lo.step.target_percent},
          {"budget", lo.budget},
          {"seed", lo.seed},
          {"diagnose", lo.diagnose.has_value()},
          {"diagnose_assumption",
           lo.diagnose ? json(std::string(text::DiagnosedModelAssumption())) : json(nullptr)},
          {"dof_pool_time", dof_time},
          {"progress", ProgressJson(r.progress)},
          {"estimates", IdentifyJson(r.estimates)},
          {"verdict", PoolVerdictJson(verdict, pool)}};
}

json RefusedLoopJson(const planner::PoolVerdict& verdict, const model::Pool& pool,
                     int exit_status) {
  return {{"iterations", json::array()},
          {"converged", false},
          {"status", std::string(planner::LoopStatusName(planner::LoopStatus::kInfeasible))},
          {"exit_status", exit_status},
          {"message", text::VerdictSentence(verdict, pool)},
          {"verdict", PoolVerdictJson(verdict, pool)}};
}

// ---------------------------------------------------------------------------------------------
// Reading.

namespace {

using model::kNaN;

model::Dof DofKey(const JsonValue& at, const std::string& name) {
  const auto dof = model::ParseDof(name);
  if (!dof) at.Expected("a DOF name (surge sway heave roll pitch yaw)");
  return *dof;
}

// iterations[i].sigma.<name>.predicted, or NaN.
double PredictedSigma(const JsonValue& it, const std::string& name) {
  const auto sigma = it.Optional("sigma");
  if (!sigma) return kNaN;
  const auto entry = sigma->Optional(name);
  if (!entry) return kNaN;
  const auto predicted = entry->Optional("predicted");
  return predicted ? NumberOrNaN(*predicted) : kNaN;
}

void ReadIteration(const JsonValue& it, int index, LoopHistory* h) {
  const planner::PlannedTrial trial = TrialFromJson(it.Required("trial", "the trial run"));
  const model::Dof dof = DofKey(it.Required("dof"), String(it.Required("dof"), "a DOF name"));
  const double pool_time = NonNegativeNumber(it.Required("pool_time"), "a number >= 0 (s)");
  h->trials.push_back({index,
                       trial.design.id,
                       std::string(model::TrialKindName(trial.design.kind)),
                       trial.design.mapping,
                       dof,
                       trial.design.duration,
                       pool_time,
                       {},
                       {}});
  if (const auto entered = it.Optional("effects_entered")) {
    if (!entered->json().is_array()) entered->Expected("an array of effects");
    for (std::size_t i = 0; i < entered->json().size(); ++i) {
      const JsonValue e = entered->Item(i);
      h->trials.back().effects_entered.push_back(String(e.Required("effect"), "an effect name"));
    }
  }
  if (const auto left = it.Optional("effects_left")) {
    if (!left->json().is_array()) left->Expected("an array of effect names");
    for (std::size_t i = 0; i < left->json().size(); ++i) {
      h->trials.back().effects_left.push_back(String(left->Item(i), "an effect name"));
    }
  }
  const JsonValue params = it.Required("params", "the estimates after the trial");
  if (!params.json().is_object()) params.Expected("an object of DOFs");
  for (const auto& [dof_name, p] : params.json().items()) {
    const JsonValue dv(p, params.file(), params.KeyPath(dof_name));
    const model::Dof d = DofKey(dv, dof_name);
    if (!p.is_object()) dv.Expected("an object of parameters");
    for (const auto& [name, e] : p.items()) {
      const JsonValue ev(e, dv.file(), dv.KeyPath(name));
      LoopPoint point{index, pool_time, NumberOrNaN(ev.Required("value")),
                      NumberOrNaN(ev.Required("sigma")),
                      d == dof ? PredictedSigma(it, name) : kNaN};
      h->series[d][name].push_back(point);
    }
  }
  if (const auto predicted = it.Optional("predicted")) {
    if (const auto entry = predicted->Optional(std::string(model::DofName(dof)))) {
      h->predicted_assumption = PredictedAssumptionOf(*entry);
    }
  }
}

}  // namespace

bool IsLoopJson(const std::string& path) {
  const nlohmann::json j = LoadJson(path);
  return j.is_object() && j.contains("iterations");
}

LoopHistory ReadLoopJson(const std::string& path) {
  const nlohmann::json j = LoadJson(path);
  const JsonValue root(j, path, "");
  LoopHistory h;
  h.path = path;
  const JsonValue iterations = root.Required("iterations", "the loop's trials");
  if (!iterations.json().is_array()) iterations.Expected("an array");
  for (std::size_t i = 0; i < iterations.json().size(); ++i) {
    ReadIteration(iterations.Item(i), static_cast<int>(i) + 1, &h);
  }
  if (const auto s = root.Optional("status")) h.status = String(*s, "a status");
  if (const auto m = root.Optional("message"))
    h.message = m->json().is_string() ? m->json().get<std::string>() : "";
  if (const auto t = root.Optional("target")) h.target_percent = PositiveNumber(*t, "%");
  if (const auto p = root.Optional("pool_time"))
    h.pool_time = NonNegativeNumber(*p, "a number >= 0 (s)");
  return h;
}

}  // namespace uuvplan::io
