// `uuvplan check-pool --json` (check_pool_json.h).
#include "uuvplan/io/check_pool_json.h"

#include "uuvplan/io/pool_verdict_json.h"
#include "uuvplan/io/schedule_json.h"

namespace uuvplan::io {

nlohmann::json CheckPoolJson(const planner::PoolCheckResult& r, const planner::PoolVerdict& verdict,
                             const model::Pool& pool) {
  nlohmann::json trials = nlohmann::json::array();
  for (const auto& t : r.trials) {
    trials.push_back({{"id", t.id},
                      {"dof", std::string(model::DofName(t.dof))},
                      {"feasible", t.check.feasible},
                      {"reasons", t.check.reasons},
                      {"travel", {t.check.travel[0], t.check.travel[1]}},
                      {"travel_unit", std::string(model::PositionUnit(t.dof))},
                      {"thrust_min", t.check.thrust_min}});
  }
  nlohmann::json v = PoolVerdictJson(verdict, pool);
  nlohmann::json j = {{"feasible", verdict.hosted},
                      {"trials", trials},
                      {"required", v["required"]},
                      {"verdict", v}};
  if (r.has_alternative) {
    nlohmann::json alt = ScheduleToJson(r.alternative.schedule);
    alt["status"] = std::string(planner::PlanStatusName(r.alternative.status));
    nlohmann::json loss = nlohmann::json::object();
    for (const auto& [dof, l] : r.information_loss) loss[std::string(model::DofName(dof))] = l;
    j["fits"] = {{"schedule", alt}, {"information_loss", loss}};
  }
  return j;
}

}  // namespace uuvplan::io
