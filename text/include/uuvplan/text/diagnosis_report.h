// A diagnosis as a readable report (its JSON is io::DiagnosisJson).
#pragma once

#include <ostream>

#include "uuvplan/ident/diagnosis/diagnosis.h"

namespace uuvplan::text {

/// The standard model's errors, the findings with their extension and gain, and the tests.
void PrintDiagnosis(const ident::DiagnosisResult& result, std::ostream& out);

}  // namespace uuvplan::text
