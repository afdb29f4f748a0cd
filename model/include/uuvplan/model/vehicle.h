// A vehicle as the user describes it in vehicle.yaml (contract §Vehicle): mass, size,
// a priori inertia and added-mass bounds, thrusters, thrust mappings, per-DOF priors, sensors.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/mapping_derivation_options.h"
#include "uuvplan/model/speed_limits.h"
#include "uuvplan/model/thruster.h"

namespace uuvplan::model {

/// One measured signal of a DOF: its sampling rate and 1σ noise.
struct SensorSpec {
  double rate_hz = 10.0;
  double sigma = 0.01;  ///< m or rad (position), m/s or rad/s (velocity)
};

struct DofSensors {
  std::optional<SensorSpec> position;
  std::optional<SensorSpec> velocity;

  /// The shortest period (s) of a wave these sensors resolve with `samples_per_period` samples
  /// of the faster of them; 0 with no sensor.
  double ShortestPeriod(double samples_per_period) const {
    double rate = 0.0;
    for (const auto* spec : {&position, &velocity}) {
      if (*spec) rate = std::max(rate, (*spec)->rate_hz);
    }
    return rate > 0 ? samples_per_period / rate : 0.0;
  }
};

/// Fewest samples per period of the fastest wave a design holds. CHOSEN 10, the usual rule of
/// sampling at about ten times the bandwidth of interest (Ljung 1999, §13.7): the samples see
/// the wave's extremes within cos(π/10) = 95% of its amplitude, and half a sample of timing
/// error moves its phase by at most 18°. At 4 (a 1 s sine read at 4 Hz, once planned for a
/// BlueROV2) the planned information rests on a model of what falls between the samples.
inline constexpr double kDefaultSamplesPerPeriod = 10.0;

/// A priori drag fit of a DOF and its relative 1σ uncertainty.
struct DragPrior {
  double k = 0.0;   ///< N·s/m (N·m·s/rad)
  double kq = 0.0;  ///< N·s²/m² (N·m·s²/rad²)
  double rel_sigma = 0.3;
};

struct DofPrior {
  std::optional<DragPrior> drag;
  std::optional<std::array<double, 2>> added_mass;  ///< fraction of rigid-body value [lo, hi]
};

/// A DOF's model as a file gives it (dofs.<dof>.params, .effects and .sigma): the truth of a
/// virtual pool, or the identified model `identify --write-vehicle` or `diagnose
/// --write-vehicle` writes into a vehicle file.
struct DofParameters {
  std::map<std::string, double> params;    ///< values by vocabulary name (parameter.h)
  std::map<std::string, double> settings;  ///< structure settings of its effects (effects.h)
  /// 1σ of identified parameters by name; empty in a hand-written truth.
  std::map<std::string, double> sigma;
  /// Where a model with σ that no campaign identified comes from (the base's estimates with a
  /// payload's rules, payload.h); empty for an identified model or a truth.
  std::string origin;
  /// A model known to ±σ: identified, or derived from an identified one (`origin`).
  bool identified() const { return !sigma.empty(); }
};

struct Vehicle {
  std::string name;
  double mass = 0.0;                       ///< kg in air
  std::array<double, 3> size = {0, 0, 0};  ///< m: length, width, height
  std::map<Dof, double> inertia;           ///< kg·m², rigid body, optional per rotational DOF
  std::array<double, 2> added_mass = {0.1, 1.0};  ///< default a priori bounds (fraction)
  std::vector<Thruster> thrusters;
  double min_thrust = 0.0;   ///< N: smallest |tau| of a working thruster
  SpeedLimits speed_limits;  ///< max_translation_speed, max_rotation_rate
  std::vector<ThrustMapping>
      mappings;  ///< the file's table, then those derived (derived_mappings.h)
  MappingDerivationOptions mapping_derivation;  ///< jet_clearance, restoring
  std::map<Dof, DofPrior> priors;
  std::map<Dof, DofSensors> sensors;
  /// The model of each DOF whose parameters the file also gives (`dofs.<dof>.params`, effects
  /// and σ, as `identify`/`diagnose --write-vehicle` write them). The planner centres its box
  /// on an identified model (planner/design/parameter_box.h); `score` and `simulate` use it;
  /// identification starts from the a priori values and fits the standard model.
  std::map<Dof, DofParameters> models;

  /// Rigid-body inertia of a DOF: the mass for translations; for rotations the given
  /// inertia or that of a uniform box of `size` (ref 000 §IV-D: I_z = m(l² + w²)/12).
  double RigidInertia(Dof dof) const;
  /// A priori added-mass bounds of a DOF as fractions (per-DOF value or the default).
  std::array<double, 2> AddedMassBounds(Dof dof) const;
  /// A priori bounds on the total inertia m = rigid·(1 + added fraction).
  std::array<double, 2> InertiaBounds(Dof dof) const;
  /// Index of the mapping called `name`, or -1.
  int MappingIndex(const std::string& name) const;
  /// Index of the thruster called `name`, or -1.
  int ThrusterIndex(const std::string& name) const;
  /// Mappings acting on `dof`, in file order.
  std::vector<int> MappingsOf(Dof dof) const;
  /// Whether mapping `mapping` may push both ways within one trial: every thruster working in
  /// it is reversible (Thruster::reversible). False for a mapping with no working thruster.
  bool Reverses(int mapping) const;
  /// The least |tau| (N) a working thruster may be asked for: min_thrust, or the largest thrust
  /// at any thruster's dead band edge, either way, where that is larger (a design never idles in
  /// a dead band; one floor for every thruster, on the safe side).
  double WorkingThrustFloor() const;
};

}  // namespace uuvplan::model
