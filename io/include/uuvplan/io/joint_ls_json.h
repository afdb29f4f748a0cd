// A multi-DOF model's identification (ident/estimators/joint_ls.h; `identify --model coupled`)
// as JSON (docs/formats.md): {"model": <its name>, "method": "one-step", "status", "message",
// "instrumental", "rows", "condition_number", "params": {"surge.m": {"value", "sigma", "unit",
// "state"}, …}, "dropped", "covariance": [[…]] (the model's θ order), "notes"}. SI.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "uuvplan/ident/estimators/joint_ls.h"

namespace uuvplan::io {

nlohmann::json JointLsJson(const ident::JointLsResult& result, const std::string& model_name);

}  // namespace uuvplan::io
