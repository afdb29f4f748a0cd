// The figures of an identification, per DOF: the measured signal against the free
// run of the identified model for each trial (validation.h, ref 002 eq. 37), the residuals
// and their normalised autocorrelation with the whiteness bounds ±1.96/√N (ref 004 §5.2),
// each parameter with its σ band, and the RLS convergence (ref 004 Fig. 11).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/identify.h"
#include "uuvplan/report/chart.h"

namespace uuvplan::report {

/// Free runs per trial; needs `dof.fit.trials[i].curve` (ValidationOptions::curve_points).
Figure FreeRunFigure(const ident::DofIdentification& dof, const std::string& stem);
/// Residual against time and its autocorrelation, one row per trial.
Figure ResidualFigure(const ident::DofIdentification& dof, const std::string& stem);
/// Each estimated parameter relative to its estimate, θ/θ̂ = 1 ± σ/|θ̂| and ± 2σ.
Figure ParameterFigure(const ident::DofIdentification& dof, const std::string& stem);

/// Ref 004 Fig. 11: each RLS coefficient (γ, θ_j/m) after every update, with its ±1σ band;
/// needs `dof.rls` (identify --method rls).
Figure RlsConvergenceFigure(const ident::DofIdentification& dof, const std::string& stem);

/// The three figures of every DOF of `result` with a fit ("identification-<dof>-...") and, after
/// --method rls, the RLS convergence.
std::vector<Figure> IdentificationFigures(const ident::IdentifyResult& result);

}  // namespace uuvplan::report
