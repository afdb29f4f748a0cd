// JSON and readable report of a diagnosis (contract §diagnose).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "uuvplan/ident/diagnosis.h"

namespace uuvplan::tool {

/// {"nominal": <identify result>, "findings": [...], "tests": [...], "breakdown": {...}}.
nlohmann::json DiagnosisJson(const ident::DiagnosisResult& result);

/// The standard model's errors, the findings with their extension and gain, and the tests.
void PrintDiagnosis(const ident::DiagnosisResult& result, std::ostream& out);

}  // namespace uuvplan::tool
