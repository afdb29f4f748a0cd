// Percentile error and statistical significance of an estimate (seed 000 §III-A, §IV-D).
#pragma once

namespace uuvplan::ident {

/// Percentile parameter error 100·sigma/|theta| (seed 000, after eq. 12).
double PercentileError(double value, double sigma);

/// Seed 000 §IV-D: a parameter whose percentile error exceeds 100/1.96 = 51.02% is
/// statistically insignificant at 95% confidence (|theta|/sigma < z_0.975 = 1.96).
inline constexpr double kInsignificantPercentileError = 100.0 / 1.959963984540054;

/// True when |value| / sigma >= z_0.975, i.e. the percentile error is at most 51.02%.
bool IsSignificant(double value, double sigma);

}  // namespace uuvplan::ident
