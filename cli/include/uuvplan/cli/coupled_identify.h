// `uuvplan identify CAMPAIGN --model coupled`: the coupled 3-DOF horizontal model of ref 003
// (model/coupled_model.h) from the campaign's fit trials, each a combined-mode log with the
// force_ and vel_ columns of surge, sway and yaw, by the multi-DOF model's one-step integral
// least squares (ident/estimators/joint_ls.h). Prints the parameters with σ and units (and --json).
#pragma once

#include <string>

#include "uuvplan/model/campaign.h"

namespace uuvplan::cli {

/// Exit status: 0 identified, 1 the fit failed or is non-physical (the message says why).
int RunCoupledIdentify(const model::Campaign& campaign, const std::string& campaign_path,
                       const std::string& json_path);

}  // namespace uuvplan::cli
