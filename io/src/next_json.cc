// `uuvplan next --json` (next_json.h).
#include "uuvplan/io/next_json.h"

#include "uuvplan/io/identify_json.h"
#include "uuvplan/io/loop_json.h"
#include "uuvplan/io/pool_verdict_json.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::io {

nlohmann::json NextStepJson(const planner::NextStepResult& r, double target,
                            const planner::PoolVerdict& verdict, const model::Pool& pool,
                            int exit_status, bool pool_refuses) {
  const bool planned = r.status == planner::NextStatus::kTrial;
  nlohmann::json j;
  j["estimates"] = IdentifyJson(r.estimates);
  j["trial"] = planned ? TrialToJson(r.trial) : nlohmann::json(nullptr);
  j["predicted"] = planned ? PredictedJson(r.dof, r.predicted) : nlohmann::json::object();
  j["status"] = std::string(planner::NextStatusName(r.status));
  j["message"] = r.message;
  j["source"] = r.source;
  j["target"] = target;
  j["progress"] = ProgressJson(r.progress);
  j["candidates"] = CandidatesJson(r.candidates);
  j["exit_status"] = exit_status;
  j["notes"] = r.notes;
  j["verdict"] = PoolVerdictJson(verdict, pool);
  if (pool_refuses) {
    j["status"] = std::string(planner::NextStatusName(planner::NextStatus::kInfeasible));
    const bool stuck = r.status == planner::NextStatus::kStuck && !r.message.empty();
    j["message"] =
        text::VerdictSentence(verdict, pool) + (stuck ? "; " + r.message : std::string());
  }
  return j;
}

}  // namespace uuvplan::io
