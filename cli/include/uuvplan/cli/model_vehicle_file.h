// `--write-vehicle OUT` of `identify` and `diagnose`: the campaign's vehicle with the model
// each DOF was identified with (dofs.<dof>.params, effects and sigma, io/vehicle_yaml.h), the
// file every command reads back — `schedule`, `next` and `loop` plan about its estimates.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/identify.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::cli {

/// Writes `vehicle` with the model of each of `dofs` (ident::ModelOf) into `path`, headed by
/// `comment`, the source campaign and the date (SOURCE_DATE_EPOCH when set, for reproducible
/// files). False, with the reason on stderr and nothing written, when a model has a parameter
/// the file readers would refuse (outside its admissible range).
bool WriteModelVehicle(const std::string& command, const std::string& path,
                       const std::string& campaign_path, model::Vehicle vehicle,
                       const std::vector<const ident::DofIdentification*>& dofs,
                       const std::string& comment);

}  // namespace uuvplan::cli
