// Percentile error and statistical significance of an estimate (ref 000 §III-A, §IV-D).
#pragma once

#include <limits>

namespace uuvplan::ident {

/// Percentile parameter error 100·sigma/|theta| (ref 000, after eq. 12).
double PercentileError(double value, double sigma);

/// Ref 000 §IV-D: a parameter whose percentile error exceeds 100/1.96 = 51.02% is
/// statistically insignificant at 95% confidence (|theta|/sigma < z_0.975 = 1.96).
inline constexpr double kInsignificantPercentileError = 100.0 / 1.959963984540054;

/// True when |value| / sigma >= z_0.975, i.e. the percentile error is at most 51.02%.
bool IsSignificant(double value, double sigma);

/// Model selection (model_selection.h): the largest |correlation| of an insignificant
/// parameter with the others for which it is dropped. Dropping θ_j fixes at 0 a value the data
/// cannot tell from 0 — true values up to 1.96 σ_j pass the 51.02% rule — and moves a
/// parameter k correlated at ρ by ρ·(σ_k/σ_j)·θ_j while its σ shrinks to σ_k·√(1 − ρ²): a bias
/// of up to 1.96·ρ/√(1 − ρ²) of the σ then reported, per drop. At ρ = 0.3 that is 0.62 σ (95%
/// intervals keep ≥ 90% coverage) and σ_k shrinks by 4.6%; collinear k and kq (ρ 0.9–0.99)
/// would be 4–14 σ off, more beyond (payload60 heave, bias −3 N dropped at
/// 0.26 ± 1.54, gave k 36.2 ± 0.66 for 20: 25 σ).
inline constexpr double kDropCorrelation = 0.3;
/// Ref 000 §IV-D's own rule drops whatever the correlation (`identify --seed-selection`).
inline constexpr double kSeedDropCorrelation = std::numeric_limits<double>::infinity();

}  // namespace uuvplan::ident
