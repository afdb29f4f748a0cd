// Vehicles for the planner's tests: ROMEO from cases/romeo (ref 000), and a minimal vehicle
// with one open-water mapping for analytic oracles.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "uuvplan/io/io.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/criteria.h"
#include "uuvplan/planner/design/dof_planning_problem.h"

namespace uuvplan::planner::testing {

/// A file of a shipped case: cases/<vehicle>/<file>.
inline std::string CasePath(const std::string& vehicle, const std::string& file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + vehicle + "/" + file;
}

inline std::string RomeoPath(const std::string& file) { return CasePath("romeo", file); }

inline model::Vehicle Romeo() { return io::ReadVehicle(RomeoPath("vehicle.yaml")); }
inline model::Pool RomeoPool() { return io::ReadPool(RomeoPath("pool.yaml")); }

/// One surge mapping "both" (eta = 1 both ways) on one thruster of large range; surge drag
/// k, kq; a velocity sensor (rate, sigma) and/or a position sensor.
inline model::Vehicle SimpleVehicle(double mass, double k, double kq, bool velocity_sensor,
                                    bool position_sensor) {
  model::Vehicle v;
  v.name = "simple";
  v.mass = mass;
  v.size = {1.0, 1.0, 1.0};
  v.added_mass = {0.0, 0.0};
  model::Thruster t;
  t.name = "T";
  t.model.kind = model::ThrustModel::Kind::kSquare;
  t.model.c_pos = t.model.c_neg = 1.0;
  t.command_min = -100.0;
  t.command_max = 100.0;
  v.thrusters = {t};
  v.min_thrust = 0.0;
  v.mappings = {{"all", model::Dof::kSurge, {{0, 1.0}}, model::OpenWater::kBoth}};
  model::DofPrior prior;
  prior.drag = model::DragPrior{k, kq, 0.0};
  v.priors[model::Dof::kSurge] = prior;
  model::DofSensors s;
  if (velocity_sensor) s.velocity = model::SensorSpec{10.0, 0.01};
  if (position_sensor) s.position = model::SensorSpec{10.0, 0.01};
  v.sensors[model::Dof::kSurge] = s;
  return v;
}

inline model::Pool BigPool() {
  model::Pool p;
  p.name = "big";
  p.length = 1e6;
  p.width = 1e6;
  p.depth = 1e6;
  p.margin = 0.0;
  return p;
}

// Ref 000 §IV-D: 35 N offset, 25 N amplitude, 26 s period in surge-front; "a couple of
// sinusoidal periods in a maneuvering space of about 20 m": two periods, 52 s.
inline model::TrialDesign PaperSurgeSine() {
  model::TrialDesign d;
  d.id = "paper";
  d.dof = model::Dof::kSurge;
  d.kind = model::TrialKind::kSine;
  d.mapping = "surge-front";
  d.offset = 35.0;
  d.amplitude = 25.0;
  d.omega = 2 * M_PI / 26.0;
  d.duration = 52.0;
  return d;
}

/// Worst relative σ(m) over the design points of ctx's box for information M (per point).
inline double WorstSigmaM(const DofPlanningProblem& ctx, const std::vector<Eigen::MatrixXd>& M) {
  double worst = 0.0;
  for (std::size_t j = 0; j < M.size(); ++j) {
    const double rel = PredictedSigma(M[j], ctx.design_thetas()[j])[0] / ctx.design_thetas()[j][0];
    worst = std::max(worst, rel);
  }
  return worst;
}

}  // namespace uuvplan::planner::testing
