// The trial log (contract §Trial log) as CSV: read with unwrapped headings, every fault a
// model::InputError "<file>:<line>: ..."; written so that it reads back.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// Reads a trial CSV. Headings (pos_roll/pitch/yaw) are unwrapped.
model::TrialLog ReadTrialLog(const std::string& path);
/// As ReadTrialLog, and every cell of a `mapping` column must be one of `mappings` (ReadCampaign
/// passes the vehicle's mappings of the trial's DOF); the error names the line.
model::TrialLog ReadTrialLog(const std::string& path, const std::vector<std::string>& mappings);
/// The log of a trial of `vehicle` on `dof` in `mapping`: as ReadTrialLog with the vehicle's
/// mappings of `dof`, and cmd_<thruster> columns turned into force columns
/// (model::ForceFromCommands).
model::TrialLog ReadTrialOf(const std::string& path, const model::Vehicle& vehicle, model::Dof dof,
                            const std::string& mapping);

/// Writes a trial CSV (columns present in `log`, empty cells for NaN) atomically, headed by
/// `comment` as '#' lines. Throws std::invalid_argument for a log the reader would reject.
void WriteTrialLog(const std::string& path, const model::TrialLog& log,
                   const std::string& comment = "");

}  // namespace uuvplan::io
