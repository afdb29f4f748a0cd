// The `identify` result as JSON (contract §identify, docs/cli.md) and as a readable table.
// Shared by the commands that print identification results (identify, next, loop, diagnose).
//
// JSON: {"status", "message",
//        "dofs": {<dof>: {"params": {<name>: {"value", "sigma", "percentile_error",
//                                             "significant", "state", ...}},
//                         "fit": {"velocity_mae": {"trials": {<file>: v}, "fit", "validate",
//                                                  "overall"}, "position_rms": {...},
//                                 "trials": [...residual analysis...]},
//                         "parameter_names", "covariance", "estimator", "stages", ...}},
//        "trials": [{"file", "dof", "use", "outliers", "gaps", "notes"}]}
// NaN (no value) is written as null.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "uuvplan/ident/identify.h"

namespace uuvplan::tool {

/// The whole identification result.
nlohmann::json IdentifyJson(const ident::IdentifyResult& result);

/// One DOF's {"params": …, "fit": …, …} block.
nlohmann::json DofIdentificationJson(const ident::DofIdentification& dof);

/// {<name>: {"value", "sigma"}} of a DOF (the compact form used by `loop`).
nlohmann::json ParamsJson(const ident::DofIdentification& dof);

/// Readable tables: per DOF the parameters (value, σ, percentile error, significance) and the
/// fit figures, then warnings and what was excluded from the data.
void PrintIdentifyTable(const ident::IdentifyResult& result, std::ostream& out);

/// A number for a table: `precision` significant digits, "-" when not finite.
std::string Cell(double v, int precision = 4);

}  // namespace uuvplan::tool
