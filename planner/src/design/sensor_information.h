// What a vehicle's sensor tells the planner: a signal sampled at r Hz with white Gaussian noise
// of σ, so that each sample carries the Fisher information 1/σ² and a second of samples r/σ²
// (M = Σ_k w_k·S_kᵀ Σ⁻¹ S_k with Σ = σ², docs/planning.md "Fisher information"). The Fisher
// information of a trial, the design sensors, the steady legs' hold times and the coupled
// design's output weights all read the sensor through these.
#pragma once

#include <cmath>

#include "uuvplan/model/vehicle.h"

namespace uuvplan::planner {

/// σ², the variance of one sample (m², rad², (m/s)² or (rad/s)²).
inline double NoiseVariance(const model::SensorSpec& sensor) { return sensor.sigma * sensor.sigma; }

/// 1/σ², the Fisher information of one sample.
inline double SampleInformation(const model::SensorSpec& sensor) {
  return 1.0 / NoiseVariance(sensor);
}

/// r·span/σ², the Fisher information of the samples over `span` seconds.
inline double InformationOver(const model::SensorSpec& sensor, double span) {
  return sensor.rate_hz * span / NoiseVariance(sensor);
}

/// The sensor seen at no more than `rate` Hz: a faster one as the means of its samples over
/// 1/rate, σ·√(rate/r) at `rate`, which keeps its information per second r/σ².
inline model::SensorSpec AtMostRate(model::SensorSpec sensor, double rate) {
  if (sensor.rate_hz > rate) {
    sensor.sigma *= std::sqrt(rate / sensor.rate_hz);
    sensor.rate_hz = rate;
  }
  return sensor;
}

}  // namespace uuvplan::planner
