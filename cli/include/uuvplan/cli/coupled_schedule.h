// `uuvplan schedule VEHICLE --pool POOL --model coupled [--mode M] [--max-duration S] [--json F]`:
// the combined-mode sine trial of ref 003's coupled model (planner/design/combined_design.h with
// coupled_design.h's options), robust over the a priori box, with its start pose in the pool
// and the Cramér–Rao σ it promises. Exit 0 when every constraint holds over the box, 1 when
// not (the reasons printed).
#pragma once

#include <string>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/combined_design.h"

namespace uuvplan::cli {

int RunCoupledSchedule(const model::Vehicle& vehicle, const model::Pool& pool,
                       const planner::CombinedDesignOptions& options, const std::string& json_path);

}  // namespace uuvplan::cli
