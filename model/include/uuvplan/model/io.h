// Readers and writers of the contract's files. Every reader throws InputError naming the
// file, the line or YAML key, and what was expected; none modifies its input. Writers write
// to a temporary file and rename it, so an output is written whole or not at all.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

Vehicle ReadVehicle(const std::string& path);
Pool ReadPool(const std::string& path);
Truth ReadTruth(const std::string& path);
/// Reads the campaign YAML, its vehicle (and pool) and every trial CSV.
Campaign ReadCampaign(const std::string& path);
/// Reads a trial CSV. Headings (pos_roll/pitch/yaw) are unwrapped.
TrialLog ReadTrialLog(const std::string& path);
/// As ReadTrialLog, and every cell of a `mapping` column must be one of `mappings` (ReadCampaign
/// passes the vehicle's mappings of the trial's DOF); the error names the line.
TrialLog ReadTrialLog(const std::string& path, const std::vector<std::string>& mappings);

/// Writes a trial CSV (columns present in `log`, empty cells for NaN).
void WriteTrialLog(const std::string& path, const TrialLog& log, const std::string& comment = "");
/// Writes a vehicle file (contract §Vehicle) that ReadVehicle reads back to the same vehicle.
void WriteVehicleYaml(const std::string& path, const Vehicle& vehicle);
/// Writes campaign.yaml; trial files are written by the caller (paths relative to `path`).
void WriteCampaignYaml(const std::string& path, const Campaign& campaign);

/// Writes `text` to `path` atomically (temporary file + rename).
void WriteFileAtomically(const std::string& path, const std::string& text);

}  // namespace uuvplan::model
