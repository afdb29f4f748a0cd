// The schedule as JSON (contract §schedule, §next): writing a schedule, and reading one back or
// the single trial of a `next` result, for `uuvplan simulate` and the pool team.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/io/json_value.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/planner/design/information_table.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::io {

/// One trial as the contract's JSON object: id, dof, kind, duration, mapping, the fields of
/// its kind, travel, thrust_min (and ballast_steps when non-zero).
nlohmann::json TrialToJson(const planner::PlannedTrial& trial);
nlohmann::json ScheduleToJson(const planner::Schedule& schedule);
/// `uuvplan schedule --json` (docs/cli.md): ScheduleToJson, each trial's and the schedule's
/// "information" (information_json.h), "status", "notes": [...], "not_planned": {<dof>:
/// {"message"}} for a DOF not planned whole, and the pool "verdict" (pool_verdict_json.h: the
/// needs and the required pool, with units).
nlohmann::json ScheduleResultJson(const planner::ScheduleResult& result,
                                  const planner::ScheduleInformation& information,
                                  const planner::PoolVerdict& verdict, const model::Pool& pool);
/// A plan decided without the planner (`uuvplan demo`'s): its trials without travel and
/// thrust_min, and a "note" saying so. `simulate --plan` reads it.
nlohmann::json UnplannedScheduleJson(const std::vector<planner::PlannedTrial>& trials,
                                     const std::string& note);
/// One DOF's predicted precision: {sigma: {<parameter>: σ}, criterion, value, assumption};
/// a non-finite number is written as null (what every reader reads as NaN). Used by the
/// schedule, `next` and each loop iteration alike.
nlohmann::json PredictedToJson(const planner::PredictedPrecision& predicted);
/// What the σ of a predicted-precision object without an "assumption" key rest on: such a file
/// comes from a planner that counted each trial's initial state as known, which lends a steady
/// run's start-up lag as information on m (docs/planning.md, "Initial state").
inline constexpr const char* kUnrecordedSigmaAssumption =
    "assumption not recorded in the file (written before the planner recorded it, e624b5c of "
    "2026-11-28, when it counted each trial's initial position and velocity as known): these "
    "predicted σ may be several times smaller than `identify` achieves; plan again for σ that "
    "estimate the start";

/// The "assumption" of a predicted-precision object, or kUnrecordedSigmaAssumption when the
/// file has none.
std::string PredictedAssumptionOf(const JsonValue& predicted);

/// Reads a trial object; throws model::InputError naming the file, the trial's key path (e.g.
/// "plan.json: trials[2]") and the key on any missing or ill-typed field.
planner::PlannedTrial TrialFromJson(const JsonValue& trial);
/// Reads a schedule JSON file (as written by `uuvplan schedule --json`), or a `next` result
/// (its single "trial"). Throws model::InputError on malformed input.
planner::Schedule ReadScheduleJson(const std::string& path);
/// The pool verdict `schedule` stored in its JSON ("verdict": hosted, sentence, lines).
struct StoredVerdict {
  bool hosted = false;
  std::string sentence;            ///< "Pool <name> CAN host …"
  std::vector<std::string> lines;  ///< text::VerdictLines, the sentence first
};
/// The stored verdict, or nullopt when the file has none (a `next` result, a hand-made plan).
/// Throws model::InputError when it is there but malformed.
std::optional<StoredVerdict> ReadScheduleVerdict(const std::string& path);
/// The DOFs a schedule file was planned for: those of its trials and those `schedule` could
/// not plan (its "not_planned" keys), in DOF order. Throws model::InputError as above.
std::vector<model::Dof> ScheduleDofs(const std::string& path);

}  // namespace uuvplan::io
