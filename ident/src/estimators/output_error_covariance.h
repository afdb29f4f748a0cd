// Internal to the output error (output_error.h): the covariance at its answer.
#pragma once

#include <vector>

#include "estimators/output_error_levenberg_marquardt.h"
#include "estimators/output_error_problem.h"
#include "uuvplan/ident/estimators/output_error.h"

namespace uuvplan::ident::internal {

// Cov(z) = s²·(JᵀJ)⁻¹ (HAC when the residuals are coloured) and the CRB (JᵀJ)⁻¹, in the model
// layout; s², condition number, unidentifiable parameters and the status of the fit.
void StoreCovariance(const Problem& p, const LmOutcome& lm, const std::vector<int>& free,
                     const OutputErrorOptions& o, OutputErrorResult* res);

}  // namespace uuvplan::ident::internal
