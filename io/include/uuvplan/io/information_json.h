// The information a schedule carries as JSON (planner/design/information_table.h), SI units:
//   {"parameters": [names], "units": [unit per parameter], "theta": [...],
//    "fisher": [[...]] (entry i, j in 1/(unit_i·unit_j)),
//    "criteria": {"D", "A", "E", "singular"} (relative information, natural log),
//    "sigma": {name: σ or null when no trial reaches it}, "condition_number": c or null}
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/planner/design/information_table.h"

namespace uuvplan::io {

nlohmann::json InformationJson(const planner::InformationSummary& s);

/// Adds "information" to every trial of `schedule_json` (a ScheduleToJson object, same trial
/// order) and {"point", "dofs": {<dof>: ...}} as its top-level "information".
void AddInformationJson(const planner::ScheduleInformation& info, nlohmann::json* schedule_json);

}  // namespace uuvplan::io
