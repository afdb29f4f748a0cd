// Velocity from measured positions (and smoothing of measured velocities), as the papers do it:
//  - off-line Savitzky–Golay polynomial smoothing/differentiation (ref 000 §IV-D: 4th order,
//    symmetric windows of 21–41 points chosen per DOF and sampling rate), as local polynomial
//    least squares on the actual sample times so that jitter and drop-outs are handled; the
//    filter never crosses a gap, and the first and last half-window of every run are flagged as
//    edges (notes/pitfalls.md) and evaluated with the end polynomials;
//  - numerical differentiation followed by a second-order Butterworth low-pass applied forwards
//    and backwards (zero phase), as VSOR (ref 002 §6.1);
//  - the time scale of a logged input, and a sensor's noise from its samples.
// The steady-state segments and their speeds (ref 000 §III) are steady_detection.h's.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "uuvplan/ident/prepare/signal.h"

namespace uuvplan::ident {

struct SavitzkyGolayOptions {
  int order = 4;    ///< polynomial order (ref 000: 4)
  int window = 21;  ///< points, odd (ref 000: 21 for 3.3 Hz sonar, 41 for 10 Hz heading)
  /// A step longer than gap_factor × the median step starts a new run (never filtered across).
  double gap_factor = 3.0;
  bool IsValid(std::string* error) const;
};

/// The window ref 000 §IV-D would use at this sampling rate: about 4 s of samples, odd, within
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
/// (8 bytes a sample, not 16, on a million-sample log): the rounding, 6e-8 of the
/// value, is 10⁻⁴–10⁻⁶ of the filtered noise of any sensor the papers use (1 cm sonar at
/// 100 Hz gives mm/s of velocity noise), so no estimate moves by a visible fraction of its σ.
/// ForEachSmoothed hands out the doubles.
struct SmoothedSignal {
  SharedTimes t;                          ///< the times of the signal it was made from, shared
  std::vector<float> value;               ///< smoothed signal
  std::vector<float> derivative;          ///< its time derivative (NaN where a run is too short)
  std::vector<double> second_derivative;  ///< its second time derivative (NaN if unknown)
  std::vector<bool> edge;  ///< within half a window of a run end (trim before fitting)
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
double PositionNoiseAr1(const Signal& position, const SavitzkyGolayOptions& options, double sigma);

/// Second-order Butterworth low-pass (cutoff_hz) applied forwards and backwards (zero phase) to
/// uniformly sampled data at rate_hz; odd reflection at both ends.
std::vector<double> ButterworthFiltFilt(const std::vector<double>& y, double rate_hz,
                                        double cutoff_hz);

/// VSOR velocity (ref 002 §6.1): central differences of the positions, then the zero-phase
/// Butterworth low-pass; runs are split at gaps; irregular steps use the actual times.
SmoothedSignal ButterworthVelocity(const Signal& position, double cutoff_hz,
                                   double gap_factor = 3.0);

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
