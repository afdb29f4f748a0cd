// TRANSITIONAL (see uuvplan/model/io.h): the writers model::SimulateCampaign calls, forwarding
// to the io layer until the virtual campaign is written by io::WriteCampaign.
#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/trial_log_csv.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/io.h"

namespace uuvplan::model {

void WriteTrialLog(const std::string& path, const TrialLog& log, const std::string& comment) {
  io::WriteTrialLog(path, log, comment);
}

void WriteVehicleYaml(const std::string& path, const Vehicle& vehicle) {
  io::WriteVehicleYaml(path, vehicle);
}

void WriteCampaignYaml(const std::string& path, const Campaign& campaign) {
  io::WriteCampaignYaml(path, campaign);
}

}  // namespace uuvplan::model
