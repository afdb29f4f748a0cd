#include "uuvplan/report/schedule_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/trial_envelope.h"

namespace uuvplan::report {

namespace {

using model::Dof;

constexpr int kPoints = 400;  // samples per curve: smooth at 1100 px

std::string Unit(std::string_view u) { return std::string(u); }

// The walls and margins along the trial's DOF, placed so that the predicted excursion
// [lo, hi] is centred in the free travel (the start is where the run sheet puts the vehicle).
std::vector<Level> PoolLevels(const model::Pool& pool, Dof dof, double lo, double hi) {
  const double free = pool.FreeTravel(dof);
  const double free_lo = lo - (free - (hi - lo)) / 2;
  if (model::IsRotational(dof)) {
    return {{free_lo, "tether twist limit", Colour::kVermillion, Style::kDashed},
            {free_lo + free, "tether twist limit", Colour::kVermillion, Style::kDashed}};
  }
  const std::string wall = "wall (" + std::string(model::Pool::SideName(dof)) + " " +
                           model::Significant(pool.WallToWall(dof), 3) + " m)";
  return {{free_lo - pool.margin, wall, Colour::kBlack, Style::kLine},
          {free_lo, "margin", Colour::kVermillion, Style::kDashed},
          {free_lo + free, "margin", Colour::kVermillion, Style::kDashed},
          {free_lo + free + pool.margin, wall, Colour::kBlack, Style::kLine}};
}

Panel PositionPanel(const planner::DofPlanningProblem& ctx, const planner::PlannedTrial& trial) {
  const model::TrialDesign& d = trial.design;
  planner::PositionEnvelope e = planner::EnvelopeOf(ctx, d, kPoints);
  const double lo = *std::min_element(e.low.begin(), e.low.end());
  const double hi = *std::max_element(e.high.begin(), e.high.end());
  const bool bounded = std::isfinite(ctx.pool().FreeTravel(d.dof));
  std::vector<Level> levels;
  if (bounded) levels = PoolLevels(ctx.pool(), d.dof, lo, hi);
  // Headings in degrees, as people read them and as the verdict lines give them.
  const bool turn = model::IsRotational(d.dof);
  if (turn) {
    for (auto* v : {&e.low, &e.high, &e.nominal}) {
      for (double& x : *v) x *= 180.0 / M_PI;
    }
    for (Level& l : levels) l.y *= 180.0 / M_PI;
  }
  Panel p;
  p.title = "position over the a priori box";
  p.x_label = "t (s)";
  p.y_label = std::string(model::DofName(d.dof)) + " position (" +
              (turn ? std::string("°") : Unit(model::PositionUnit(d.dof))) + ")";
  p.series.push_back(
      {"envelope of the box", Style::kBand, Colour::kBandBlue, e.t, {}, e.low, e.high});
  p.series.push_back({"centre vehicle", Style::kLine, Colour::kBlue, e.t, e.nominal, {}, {}});
  p.levels = std::move(levels);
  p.levels.push_back({0.0, "start", Colour::kGrey, Style::kDotted});
  return p;
}

// Each working thruster's limits once (several thrusters often share them); a limit more
// than twice the largest force is left off the scale (named in the panel's title instead).
std::vector<Level> ThrustLevels(const model::Vehicle& v, const planner::ThrusterForces& f,
                                std::string* off_scale) {
  std::set<double> forward, reverse;
  double largest = 0.0;
  for (std::size_t i = 0; i < v.thrusters.size(); ++i) {
    if (!f.used[i]) continue;
    forward.insert(v.thrusters[i].MaxForwardThrust());
    reverse.insert(v.thrusters[i].MaxReverseThrust());
    for (double x : f.force[i]) largest = std::max(largest, std::abs(x));
  }
  std::vector<Level> levels = {{0.0, "zero (reversal)", Colour::kBlack, Style::kLine, true}};
  auto limit = [&](double y) {
    const bool near = std::abs(y) <= 2 * largest;
    levels.push_back(
        {y, "limit " + model::Significant(y, 3) + " N", Colour::kVermillion, Style::kDashed, near});
    if (!near) *off_scale += (off_scale->empty() ? "" : ", ") + model::Significant(y, 3) + " N";
  };
  for (double x : forward) limit(x);
  for (double x : reverse) limit(-x);
  if (v.min_thrust > 0) {
    levels.push_back({v.min_thrust, "±min_thrust", Colour::kGrey, Style::kDotted, true});
    levels.push_back({-v.min_thrust, "±min_thrust", Colour::kGrey, Style::kDotted, true});
  }
  return levels;
}

std::vector<Panel> ThrustPanels(const model::Vehicle& v, const model::TrialDesign& d) {
  const planner::ThrusterForces f = planner::ThrusterForcesOf(v, d, kPoints);
  Panel thrusters;
  thrusters.title = "each thruster's force tau_i = share_i·phi_n";
  thrusters.x_label = "t (s)";
  thrusters.y_label = "thrust (N)";
  const Colour colours[] = {Colour::kBlue, Colour::kOrange,     Colour::kGreen, Colour::kPurple,
                            Colour::kSky,  Colour::kVermillion, Colour::kBlack, Colour::kGrey};
  int k = 0;
  for (std::size_t i = 0; i < v.thrusters.size(); ++i) {
    if (!f.used[i]) continue;
    thrusters.series.push_back({v.thrusters[i].name,
                                k % 2 ? Style::kDashed : Style::kLine,
                                colours[k % 8],
                                f.t,
                                f.force[i],
                                {},
                                {}});
    ++k;
  }
  std::string off_scale;
  thrusters.levels = ThrustLevels(v, f, &off_scale);
  if (!off_scale.empty()) thrusters.title += " (limits " + off_scale + " off the scale)";
  Panel input;
  input.title = "designed input phi_n (" + std::string(model::TrialKindName(d.kind)) +
                ", mapping " + d.mapping + ")";
  input.x_label = "t (s)";
  input.y_label = "phi_n (" + Unit(model::ForceUnit(d.dof)) + ")";
  input.series.push_back({"phi_n", Style::kLine, Colour::kBlack, f.t, f.nominal, {}, {}});
  input.levels.push_back({0.0, "", Colour::kGrey, Style::kDotted});
  return {thrusters, input};
}

Figure TrialFigure(const planner::DofPlanningProblem& ctx, const planner::PlannedTrial& trial,
                   int index) {
  const model::TrialDesign& d = trial.design;
  Figure f;
  char number[16];
  std::snprintf(number, sizeof number, "%02d", index + 1);  // file names sort in trial order
  f.name = "schedule-" + std::string(number) + "-" + d.id;
  f.title = "Trial " + std::to_string(index + 1) + ": " + d.id + " (" +
            std::string(model::DofName(d.dof)) + ", " + model::Significant(d.duration, 3) + " s)";
  f.caption = "Trial " + d.id +
              ": the position from rest over the a priori box (shaded: the "
              "envelope of the pool check's extreme vehicles; line: the centre vehicle), with the "
              "pool's walls and margins placed so the excursion is centred; each working "
              "thruster's force with its limits, min_thrust and the zero line (a reversal would "
              "cross it); and the designed input.";
  f.panels.push_back(PositionPanel(ctx, trial));
  for (Panel& p : ThrustPanels(ctx.vehicle(), d)) f.panels.push_back(std::move(p));
  f.height = 40 + 3 * 290;
  return f;
}

}  // namespace

std::vector<Figure> ScheduleFigures(const model::Vehicle& vehicle, const model::Pool& pool,
                                    const planner::Schedule& schedule,
                                    const planner::PlannerOptions& options,
                                    std::vector<std::string>* notes) {
  std::map<Dof, std::unique_ptr<planner::DofPlanningProblem>> contexts;
  std::vector<Figure> figures;
  for (std::size_t i = 0; i < schedule.trials.size(); ++i) {
    const planner::PlannedTrial& t = schedule.trials[i];
    auto& ctx = contexts[t.design.dof];
    if (!ctx)
      ctx = planner::DofPlanningProblem::APriori(vehicle, pool, t.design.dof, options, notes);
    figures.push_back(TrialFigure(*ctx, t, static_cast<int>(i)));
  }
  return figures;
}

}  // namespace uuvplan::report
