#include "uuvplan/cli/model_vehicle_file.h"

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "uuvplan/ident/score.h"
#include "uuvplan/io/files.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::cli {
namespace {

// Today as YYYY-MM-DD (UTC), or SOURCE_DATE_EPOCH's day when that is set
// (reproducible-builds.org's convention for a fixed date).
std::string Today() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = std::atoll(epoch);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &utc);
  return text;
}

}  // namespace

bool WriteModelVehicle(const std::string& command, const std::string& path,
                       const std::string& campaign_path, const std::string& source,
                       model::Vehicle vehicle,
                       const std::vector<const ident::DofIdentification*>& dofs,
                       const std::string& comment) {
  for (const ident::DofIdentification* d : dofs) {
    const model::DofTruth m = ident::ModelOf(*d);
    const std::string problem = ident::Inadmissible(m);
    if (!problem.empty()) {
      std::cerr << "uuvplan: " << command << ": error: " << path << " not written: the "
                << model::DofName(d->dof) << " model has " << problem << "\n";
      return false;
    }
    vehicle.models[d->dof] = m;
  }
  const std::string header = std::string(io::kWrittenByPrefix) + command + " " + campaign_path +
                             " --write-vehicle` on " + Today() + ": " + comment;
  if (source.empty()) {
    io::WriteVehicleYaml(path, vehicle, header);
  } else {
    io::WriteVehicleYamlOver(path, source, vehicle, header);
  }
  return true;
}

std::string CampaignVehicleFile(const model::Campaign& campaign) {
  return io::ResolveBeside(campaign.path, campaign.vehicle_file);
}

void RefuseWritingOverTheVehicleFile(const std::string& path, const model::Campaign& campaign) {
  std::error_code ec;
  if (path.empty() || !std::filesystem::equivalent(path, CampaignVehicleFile(campaign), ec)) return;
  throw model::InputError("--write-vehicle " + path,
                          "is the campaign's vehicle file, an input that is never modified: "
                          "write the model to another file (it keeps this one's text)");
}

bool WriteIdentifiedVehicle(const std::string& command, const std::string& path,
                            const std::string& campaign_path, const std::string& source,
                            const model::Vehicle& vehicle, const ident::IdentifyResult& result,
                            const std::string& what) {
  std::vector<const ident::DofIdentification*> dofs;
  for (const ident::DofIdentification& d : result.dofs) {
    if (d.status == ident::IdentifyStatus::kFailed) {
      std::cerr << "uuvplan: " << command << ": error: " << path
                << " not written: " << model::DofName(d.dof) << " was not identified\n";
      return false;
    }
    dofs.push_back(&d);
  }
  if (dofs.empty()) {
    std::cerr << "uuvplan: " << command << ": error: " << path
              << " not written: no DOF was identified\n";
    return false;
  }
  return WriteModelVehicle(command, path, campaign_path, source, vehicle, dofs,
                           what +
                               ",\nsigma: 1σ of each parameter (0: held, not estimated).\n"
                               "Every command reads it: schedule, next and loop plan about "
                               "these estimates.");
}

}  // namespace uuvplan::cli
