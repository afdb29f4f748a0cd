// `uuvplan import --json` (docs/cli.md): the campaign written and where each trial came from.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "uuvplan/io/import.h"

namespace uuvplan::io {

/// {"campaign" (its campaign.yaml), "vehicle", "trials": [{"id", "dof", "mapping", "use",
/// "file", "recording", "rows", "span_s", "rate_hz", "start_s"}]}.
nlohmann::json ImportJson(const ImportedCampaign& imported, const std::string& campaign_path);

}  // namespace uuvplan::io
