// The vehicle, the pool and the schedule.
#include <cmath>
#include <utility>

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/report/sections.h"

namespace uuvplan::report {

std::string Number(double x) { return std::isfinite(x) ? model::Significant(x, 4) : "—"; }

namespace {

Table ThrusterTable(const model::Vehicle& v) {
  Table t{"Thrusters",
          {"thruster", "thrust model", "command range (command units)",
           "largest forward thrust (N)", "largest reverse thrust (N)"},
          {}};
  for (const model::Thruster& th : v.thrusters) {
    const bool square = th.model.kind == model::ThrustModel::Kind::kSquare;
    t.rows.push_back({th.name, square ? "square c·V|V|" : "poly2 a·V² + b·V",
                      Number(th.command_min) + " … " + Number(th.command_max) +
                          (th.neutral != 0.0 ? " (stopped at " + Number(th.neutral) + ")" : ""),
                      Number(th.MaxForwardThrust()), Number(th.MaxReverseThrust())});
  }
  return t;
}

Table MappingTable(const model::Vehicle& v) {
  Table t{"Thrust mappings tau_i = share_i·phi",
          {"mapping", "DOF", "shares (thruster: share, 1)", "open water"},
          {}};
  for (const model::ThrustMapping& m : v.mappings) {
    std::string shares;
    for (const auto& [i, share] : m.shares) {
      shares += (shares.empty() ? "" : ", ") + v.thrusters[i].name + ": " + Number(share);
    }
    t.rows.push_back({m.name, std::string(model::DofName(m.dof)), shares,
                      std::string(model::OpenWaterName(m.open_water))});
  }
  return t;
}

Table SensorTable(const model::Vehicle& v) {
  Table t{"Sensors",
          {"DOF", "position rate (Hz)", "position σ", "velocity rate (Hz)", "velocity σ"},
          {}};
  for (const auto& [dof, s] : v.sensors) {
    const std::string pu(model::PositionUnit(dof)), vu(model::VelocityUnit(dof));
    t.rows.push_back({std::string(model::DofName(dof)),
                      s.position ? Number(s.position->rate_hz) : "—",
                      s.position ? Number(s.position->sigma) + " " + pu : "—",
                      s.velocity ? Number(s.velocity->rate_hz) : "—",
                      s.velocity ? Number(s.velocity->sigma) + " " + vu : "—"});
  }
  return t;
}

// What the schedule's predicted σ rest on: one sentence when every DOF's says the same.
std::string PredictedAssumptions(const planner::Schedule& schedule) {
  std::string out;
  for (const auto& [dof, p] : schedule.predicted) {
    if (out.find(p.assumption) != std::string::npos) continue;
    out += (out.empty() ? "" : "; ") + p.assumption;
  }
  return out.empty() ? planner::kPredictedSigmaAssumption : out;
}

// The section of an input file: what it names (and where it was read), then its values.
Section InputFileSection(std::string id, std::string title, const std::string& name,
                         const std::string& source, Table values) {
  Section s{std::move(id), std::move(title), {name + " (" + source + ")"}, {}, {}};
  s.tables.push_back(std::move(values));
  return s;
}

}  // namespace

Section VehicleSection(const model::Vehicle& v, const std::string& source) {
  Section s = InputFileSection(
      "vehicle", "Vehicle", v.name, source,
      {"Vehicle",
       {"mass in air (kg)", "length (m)", "width (m)", "height (m)", "min_thrust (N)"},
       {{Number(v.mass), Number(v.size[0]), Number(v.size[1]), Number(v.size[2]),
         Number(v.min_thrust)}}});
  s.tables.push_back(ThrusterTable(v));
  s.tables.push_back(MappingTable(v));
  s.tables.push_back(SensorTable(v));
  return s;
}

Section PoolSection(const model::Pool& p, const std::string& source) {
  return InputFileSection(
      "pool", "Pool", p.name, source,
      {"Pool",
       {"length (m)", "width (m)", "depth (m)", "margin (m)", "tether twist (turns)"},
       {{Number(p.length), Number(p.width), Number(p.depth), Number(p.margin),
         Number(p.max_turns)}}});
}

Section ScheduleSection(const planner::Schedule& schedule,
                        const std::vector<std::string>& verdict_lines) {
  Section s{"schedule", "Schedule", verdict_lines, {}, {}};
  s.paragraphs.push_back(std::to_string(schedule.trials.size()) + " trials, pool time " +
                         Number(schedule.pool_time) + " s (" + Number(schedule.pool_time / 60) +
                         " min) with the pauses between trials.");
  Table trials{"Trials",
               {"#", "trial", "DOF", "kind", "mapping", "duration (s)", "travel min", "travel max",
                "travel unit", "smallest working thrust (N)"},
               {}};
  for (std::size_t i = 0; i < schedule.trials.size(); ++i) {
    const auto& t = schedule.trials[i];
    const auto& d = t.design;
    // Rotations in degrees, as the terminal's verdict lines give them (the JSON stays in rad).
    const bool turn = model::IsRotational(d.dof);
    const double scale = turn ? 180.0 / M_PI : 1.0;
    trials.rows.push_back({std::to_string(i + 1), d.id, std::string(model::DofName(d.dof)),
                           std::string(model::TrialKindName(d.kind)), d.mapping, Number(d.duration),
                           Number(t.travel[0] * scale), Number(t.travel[1] * scale),
                           turn ? "°" : std::string(model::PositionUnit(d.dof)),
                           Number(t.thrust_min)});
  }
  s.tables.push_back(std::move(trials));
  Table predicted{"Predicted precision (" + PredictedAssumptions(schedule) + ")",
                  {"DOF", "parameter", "predicted σ", "unit", "criterion"},
                  {}};
  for (const auto& [dof, p] : schedule.predicted) {
    for (const auto& [name, sigma] : p.sigma) {
      predicted.rows.push_back({std::string(model::DofName(dof)), name, Number(sigma),
                                model::Unit(name, dof), p.criterion});
    }
  }
  s.tables.push_back(std::move(predicted));
  return s;
}

}  // namespace uuvplan::report
