// `uuvplan report`'s content: from what is known (a vehicle, a pool, a schedule, an
// identification, a diagnosis, a loop history) the sections and figures that apply, as the
// files of the report directory — report.html (figures embedded) and figures/<name>.png|svg.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/io/loop_json.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/report/diagnosis_figures.h"

namespace uuvplan::report {

struct ReportInputs {
  std::string title;
  std::string source;  ///< what the report is of (the input's path)
  std::optional<model::Vehicle> vehicle;
  std::string vehicle_source;
  std::optional<model::Pool> pool;
  std::string pool_source;
  std::optional<planner::Schedule> schedule;  ///< needs vehicle and pool for its figures
  /// The pool verdict on the schedule (text::VerdictLines, the sentence first) and where it
  /// comes from.
  struct Verdict {
    bool hosted = false;
    std::vector<std::string> lines;
    std::string source;
  };
  std::optional<Verdict> verdict;
  planner::PlannerOptions planner;                      ///< the box the schedule's figures simulate
  std::optional<ident::IdentifyResult> identification;  ///< with free-run curves
  std::optional<ident::DiagnosisResult> diagnosis;
  std::vector<BeforeAfter> before_after;  ///< per DOF diagnosed
  std::optional<io::LoopHistory> loop;
};

struct ReportFiles {
  std::map<std::string, std::string> files;  ///< relative path → bytes
  int figures = 0;
  std::vector<std::string> notes;
};

/// Builds every section and figure the inputs allow. Throws std::runtime_error when a figure
/// cannot be drawn (render.h).
ReportFiles BuildReport(const ReportInputs& inputs);

}  // namespace uuvplan::report
