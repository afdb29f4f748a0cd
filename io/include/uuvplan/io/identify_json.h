// The `identify` result as JSON (contract §identify, docs/formats.md). NaN is written as null.
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/ident/identify.h"

namespace uuvplan::io {

/// The whole identification result: {"status", "message", "dofs": {...}, "trials": [...]}.
nlohmann::json IdentifyJson(const ident::IdentifyResult& result);

/// One DOF's {"params": …, "fit": …, …} block.
nlohmann::json DofIdentificationJson(const ident::DofIdentification& dof);

/// {<name>: {"value", "sigma"}} of a DOF (the compact form used by `loop`).
nlohmann::json ParamsJson(const ident::DofIdentification& dof);

}  // namespace uuvplan::io
