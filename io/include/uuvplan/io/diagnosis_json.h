// The `diagnose` result as JSON (contract §diagnose, docs/formats.md).
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/ident/diagnosis/diagnosis.h"

namespace uuvplan::io {

/// {"nominal": <identify result>, "findings": [...], "tests": [...], "breakdown": {...}}.
nlohmann::json DiagnosisJson(const ident::DiagnosisResult& result);

}  // namespace uuvplan::io
