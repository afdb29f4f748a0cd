// `--write-vehicle OUT` of `identify`, `diagnose` and `loop`: the campaign's vehicle with the model
// each DOF was identified with (dofs.<dof>.params, effects and sigma, io/vehicle_yaml.h), the
// file every command reads back — `schedule`, `next` and `loop` plan about its estimates.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/identify.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::cli {

/// Writes `vehicle` with the model of each of `dofs` (ident::ModelOf) into `path`, headed by
/// `comment`, the source campaign and the date (SOURCE_DATE_EPOCH when set, for reproducible
/// files). False, with the reason on stderr and nothing written, when a model has a parameter
/// the file readers would refuse (outside its admissible range). `source`: the vehicle file
/// `vehicle` was read from, whose text the written file keeps (io::WriteVehicleYamlOver);
/// empty: written whole (a truth file's vehicle).
bool WriteModelVehicle(const std::string& command, const std::string& path,
                       const std::string& campaign_path, const std::string& source,
                       model::Vehicle vehicle,
                       const std::vector<const ident::DofIdentification*>& dofs,
                       const std::string& comment);

/// WriteModelVehicle with every DOF of `result`, headed by `what` ("the identified model") and
/// what its σ are and who reads it; false, with the reason on stderr and nothing written, when
/// a DOF failed (the file would mix an identified model with a failed one's a priori box) or
/// none was identified.
bool WriteIdentifiedVehicle(const std::string& command, const std::string& path,
                            const std::string& campaign_path, const std::string& source,
                            const model::Vehicle& vehicle, const ident::IdentifyResult& result,
                            const std::string& what);

/// The vehicle file a campaign names, resolved beside the campaign file.
std::string CampaignVehicleFile(const model::Campaign& campaign);

/// Throws model::InputError naming --write-vehicle when `path` is the campaign's vehicle file:
/// an input is never modified.
void RefuseWritingOverTheVehicleFile(const std::string& path, const model::Campaign& campaign);

}  // namespace uuvplan::cli
