#include "uuvplan/model/commanded_force.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "uuvplan/model/configuration_matrix.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/numbers.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::model {

namespace {

// "t = 1.5 s (data row 16)": where a row's fault is.
std::string RowPlace(const TrialLog& log, std::size_t row) {
  return "t = " + ShortestNumber(log.t[row]) + " s (data row " + std::to_string(row + 1) + ")";
}

// Each thruster's command column, in the vehicle's order; every column names a thruster.
std::vector<const std::vector<double>*> CommandColumns(const Vehicle& vehicle,
                                                       const std::string& file,
                                                       const TrialLog& log) {
  std::vector<std::string> names;
  for (const Thruster& t : vehicle.thrusters) names.push_back(t.name);
  for (const auto& [name, values] : log.commands) {
    if (vehicle.ThrusterIndex(name) < 0) {
      throw InputError(file, "column 'cmd_" + name + "': expected a thruster of vehicle '" +
                                 vehicle.name + "' (" + Join(names) + ")");
    }
  }
  std::vector<const std::vector<double>*> columns;
  for (const Thruster& t : vehicle.thrusters) {
    const auto it = log.commands.find(t.name);
    if (it == log.commands.end()) {
      throw InputError(file, "no column 'cmd_" + t.name + "': a log of commands gives every " +
                                 "thruster's (a missing one is not taken as stopped)");
    }
    columns.push_back(&it->second);
  }
  return columns;
}

// Every thruster's thrust (N) per row, from its command; NaN for an empty cell.
std::vector<std::vector<double>> Thrusts(const Vehicle& vehicle, const std::string& file,
                                         const TrialLog& log,
                                         const std::vector<const std::vector<double>*>& columns) {
  std::vector<std::vector<double>> thrust(columns.size());
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const Thruster& th = vehicle.thrusters[i];
    const std::vector<double>& command = *columns[i];
    thrust[i].resize(command.size());
    for (std::size_t r = 0; r < command.size(); ++r) {
      const double c = command[r];
      if (c < th.command_min || c > th.command_max) {
        throw InputError(file, "column 'cmd_" + th.name + "' at " + RowPlace(log, r) +
                                   ": expected a command within [" +
                                   ShortestNumber(th.command_min) + ", " +
                                   ShortestNumber(th.command_max) + "] (thruster " + th.name +
                                   "), got " + ShortestNumber(c));
      }
      thrust[i][r] = th.Thrust(c);  // NaN stays NaN
    }
  }
  return thrust;
}

// The mapping of each row: its `mapping` cell, else the trial's.
std::vector<int> RowMappings(const Vehicle& vehicle, const std::string& mapping,
                             const TrialLog& log) {
  std::vector<int> of_name;
  for (const std::string& name : log.mapping_names) of_name.push_back(vehicle.MappingIndex(name));
  const int trial = vehicle.MappingIndex(mapping);
  std::vector<int> rows(log.size(), trial);
  for (std::size_t r = 0; r < log.mapping.size(); ++r) {
    if (log.mapping[r] >= 0) rows[r] = of_name[log.mapping[r]];
  }
  return rows;
}

// Each mapping's share of every thruster (0 for one it does not use), in the vehicle's order.
std::vector<std::vector<double>> ShareRows(const Vehicle& vehicle) {
  std::vector<std::vector<double>> rows;
  for (const ThrustMapping& m : vehicle.mappings) {
    rows.emplace_back(vehicle.thrusters.size(), 0.0);
    for (const auto& [i, s] : m.shares) rows.back()[i] = s;
  }
  return rows;
}

// phi of one row in `m` (shares `share`): the least-squares fit of tau_i = share_i·phi
// (ref 000 Table I); throws when a thruster `m` does not use pushes more than
// kForeignThrustFraction of the row's largest thrust in `m` and the working floor `floor`.
double NominalForce(const Vehicle& vehicle, const ThrustMapping& m,
                    const std::vector<double>& share, double floor, const std::string& file,
                    const TrialLog& log, std::size_t row,
                    const std::vector<std::vector<double>>& thrust) {
  double largest = 0.0, fit = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < thrust.size(); ++i) {
    if (share[i] == 0.0) continue;  // an empty cell of a thruster outside it blanks nothing
    largest = std::max(largest, std::abs(thrust[i][row]));
    fit += share[i] * thrust[i][row];
    norm += share[i] * share[i];
  }
  const double allowed = std::max(kForeignThrustFraction * largest, floor);
  for (std::size_t i = 0; i < thrust.size(); ++i) {
    if (share[i] != 0.0 || !(std::abs(thrust[i][row]) > allowed)) continue;
    throw InputError(file, "column 'cmd_" + vehicle.thrusters[i].name + "' at " +
                               RowPlace(log, row) + ": thruster " + vehicle.thrusters[i].name +
                               " pushes " + Significant(thrust[i][row], 3) + " N in a row of " +
                               "mapping '" + m.name + "', which does not use it: expected " +
                               "the row's mapping (its 'mapping' cell or the trial's)");
  }
  return norm > 0 ? fit / norm : kNaN;
}

// force_<d> = row d of B·tau for every DOF but `dof` that some thruster pushes.
void GeneralisedForces(const Vehicle& vehicle, Dof dof,
                       const std::vector<std::vector<double>>& thrust, TrialLog* log) {
  const Eigen::MatrixXd b = ConfigurationMatrix(vehicle.thrusters);
  for (Dof d : kAllDofs) {
    const int k = Index(d);
    if (d == dof || b.row(k).isZero()) continue;
    std::vector<double>& force = log->force[k];
    force.assign(log->size(), 0.0);
    for (std::size_t i = 0; i < thrust.size(); ++i) {
      if (b(k, i) == 0.0) continue;  // nor here
      for (std::size_t r = 0; r < force.size(); ++r) force[r] += b(k, i) * thrust[i][r];
    }
  }
}

}  // namespace

void ForceFromCommands(const Vehicle& vehicle, Dof dof, const std::string& mapping,
                       const std::string& file, TrialLog* log) {
  // A log that gives the force keeps it: its cmd_ columns are other columns then.
  if (log->commands.empty() || log->HasAnyForce()) return;
  const auto columns = CommandColumns(vehicle, file, *log);
  const auto thrust = Thrusts(vehicle, file, *log, columns);
  const std::vector<int> mappings = RowMappings(vehicle, mapping, *log);
  const std::vector<std::vector<double>> shares = ShareRows(vehicle);
  const double floor = vehicle.WorkingThrustFloor();
  std::vector<double>& force = log->force[Index(dof)];
  force.resize(log->size());
  for (std::size_t r = 0; r < force.size(); ++r) {
    const int m = mappings[r];
    force[r] =
        m < 0 ? kNaN
              : NominalForce(vehicle, vehicle.mappings[m], shares[m], floor, file, *log, r, thrust);
  }
  if (HasFullGeometry(vehicle.thrusters)) GeneralisedForces(vehicle, dof, thrust, log);
  log->commands.clear();
}

}  // namespace uuvplan::model
