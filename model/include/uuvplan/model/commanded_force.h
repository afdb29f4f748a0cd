// The nominal force of a trial logged as thruster commands (cmd_<thruster> columns, in each
// thruster's command unit): each thruster's thrust from its model (thruster.h: measured from
// neutral, none inside the dead band), then per row the nominal force phi of the row's mapping,
// the least-squares fit of tau_i = share_i·phi over its thrusters (ref 000 Table I), and, when
// every thruster has a position and a direction, the generalised force B·tau on every other
// DOF (Fossen 2011 eq. 11.3; configuration_matrix.h).
#pragma once

#include <string>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

/// A thruster outside the row's mapping may push at most this fraction of the largest thrust of
/// the mapping's thrusters in that row (or the vehicle's working floor, where larger): more
/// means the row was not run in that mapping (a wrong `mapping` cell or trial mapping), not the
/// rounding of a command or a thruster spinning down.
inline constexpr double kForeignThrustFraction = 0.1;

/// Turns log->commands into force columns (and clears them): force_<dof> of the trial's DOF
/// from the mapping of each row (its `mapping` cell, else `mapping`), and with full geometry
/// force_<d> of every other DOF the thrusters push. An empty command cell of a thruster that
/// acts on a force gives an empty cell of that force. A log without commands, or with force_
/// columns, is left as it is (io::ReadTrialOf then ignores its cmd_ columns with a note). Throws
/// InputError naming `file`, the column and, for a row, its time: a cmd_ column that names no
/// thruster of the vehicle, a thruster without its column, a command outside the thruster's
/// range, a thruster outside the row's mapping pushing (kForeignThrustFraction).
void ForceFromCommands(const Vehicle& vehicle, Dof dof, const std::string& mapping,
                       const std::string& file, TrialLog* log);

}  // namespace uuvplan::model
