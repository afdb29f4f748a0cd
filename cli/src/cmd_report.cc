// `uuvplan report INPUT -o DIR [--vehicle V] [--pool P] [--loop LOOP.json] [--no-diagnosis
// [--method M [--forgetting λ]]] [--sg-window N] [--accept-units]`: one self-contained HTML file
// (figures embedded, no network) and the figures as PNG and SVG files (planner/report,
// docs/report.md). INPUT is a schedule (`schedule --json`, with --vehicle and --pool), a loop's
// JSON (`loop
// --json`), or a campaign (identified and diagnosed here; with --method rls also the RLS
// convergence, ref 004 Fig. 11). DIR is written whole or not at all. Exit status: 0 written;
// 1 written, but a DOF could not be identified or diagnosed, or the pool cannot host a
// schedule's DOF, as `identify`, `diagnose` or `schedule` would say; 2 bad input.
#include <filesystem>
#include <iostream>
#include <string>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/filter_window_flag.h"
#include "uuvplan/cli/method_flags.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/loop_json.h"
#include "uuvplan/io/new_directory.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/report/report.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::cli {
namespace {

using model::InputError;

struct ReportFlags {
  std::string input;
  std::string out;
  std::string vehicle;
  std::string pool;
  std::string loop;
  bool no_diagnosis = false;
  MethodFlags method;            ///< --method, --forgetting (with --no-diagnosis)
  ident::TrialDataOptions data;  ///< --sg-window (a campaign)
  bool accept_units = false;
};

// Samples kept per free run for the figures: finer than a 1100 px wide panel shows.
constexpr int kCurvePoints = 800;

bool IsJsonFile(const std::string& path) {
  return std::filesystem::path(path).extension() == ".json" &&
         std::filesystem::is_regular_file(path);
}

void AddVehicleAndPool(const ReportFlags& o, report::ReportInputs* in) {
  if (!o.vehicle.empty()) {
    in->vehicle = io::ReadVehicle(o.vehicle);
    in->vehicle_source = o.vehicle;
  }
  if (!o.pool.empty()) {
    in->pool = io::ReadPool(o.pool);
    in->pool_source = o.pool;
  }
}

void AddSchedule(const ReportFlags& o, report::ReportInputs* in) {
  if (o.vehicle.empty() || o.pool.empty()) {
    throw InputError(o.input,
                     "a schedule names neither its vehicle nor its pool: expected "
                     "--vehicle VEHICLE.yaml and --pool POOL.yaml (those given to `schedule`)");
  }
  in->title = "Schedule report";
  in->schedule = io::ReadScheduleJson(o.input);
  // The verdict `schedule` stored with the file (its --target, --max-duration and DOFs), when
  // it is this pool's; else judged here as check-pool would judge the file.
  const auto stored = io::ReadScheduleVerdict(o.input);
  if (stored && stored->sentence.rfind("Pool " + in->pool->name + " ", 0) == 0) {
    in->verdict = {stored->hosted, stored->lines,
                   "the verdict `schedule` gave when it planned this file"};
    return;
  }
  planner::ScheduleOptions so;
  so.dofs = io::ScheduleDofs(o.input);
  const planner::PoolVerdict v = planner::JudgePool(*in->vehicle, *in->pool, so, &*in->schedule);
  in->verdict = {v.hosted, text::VerdictLines(v, *in->pool),
                 "judged here as `check-pool VEHICLE --pool POOL --plan SCHEDULE --dof <its DOFs>` "
                 "would, with the default target and longest trial: the file holds no verdict "
                 "for pool '" +
                     in->pool->name + "'"};
}

// The free runs of the standard and the extended model of each diagnosed DOF, on the trials
// prepared as the diagnosis prepared them (`data`).
void AddBeforeAfter(const model::Campaign& campaign, const ident::TrialDataOptions& data,
                    report::ReportInputs* in) {
  for (const ident::DofIdentification& ext : in->diagnosis->extended) {
    const ident::DofIdentification* std_model = nullptr;
    for (const auto& s : in->diagnosis->standard) {
      if (s.dof == ext.dof) std_model = &s;
    }
    if (!std_model) continue;
    ident::ScoreOptions so;
    so.data = data;
    so.dofs = {ext.dof};
    so.curve_points = kCurvePoints;
    report::BeforeAfter ba;
    ba.dof = ext.dof;
    model::Truth given{campaign.vehicle, {{ext.dof, ident::ModelOf(*std_model)}}, {}, 0.01};
    ba.before = ident::ScoreCampaign(campaign, given, so);
    given.dofs[ext.dof] = ident::ModelOf(ext);
    ba.after = ident::ScoreCampaign(campaign, given, so);
    in->before_after.push_back(std::move(ba));
  }
}

void AddCampaign(const ReportFlags& o, report::ReportInputs* in) {
  const model::Campaign campaign = ReadCampaignForIdentification(o.input, o.accept_units);
  in->title = "Campaign report: " + campaign.vehicle.name;
  if (!in->vehicle) in->vehicle = campaign.vehicle, in->vehicle_source = campaign.path;
  if (!in->pool && campaign.pool) in->pool = *campaign.pool, in->pool_source = campaign.path;
  ident::IdentifyOptions identify;
  identify.data = o.data;
  identify.validation.curve_points = kCurvePoints;
  ApplyMethodFlags(o.method, &identify);
  if (identify.method != ident::Method::kChain && !o.no_diagnosis) {
    throw InputError("--method " + o.method.method,
                     "the diagnosis identifies with the default chain; give --no-diagnosis to "
                     "report the estimates of method " +
                         o.method.method);
  }
  // The estimates are `identify`'s (one campaign, one answer); the diagnosis's standard model
  // (every η = 1: the contract's baseline) stays in its own section.
  in->identification = ident::Identify(campaign, identify);
  if (o.no_diagnosis) return;
  ident::DiagnoseOptions d;
  d.identify = identify;
  in->diagnosis = ident::Diagnose(campaign, d);
  AddBeforeAfter(campaign, identify.data, in);
}

int RunReport(const ReportFlags& o) {
  CheckFilterWindow(o.data);
  io::CheckNewDirectory(o.out, "-o");
  report::ReportInputs in;
  in.source = o.input;
  AddVehicleAndPool(o, &in);
  if (IsJsonFile(o.input) && o.data.sg_window > 0) {
    throw InputError("--sg-window",
                     "the velocity filter of a campaign's trials: a schedule or "
                     "a loop's JSON has no trials to filter; drop it");
  }
  if (IsJsonFile(o.input) && io::IsLoopJson(o.input)) {
    in.title = "Loop report";
    in.loop = io::ReadLoopJson(o.input);
  } else if (IsJsonFile(o.input)) {
    AddSchedule(o, &in);
  } else {
    AddCampaign(o, &in);
  }
  if (!o.loop.empty()) in.loop = io::ReadLoopJson(o.loop);
  const report::ReportFiles files = report::BuildReport(in);
  io::WriteNewDirectory(o.out, files.files, "-o", "a report");
  std::cout << "report: "
            << (std::filesystem::path(io::DirectoryPath(o.out)) / "report.html").string() << " ("
            << files.figures << " figures, also as PNG and SVG in "
            << (std::filesystem::path(io::DirectoryPath(o.out)) / "figures").string() << ")\n";
  // The verdicts of the commands whose results are reported: identify's (a DOF that failed),
  // diagnose's (a DOF it could not diagnose), the schedule's (a DOF the pool cannot host).
  const bool failed =
      (in.identification && in.identification->status == ident::IdentifyStatus::kFailed) ||
      (in.diagnosis && !in.diagnosis->not_diagnosed.empty()) || (in.verdict && !in.verdict->hosted);
  return failed ? kExitActionNeeded : kExitOk;
}

void BindReport(CLI::App* sub, ReportFlags* o) {
  sub->add_option("INPUT", o->input,
                  "a schedule (schedule --json), a loop's JSON (loop --json), or a campaign "
                  "(campaign.yaml or its directory)")
      ->required();
  sub->add_option("-o,--out", o->out, "report directory to create (new or empty)")->required();
  sub->add_option("--vehicle", o->vehicle, "vehicle file (required with a schedule)");
  sub->add_option("--pool", o->pool,
                  "pool file (required with a schedule; default: the campaign's)");
  sub->add_option("--loop", o->loop, "also report this loop's history (loop --json)");
  sub->add_flag("--no-diagnosis", o->no_diagnosis, "identify the campaign without diagnosing it");
  AddMethodOptions(sub, &o->method);
  AddFilterWindowOption(sub, &o->data);
  AddAcceptUnitsFlag(sub, &o->accept_units);
}

const CommandRegistration kReportRegistration(MakeCommand<ReportFlags>(
    "report", 95,
    "Write a self-contained HTML report (vehicle, pool, schedule or estimates, validation, "
    "diagnosis, loop history; figures embedded) and its figures as PNG and SVG.",
    BindReport, RunReport));

}  // namespace
}  // namespace uuvplan::cli
