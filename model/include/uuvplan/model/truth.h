// A truth file: a vehicle plus the true parameters and effects of each DOF (contract, last
// paragraph), and the sensor defects of the virtual pool.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

/// Exogenous velocity of another DOF during a trial, for coupling terms in the virtual pool:
/// v(t) = offset + amplitude·sin(omega·t).
struct AuxMotion {
  double offset = 0.0;
  double amplitude = 0.0;
  double omega = 0.0;  ///< rad/s
};

/// Defects of the virtual sensors (defaults: a clean but noisy sensor).
struct SensorDefects {
  double dropout_probability = 0.0;  ///< probability a sample is missing
  double outlier_probability = 0.0;  ///< probability of a multipath outlier (ref 000 Fig. 14)
  double outlier_size = 0.0;         ///< outlier offset magnitude (m or rad); 0 = 20σ
  /// Lag-1 correlation ρ of successive samples' noise of a sensor: AR(1) noise
  /// e_i = ρ·e_{i−1} + √(1 − ρ²)·σ·n_i (stationary variance σ²; 0 = white), |ρ| < 1.
  double noise_ar1 = 0.0;
};

struct DofTruth {
  /// True parameter values by vocabulary name (parameter.h), e.g. {"m": 890, "k": 46.9, ...}.
  std::map<std::string, double> params;
  /// Other DOFs' velocities during this DOF's trials (for coupling), by velocity letter.
  std::map<char, AuxMotion> aux_motion;
  /// Structure settings of its effects (effects.h EffectSetting), e.g. "thrust_reference".
  std::map<std::string, double> settings;
  /// σ of identified parameters by name (a model written by `diagnose --write-vehicle`);
  /// empty in a hand-written truth.
  std::map<std::string, double> sigma;
};

struct Truth {
  Vehicle vehicle;
  std::map<Dof, DofTruth> dofs;
  SensorDefects defects;
  double integration_step_s = 0.01;  ///< RK4 step of the virtual pool
};

}  // namespace uuvplan::model
