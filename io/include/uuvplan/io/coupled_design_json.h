// A combined-mode design of the coupled horizontal model (`schedule --model coupled`,
// planner/design/coupled_design.h) as JSON (docs/formats.md): {"model": "coupled-horizontal", "fits",
// "reasons", "notes", "trial": {"id", "mode", "duration", "inputs": [{"dof", "mapping", "kind":
// "sine", "offset", "amplitude", "omega"}], "start": {"x", "y", "heading"}, "profile": {"t",
// "force": {"surge": […], …}, "thrusters": {"HFL": […], …}}}, "envelope", "cramer_rao":
// {"surge.m": {"sigma", "relative"}, …}, "criterion", "solver"}. SI; the profile every 0.1 s.
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/coupled_design.h"

namespace uuvplan::io {

nlohmann::json CoupledDesignJson(const planner::CoupledDesign& design,
                                 const model::Vehicle& vehicle, const model::Pool& pool);

/// Whether the JSON file's top level is a coupled schedule ({"model": "coupled-horizontal"}).
bool IsCoupledScheduleJson(const nlohmann::json& root);

/// The trial of a coupled schedule JSON (its "trial": id, mode, duration, inputs); InputError
/// naming the file and key when a value is missing or wrong, or the inputs do not match the
/// mode.
model::CoupledTrialDesign CoupledTrialOfJson(const nlohmann::json& root, const std::string& path);

}  // namespace uuvplan::io
