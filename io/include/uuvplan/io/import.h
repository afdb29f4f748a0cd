// `uuvplan import`: a lab's recordings (ROS 1 bags, MCAP files; recording.h) turned into a
// campaign through a map file (docs/import.md): each thruster's command held from its last
// message, the force it makes (thrust table and arms) or the command itself (cmd_ columns),
// each measured signal scaled into uuvplan's units and NED/FRD axes, device clocks mapped onto
// the recorder's, one trial per recording or per span of thruster activity.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/campaign.h"

namespace uuvplan::io {

struct ImportedTrial {
  std::string recording;  ///< the file it came from
  double span_s = 0.0;    ///< from its first to its last row
  double rate_hz = 0.0;   ///< rows per second
};

struct ImportedCampaign {
  model::Campaign campaign;           ///< trials at trials/<id>.csv, vehicle as read
  std::vector<std::string> comments;  ///< each trial log's header: source, topics, time span
  std::vector<ImportedTrial> trials;
};

/// Imports the recordings at `source` (one file, or a directory's recordings) by the map file
/// `map_file`; `vehicle_file` ("" = the map's `vehicle`) is the campaign's vehicle. Every fault
/// is model::InputError naming the file (and map key, topic, field or message) at fault.
ImportedCampaign ImportRecordings(const std::string& source, const std::string& map_file,
                                  const std::string& vehicle_file);

}  // namespace uuvplan::io
