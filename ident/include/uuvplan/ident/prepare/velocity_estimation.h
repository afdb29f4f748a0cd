// Velocity from measured positions (and smoothing of measured velocities), as the seeds do it:
//  - off-line Savitzky–Golay polynomial smoothing/differentiation (seed 000 §IV-D: 4th order,
//    symmetric windows of 21–41 points chosen per DOF and sampling rate), as local polynomial
//    least squares on the actual sample times so that jitter and drop-outs are handled; the
//    filter never crosses a gap, and the first and last half-window of every run are flagged as
//    edges (notes/pitfalls.md) and evaluated with the end polynomials;
//  - numerical differentiation followed by a second-order Butterworth low-pass applied forwards
//    and backwards (zero phase), as VSOR (seed 002 §6.1);
//  - the least-squares constant speed of a steady-state segment from positions alone
//    (seed 000 §III: < 3% σ at 3 Hz sonar), or the mean of measured velocities;
//  - automatic detection of the steady-state part of each constant-force piece: the speed must
//    have settled within the noise, tested on the data, never assumed after a fixed time.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "uuvplan/ident/prepare/shared_times.h"

namespace uuvplan::ident {

struct ColumnBasis;  // covariance.h

/// Samples of one signal: times (s) and values, no NaN.
struct Signal {
  SharedTimes t;  ///< shared with the signals made from this one (a velocity estimate's)
  std::vector<double> y;
  std::size_t size() const { return t.size(); }
  bool empty() const { return t.empty(); }
};

struct SavitzkyGolayOptions {
  int order = 4;    ///< polynomial order (seed 000: 4)
  int window = 21;  ///< points, odd (seed 000: 21 for 3.3 Hz sonar, 41 for 10 Hz heading)
  /// A step longer than gap_factor × the median step starts a new run (never filtered across).
  double gap_factor = 3.0;
  bool IsValid(std::string* error) const;
};

/// The window seed 000 §IV-D would use at this sampling rate: about 4 s of samples, odd, within
/// 21–41 points (3.33 Hz sonar → 21, 10 Hz heading/depth → 41). When the input changes faster
/// (`input_time_scale_s` > 0: the median leg of a piecewise-constant input, or the period of
/// a smooth one), the span is also kept below a quarter of it so that the filter follows the
/// motion (down to 9 points, the fewest a 4th-order fit can smooth with).
int SavitzkyGolayWindow(double rate_hz, double input_time_scale_s = 0.0);

/// The window a user gave (`given` > 0: `--sg-window`), else SavitzkyGolayWindow's.
int ChosenWindow(int given, double rate_hz, double input_time_scale_s);

/// The time scale of a logged input: the median duration of its constant pieces when it is
/// piecewise constant, else twice the median time between sign changes of its deviation from
/// the mean (the period of a sine). 0 when it cannot be told (constant input).
double InputTimeScale(model::TimesView t, const std::vector<double>& force);

/// A filter's output. Its value and derivative are computed in double and stored in float
/// (8 bytes a sample, not 16, on a million-sample log; issue #16): the rounding, 6e-8 of the
/// value, is 10⁻⁴–10⁻⁶ of the filtered noise of any sensor the seeds use (1 cm sonar at
/// 100 Hz gives mm/s of velocity noise), so no estimate moves by a visible fraction of its σ.
/// ForEachSmoothed hands out the doubles.
struct SmoothedSignal {
  SharedTimes t;                          ///< the times of the signal it was made from, shared
  std::vector<float> value;               ///< smoothed signal
  std::vector<float> derivative;          ///< its time derivative (NaN where a run is too short)
  std::vector<double> second_derivative;  ///< its second time derivative (NaN if unknown)
  std::vector<bool> edge;          ///< within half a window of a run end (trim before fitting)
  /// First sample of each run (runs are separated by gaps; the first starts at 0).
  std::vector<std::size_t> run_starts;
  /// The run of sample i.
  int run(std::size_t i) const;
  /// Noise gains of the centred filter: σ_value = gain·σ_input, σ_derivative = gain_d·σ_input
  /// (per second; for the median step of the first run).
  double value_gain = 1.0;
  double derivative_gain = 0.0;
  std::vector<double> derivative_weights;  ///< the centred filter's, per second (gain = norm)
  std::size_t size() const { return t.size(); }
};

/// Savitzky–Golay smoothing and differentiation of irregularly sampled data.
SmoothedSignal SavitzkyGolay(const Signal& s, const SavitzkyGolayOptions& options);

/// SavitzkyGolay one derivative up, for a rate from positions: `value` is the filter's
/// derivative, `derivative` its second derivative (second_derivative empty), the gains the
/// filter's; the smoothed signal itself is not stored (8 bytes a sample), only its first sample's
/// value, in `first_value` (NaN where a run is too short).
SmoothedSignal SavitzkyGolayRate(const Signal& s, const SavitzkyGolayOptions& options,
                                 double* first_value);

/// One sample of SavitzkyGolay's output (index i into s).
struct SmoothedSample {
  std::size_t i = 0;
  double value = 0.0, derivative = 0.0, second_derivative = 0.0;
  bool edge = true;
  int run = 0;
};
/// The samples SavitzkyGolay(s, options) computes, the same numbers, handed to `visit` in
/// order of i without storing them (a streaming check of a long log needs O(1) memory, not
/// the 36 bytes a sample of a SmoothedSignal).
void ForEachSmoothed(const Signal& s, const SavitzkyGolayOptions& options,
                     const std::function<void(const SmoothedSample&)>& visit);

/// The weights of one sample's Savitzky–Golay derivative: derivative_i = Σ_j w[j]·y[first + j]
/// (per second; empty where the run is too short for a derivative).
struct SampleWeights {
  std::size_t first = 0;
  std::vector<double> w;
};
/// The derivative weights SavitzkyGolay applied at samples [begin, end) of s (the same runs,
/// window, end polynomials and actual times): the linear map from the samples' noise to the
/// derivative's, for its exact variance σ²·wᵀΩw (covariance.h, Ar1QuadraticForm).
std::vector<SampleWeights> SavitzkyGolayDerivativeWeights(const Signal& s,
                                                         const SavitzkyGolayOptions& options,
                                                         std::size_t begin, std::size_t end);

/// The AR(1) coefficient of a position sensor's noise: the residuals of the filter's own local
/// polynomial (options.order) fitted to consecutive, non-overlapping windows of
/// options.window samples (the span over which the filter takes the motion to be a
/// polynomial), pooled and freed of the fits' bias: with the sensor's σ (> 0) from their
/// variance (Ar1FromResidualVariance), else from their lag-1 (Ar1FromFittedResiduals).
/// Unlike the differences of raw − smoothed (NoiseAr1FromDifferences), whose smoother follows
/// the slow part of the noise (0.5–0.66 read for 0.9), the bias of the fitted columns is
/// accounted for exactly.
double PositionNoiseAr1(const Signal& position, const SavitzkyGolayOptions& options,
                        double sigma);

/// Second-order Butterworth low-pass (cutoff_hz) applied forwards and backwards (zero phase) to
/// uniformly sampled data at rate_hz; odd reflection at both ends.
std::vector<double> ButterworthFiltFilt(const std::vector<double>& y, double rate_hz,
                                        double cutoff_hz);

/// VSOR velocity (seed 002 §6.1): central differences of the positions, then the zero-phase
/// Butterworth low-pass; runs are split at gaps; irregular steps use the actual times.
SmoothedSignal ButterworthVelocity(const Signal& position, double cutoff_hz,
                                   double gap_factor = 3.0);

/// The least-squares constant speed of a segment: chi(t) = c + v·t (seed 000 §III), or, from
/// velocity samples, their mean. sigma follows eqs. 11–12 (noise from the residuals) unless a
/// known noise σ is given; when the residuals are positively autocorrelated beyond chance
/// (lag-1 ρ > 2/√n), σ is inflated by √((1+ρ)/(1−ρ)).
struct SpeedFit {
  bool ok = false;
  double speed = 0.0;
  double sigma = 0.0;         ///< 1σ of the speed
  double offset = 0.0;        ///< c at the segment's mean time (position fits)
  double residual_sd = 0.0;   ///< standard deviation of the residuals
  double lag1 = 0.0;          ///< lag-1 autocorrelation of the residuals
  int n = 0;
  double t0 = 0.0, t1 = 0.0;
  int fitted = 0;                ///< coefficients fitted to the n samples
  std::vector<double> weights;   ///< speed = Σ weights_i·y_i over the n samples (linearised)
  /// An orthonormal basis of the fit's n × fitted columns (OrthonormalBasis; linearised):
  /// what the pooled noise AR(1) needs of them (PooledNoiseAr1), shared.
  std::shared_ptr<const ColumnBasis> basis;
};
SpeedFit ConstantSpeedFit(const Signal& position, double t0, double t1,
                          double known_sigma = -1.0);
SpeedFit MeanSpeedFit(const Signal& velocity, double t0, double t1, double known_sigma = -1.0);

/// The steady speed of a segment that may still hold the tail of a transient: near a steady
/// speed v∞ the model (3) is linear, ξ(t) = v∞ + A·e^{−(t−t0)/τ} (τ = m/k_L, seed 000 eq. 13),
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

/// A time interval during which the commanded force and mapping are constant.
struct ForcePiece {
  double t0 = 0.0, t1 = 0.0;
  double force = 0.0;
  int mapping = -1;
};

struct SteadyDetectionOptions {
  double min_duration_s = 5.0;  ///< shortest steady segment kept
  int min_samples = 10;         ///< fewest samples in a steady segment
  /// Settling test: the speed change across the segment (quadratic fit) and the difference of
  /// the two halves' speeds must both lie within z·σ.
  double z = 2.0;
  /// Candidate starts are tried every `stride` samples (0: automatic, about 200 candidates).
  int stride = 0;
  /// Fit the tail of the transient (SettlingSpeedFit) instead of a constant speed: the start
  /// is the first candidate whose settling fit is consistent with the noise (χ² within 2σ of
  /// its degrees of freedom). False: seed 000's constant-speed fit after the settling tests.
  bool transient_model = true;
  bool IsValid(std::string* error) const;
};

struct SteadySegment {
  int piece = -1;  ///< index into the pieces given
  SpeedFit fit;
  bool user_marked = false;
};

/// The settled tail of each constant-force piece, from positions (`is_position`) or measured
/// velocities. `known_sigma` is the sensor's noise (negative: estimated from residuals).
std::vector<SteadySegment> DetectSteadySegments(const Signal& s, bool is_position,
                                                const std::vector<ForcePiece>& pieces,
                                                const SteadyDetectionOptions& options,
                                                double known_sigma = -1.0);

/// Median of the steps t[i] − t[i−1] over [begin, end) (from at most ~20,000 evenly spread
/// steps of a long record).
double MedianStep(model::TimesView t, std::size_t begin, std::size_t end);

/// Linear interpolation of samples at time t (held constant beyond the ends).
template <class Real>
double Interpolate(model::TimesView t, const std::vector<Real>& y, double at);
extern template double Interpolate(model::TimesView, const std::vector<double>&, double);
extern template double Interpolate(model::TimesView, const std::vector<float>&, double);

/// Robust noise estimate of a sampled signal: 1.4826·MAD of the third differences / √20
/// (exact for white noise on a locally quadratic signal).
double NoiseSigmaFromDifferences(const Signal& s);

}  // namespace uuvplan::ident
