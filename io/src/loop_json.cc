#include "uuvplan/io/loop_json.h"

#include <cmath>
#include <limits>

#include "uuvplan/io/json_value.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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
  h->trials.push_back({index, trial.design.id, std::string(model::TrialKindName(trial.design.kind)),
                       trial.design.mapping, dof, trial.design.duration, pool_time});
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
