// The speed of a steady-state segment, as ref 000 §III measures it: the least-squares constant
// speed from positions alone (< 3% σ at 3 Hz sonar) or the mean of measured velocities, the
// settling fit that also models what remains of the transient, and their σ under AR(1) noise.
#pragma once

#include <memory>
#include <vector>

#include "uuvplan/ident/prepare/signal.h"

namespace uuvplan::ident {

struct ColumnBasis;  // covariance.h

/// The least-squares constant speed of a segment: chi(t) = c + v·t (ref 000 §III), or, from
/// velocity samples, their mean. sigma follows eqs. 11–12 (noise from the residuals) unless a
/// known noise σ is given; when the residuals are positively autocorrelated beyond chance
/// (lag-1 ρ > 2/√n), σ is inflated by √((1+ρ)/(1−ρ)).
struct SpeedFit {
  bool ok = false;
  double speed = 0.0;
  double sigma = 0.0;        ///< 1σ of the speed
  double offset = 0.0;       ///< c at the segment's mean time (position fits)
  double residual_sd = 0.0;  ///< standard deviation of the residuals
  double lag1 = 0.0;         ///< lag-1 autocorrelation of the residuals
  int n = 0;
  double t0 = 0.0, t1 = 0.0;
  int fitted = 0;               ///< coefficients fitted to the n samples
  std::vector<double> weights;  ///< speed = Σ weights_i·y_i over the n samples (linearised)
  /// An orthonormal basis of the fit's n × fitted columns (OrthonormalBasis; linearised):
  /// what the pooled noise AR(1) needs of them (PooledNoiseAr1), shared.
  std::shared_ptr<const ColumnBasis> basis;
};
SpeedFit ConstantSpeedFit(const Signal& position, double t0, double t1, double known_sigma = -1.0);
SpeedFit MeanSpeedFit(const Signal& velocity, double t0, double t1, double known_sigma = -1.0);

/// The steady speed of a segment that may still hold the tail of a transient: near a steady
/// speed v∞ the model (3) is linear, ξ(t) = v∞ + A·e^{−(t−t0)/τ} (τ = m/k_L, ref 000 eq. 13),
/// so chi(t) = c + v∞·(t − t̄) + B·e^{−(t−t0)/τ} (positions) or ξ(t) = v∞ + A·e^{−(t−t0)/τ}
/// (velocities) is fitted, τ by a profile search, and σ(v∞) from the Gauss–Newton covariance
/// of all four (three) parameters. A transient too small to detect by a constant-speed test
/// still biases a constant-speed fit by several σ when the segment is a few τ long; this fit
/// removes that bias. `tau`, `amplitude` describe the transient; chi2 = Σ r²/σ².
struct SettlingFit : SpeedFit {
  double tau = 0.0;
  double amplitude = 0.0;
  double amplitude_sigma = 0.0;
  double chi2 = 0.0;
  int dof = 0;
};
/// `fixed_tau` > 0 holds τ at that value (e.g. m/k_L from an identified model): the fit is
/// then linear in the other parameters and far more precise.
SettlingFit SettlingSpeedFit(const Signal& s, bool is_position, double t0, double t1,
                             double known_sigma, double fixed_tau = -1.0);

/// The AR(1) coefficient of a sensor's noise from the residuals of its steady-segment fits,
/// pooled and freed of the fits' bias (covariance.h, Ar1FromFittedResiduals).
double PooledNoiseAr1(const std::vector<const SpeedFit*>& fits);

/// σ of a fit's speed under AR(1) noise of marginal sd `noise_sigma` (≤ 0: the residuals'
/// sd) and coefficient ρ: σ² = noise_sigma²·wᵀΩw, Ω_ij = ρ^|i−j| (covariance.h,
/// Ar1QuadraticForm), exact for any segment length where √((1+ρ)/(1−ρ)) is the long-segment limit.
double Ar1SpeedSigma(const SpeedFit& fit, double rho, double noise_sigma);

}  // namespace uuvplan::ident
