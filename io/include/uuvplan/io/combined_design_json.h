// A combined design of a multi-DOF model (planner/design/combined_design.h; `schedule --model
// coupled`) as JSON (docs/formats.md): {"model": <its name>, "pool", "fits", "reasons",
// "notes", "trial": {"id", "mode", "duration", "inputs": [{"dof", "mapping", "kind": "sine",
// "offset", "amplitude", "omega"}], "start": {<position>: …}, "profile": {"t", "force":
// {"surge": […], …}, "thrusters": {"HFL": […], …}}}, "envelope": {<translational position>:
// [min, max], "turns", "thrust_margin", "thrust_load", "closed_water_force"}, "cramer_rao":
// {"surge.m": {"sigma", "relative"}, …}, "cramer_rao_assumption", "criterion", "solver"}.
// Positions are named as the model names them (MultiDofModel::PositionName: x, y, heading in
// the plane). SI; the profile every 0.1 s.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/combined_design.h"

namespace uuvplan::io {

/// The model a combined design is for and what its Cramér–Rao σ rest on.
struct CombinedModelText {
  std::string name;              ///< "coupled-horizontal"
  std::string sigma_assumption;  ///< planner::kCoupledSigmaAssumption
};

nlohmann::json CombinedDesignJson(const planner::CombinedDesign& design,
                                  const model::MultiDofModel& model, const model::Vehicle& vehicle,
                                  const model::Pool& pool, const CombinedModelText& text);

/// Whether the JSON file's top level is a combined schedule of the model named `model_name`
/// ({"model": "coupled-horizontal"}).
bool IsCombinedScheduleJson(const nlohmann::json& root, const std::string& model_name);

/// The trial of a combined schedule JSON (its "trial": id, mode, duration, inputs) for `model`;
/// InputError naming the file and key when a value is missing or wrong, a DOF is not the
/// model's, or the inputs do not match the mode.
model::CombinedTrialDesign CombinedTrialOfJson(const nlohmann::json& root, const std::string& path,
                                               const model::MultiDofModel& model);

}  // namespace uuvplan::io
