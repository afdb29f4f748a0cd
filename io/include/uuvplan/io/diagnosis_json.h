// The `diagnose` result as JSON (contract §diagnose, docs/formats.md).
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/ident/diagnosis/diagnosis.h"

namespace uuvplan::io {

/// {"nominal": <identify result>, "findings": [...], "tests": [...], "breakdown": {...}}.
nlohmann::json DiagnosisJson(const ident::DiagnosisResult& result);

/// A finding's held-out gain: {"metric", "before", "after", "relative", "on"} (relative null
/// when not scored).
nlohmann::json GainJson(const ident::DiagnosisGain& gain);

}  // namespace uuvplan::io
