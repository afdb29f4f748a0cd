// Thruster commands and the run sheet of a schedule (command_sheet.h).
#include "uuvplan/planner/pool/command_sheet.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "uuvplan/model/simulator.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/planner/design/centred_travel.h"
#include "uuvplan/planner/design/dof_planning_problem.h"

namespace uuvplan::planner {
namespace {

// Row times: every 1/rate s, every segment change, and the end.
std::vector<double> RowTimes(const model::TrialDesign& d, double rate_hz) {
  std::vector<double> t;
  const long n = static_cast<long>(std::floor(d.duration * rate_hz + 1e-9));
  for (long i = 0; i <= n; ++i) t.push_back(i / rate_hz);
  double start = 0.0;
  for (const model::SegmentDesign& s : d.segments) {
    t.push_back(start);
    start += s.duration;
  }
  t.push_back(d.duration);
  std::sort(t.begin(), t.end());
  t.erase(
      std::unique(t.begin(), t.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }),
      t.end());
  while (!t.empty() && t.back() > d.duration + 1e-9) t.pop_back();
  return t;
}

std::vector<std::string> MappingsOf(const model::TrialDesign& d) {
  std::vector<std::string> names;
  for (const model::ForceDemand& demand : d.Demands()) {
    if (std::find(names.begin(), names.end(), demand.mapping) == names.end()) {
      names.push_back(demand.mapping);
    }
  }
  return names;
}

double ToCentimetre(double metres) { return std::round(metres * 100.0) / 100.0; }

// Where the run starts and where it is aborted (command_sheet.h, "Start and abort").
void PlaceStart(const model::Pool& pool, const PlannedTrial& trial, TrialCommands* c) {
  const double free = pool.FreeTravel(c->dof);
  const double slack = free - (trial.travel[1] - trial.travel[0]);
  c->travel = trial.travel;
  c->abort = CentreTravel(slack, trial.travel).ends;
  c->start = {ToCentimetre(pool.length / 2), ToCentimetre(pool.width / 2),
              ToCentimetre(pool.depth / 2)};
  if (model::IsRotational(c->dof)) {
    c->start_twist = -free / 2 - c->abort[0];
    return;
  }
  const int axis = c->dof == model::Dof::kSurge ? 0 : c->dof == model::Dof::kSway ? 1 : 2;
  c->start[axis] = ToCentimetre(pool.margin - c->abort[0]);
  const double behind = pool.margin - c->start[axis];  // the margin lines from that start
  c->abort = {ToCentimetre(behind), ToCentimetre(behind + free)};
}

}  // namespace

Eigen::VectorXd ThrusterCommands(const model::Vehicle& vehicle, int mapping, double phi) {
  Eigen::VectorXd v(static_cast<int>(vehicle.thrusters.size()));
  for (std::size_t i = 0; i < vehicle.thrusters.size(); ++i) v[i] = vehicle.thrusters[i].neutral;
  if (mapping < 0) return v;
  for (const auto& [thruster, share] : vehicle.mappings[mapping].shares) {
    v[thruster] = vehicle.thrusters[thruster].Command(share * phi);
  }
  return v;
}

CommandSheet MakeCommandSheet(const model::Vehicle& vehicle, const model::Pool& pool,
                              const Schedule& schedule, const CommandSheetOptions& options) {
  CommandSheet sheet;
  sheet.rate_hz = options.rate_hz;
  for (const model::Thruster& t : vehicle.thrusters) sheet.thrusters.push_back(t.name);
  std::map<model::Dof, std::unique_ptr<DofPlanningProblem>> contexts;
  std::vector<std::string> notes;  // the planner's notes were printed with the schedule
  for (const PlannedTrial& trial : schedule.trials) {
    const model::TrialDesign& d = trial.design;
    TrialCommands c;
    c.id = d.id;
    c.dof = d.dof;
    c.kind = d.kind;
    c.duration = d.duration;
    c.mappings = MappingsOf(d);
    c.t = RowTimes(d, options.rate_hz);
    const auto input = model::MakeExcitation(vehicle, d);  // InputError: an unknown mapping
    c.command.resize(static_cast<int>(c.t.size()), static_cast<int>(vehicle.thrusters.size()));
    for (std::size_t i = 0; i + 1 < c.t.size(); ++i) {
      c.command.row(static_cast<int>(i)) =
          ThrusterCommands(vehicle, input->Mapping(c.t[i]), input->Force(c.t[i]));
    }
    c.command.row(static_cast<int>(c.t.size()) - 1) =  // the end: every thruster stops
        ThrusterCommands(vehicle, -1, 0.0).transpose();
    auto& ctx = contexts[d.dof];
    if (!ctx)
      ctx = DofPlanningProblem::APriori(vehicle, pool, d.dof, options.schedule.planner, &notes);
    const DofPlanningProblem::TrialModel& tm = ctx->ModelFor(d);
    model::TrialConditions conditions;
    conditions.input = input.get();
    model::SimulationOptions so;
    so.step_s = std::min(ctx->step_s(), 0.1);
    const model::Trajectory x =
        model::Simulate(*tm.model, tm.design_thetas[0], conditions, c.t, so);
    c.expected_position.assign(x.x.col(0).data(), x.x.col(0).data() + x.x.rows());
    PlaceStart(pool, trial, &c);
    sheet.trials.push_back(std::move(c));
  }
  return sheet;
}

}  // namespace uuvplan::planner
