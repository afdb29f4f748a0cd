// TRANSITIONAL: the readers and writers of the contract's files live in the io layer
// (planner/io, namespace uuvplan::io, library uuvplan_io). The three writers below keep
// model::SimulateCampaign (virtual_pool.cc) building until the virtual campaign is built in
// memory and written by io::WriteCampaign; they forward to the io functions of the same name
// and are defined in uuvplan_io. Remove this header with the last call in virtual_pool.cc.
#pragma once

#include <string>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

void WriteTrialLog(const std::string& path, const TrialLog& log, const std::string& comment = "");
void WriteVehicleYaml(const std::string& path, const Vehicle& vehicle);
void WriteCampaignYaml(const std::string& path, const Campaign& campaign);

}  // namespace uuvplan::model
