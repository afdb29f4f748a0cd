// The coupled horizontal model's identification (`identify --model coupled`, ident/estimators/coupled_ls.h)
// as JSON (docs/formats.md): {"model": "coupled-horizontal", "method": "one-step", "status",
// "message", "instrumental", "rows", "condition_number", "params": {"surge.m": {"value",
// "sigma", "unit"}, …}, "covariance": [[…]] (θ order of model/coupled_model.h), "notes"}. SI.
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/ident/estimators/coupled_ls.h"

namespace uuvplan::io {

nlohmann::json CoupledIdentifyJson(const ident::CoupledLsResult& result);

}  // namespace uuvplan::io
