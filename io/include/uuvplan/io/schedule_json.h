// The schedule as JSON (contract §schedule, §next): writing a schedule, and reading one back or
// the single trial of a `next` result, for `uuvplan simulate` and the pool team.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/io/json_value.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::io {

/// One trial as the contract's JSON object: id, dof, kind, duration, mapping, the fields of
/// its kind, travel, thrust_min (and ballast_steps when non-zero).
nlohmann::json TrialToJson(const planner::PlannedTrial& trial);
nlohmann::json ScheduleToJson(const planner::Schedule& schedule);
/// One DOF's predicted precision: {sigma: {<parameter>: σ}, criterion, value, assumption};
/// a non-finite number is written as null (what every reader reads as NaN). Used by the
/// schedule, `next` and each loop iteration alike.
nlohmann::json PredictedToJson(const planner::PredictedPrecision& predicted);
/// The "assumption" of a predicted-precision object, or planner::kUnrecordedSigmaAssumption
/// when the file was written before it was recorded.
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
  std::vector<std::string> lines;  ///< planner::VerdictLines, the sentence first
};
/// The stored verdict, or nullopt when the file has none (a `next` result, a hand-made plan).
/// Throws model::InputError when it is there but malformed.
std::optional<StoredVerdict> ReadScheduleVerdict(const std::string& path);
/// The DOFs a schedule file was planned for: those of its trials and those `schedule` could
/// not plan (its "not_planned" keys), in DOF order. Throws model::InputError as above.
std::vector<model::Dof> ScheduleDofs(const std::string& path);

}  // namespace uuvplan::io
