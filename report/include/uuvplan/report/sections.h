// The report's sections, each a function of what it reports on, every table with its units
// (the parameters' from the vocabulary, model/parameter.h; numbers to 4 significant digits).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/io/loop_json.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/report/html.h"

namespace uuvplan::report {

/// A number as the report prints it: 4 significant digits, "—" when not finite.
std::string Number(double x);

Section VehicleSection(const model::Vehicle& vehicle, const std::string& source);
Section PoolSection(const model::Pool& pool, const std::string& source);
/// `verdict_lines`: the pool verdict on the schedule (VerdictLines), first; none when not judged.
Section ScheduleSection(const planner::Schedule& schedule,
                        const std::vector<std::string>& verdict_lines);
Section EstimatesSection(const ident::IdentifyResult& result);
Section ValidationSection(const ident::IdentifyResult& result);
Section DiagnosisSection(const ident::DiagnosisResult& diagnosis);
Section LoopSection(const io::LoopHistory& history);
/// The verdicts first, so the first screen answers: schedule size and the pool's verdict on it,
/// each DOF's identification status, the effects found, the loop's outcome (whichever are given).
Section SummarySection(const planner::Schedule* schedule, const std::string* verdict_sentence,
                       const ident::IdentifyResult* identification,
                       const ident::DiagnosisResult* diagnosis, const io::LoopHistory* loop);

}  // namespace uuvplan::report
