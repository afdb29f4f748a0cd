// The `score` result as JSON (docs/formats.md): per trial its free-run scores, per DOF the
// pooled velocity MAE of its fit and validate trials. SI units; NaN as null.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "uuvplan/ident/score.h"

namespace uuvplan::io {

/// {"vehicle", "campaign", "trials": [{file, dof, use, velocity_mae, velocity_samples,
/// position_rms, position_samples}], "dofs": {<dof>: {velocity_mae_fit, velocity_mae_validate,
/// velocity_mae_all, samples_fit, samples_validate, problem}}, "notes"}.
nlohmann::json ScoreJson(const ident::ScoreResult& result, const std::string& vehicle,
                         const std::string& campaign);

}  // namespace uuvplan::io
