// Physical plausibility of what input files give: a value may be a valid number and still
// nonsense for a pool trial (a 1e-300 kg vehicle, a 1e308 N force, a time column in ms). The
// ranges are wide (orders of magnitude): they catch 1e308, 1e-300 and unit slips, not unusual
// vehicles. Each is checked with the file, line and key in the message. An implausible value
// is refused (model::InputError, exit 2) unless the user accepted implausible values (`uuvplan
// --accept-implausible`): then it is a warning. The work limits (model/work_limits.h) hold
// either way.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <string_view>

#include "uuvplan/io/place.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// A quantity an input file gives that is not a model parameter, with the range any pool trial
/// has.
struct InputQuantity {
  std::string_view what;  ///< "a vehicle mass"
  std::string_view unit;  ///< "kg"
  double lower = 0.0;
  double upper = std::numeric_limits<double>::infinity();
  bool Holds(double x) const { return x >= lower && x <= upper; }
  /// "a vehicle mass in [0.01, 1e+07] kg".
  std::string Expected() const;
};

namespace plausible {
/// m/s²: weights are the scale of forces (ParameterScale).
inline constexpr double kGravity = 9.81;
// From a 10 g micro-robot to a 10,000 t submarine; sizes from 1 cm to 500 m.
inline constexpr InputQuantity kVehicleMass{"a vehicle mass", "kg", 0.01, 1e7};
inline constexpr InputQuantity kVehicleSize{"a vehicle dimension", "m", 0.01, 500};
/// Rotational inertia / (mass · largest dimension²): a uniform box is 1/12 = 0.083.
inline constexpr InputQuantity kInertiaRatio{"an inertia / (mass · size²)", "1", 1e-4, 10};
/// The largest thrust of one thruster / the vehicle's weight (a BlueROV's is about 0.5).
inline constexpr InputQuantity kThrustToWeight{"a thruster's largest thrust / weight", "1", 0, 100};
inline constexpr InputQuantity kSensorRate{"a sensor rate", "Hz", 0.01, 1e5};
/// Sensor noise σ / (the largest vehicle dimension, or 1 rad for an angle) and per second.
inline constexpr InputQuantity kSensorSigmaRatio{"a sensor σ / vehicle size (1 rad for angles)",
                                                 "1", 0, 100};
inline constexpr InputQuantity kPoolDimension{"a pool dimension", "m", 0.1, 1e5};
/// The deepest pool built is 60 m (Deep Dive Dubai); a depth above 100 m is a unit slip
/// (a 5 m pool written in cm) more likely than a pool.
inline constexpr InputQuantity kPoolDepth{"a pool depth", "m", 0.1, 100};
/// The clearance kept from the walls, floor and surface is about a vehicle length (cases/):
/// more than 20 m is a unit slip (1.5 m written in cm) more likely than a margin.
inline constexpr InputQuantity kPoolMargin{"a pool margin", "m", 0, 20};
/// A trial or leg from 1 ms to a day.
inline constexpr InputQuantity kDuration{"a duration", "s", 1e-3, 86400};
inline constexpr InputQuantity kIntegrationStep{"an integration step", "s", 1e-6, 1};
/// The interval between a log's rows: the time column in s (in ms every interval reads 1000×).
inline constexpr InputQuantity kSampleInterval{"a median sampling interval", "s", 1e-5, 10};
/// A logged force or torque / (weight, or weight × size): 1e308 in one cell is not a force.
inline constexpr InputQuantity kForceRatio{"a logged force / vehicle weight", "1", 0, 1000};
/// A payload's mass / the water it displaces: from foam (about 100) to tungsten (19,300); a
/// volume in litres where m³ are asked reads 1000× too light.
inline constexpr InputQuantity kPayloadDensity{"a payload's mean density (mass / volume)", "kg/m³",
                                               50, 25000};
/// The distance of a payload's centre from the base's / the base's largest dimension: more than
/// 10 is a unit slip (cm for m), not a payload.
inline constexpr InputQuantity kPayloadOffsetRatio{"a payload's offset / base size", "1", 0, 10};
}  // namespace plausible

/// From now on, an implausible value is passed to `warn` instead of refused (nullptr: refused).
/// The command line sets it once, for --accept-implausible.
void AcceptImplausible(std::function<void(const std::string& warning)> warn);

/// Refuses (or warns about) what `where` holds: "<where>: implausible: <what> (if it is
/// right, pass --accept-implausible)".
void Implausible(const Place& where, const std::string& what);

/// `x` must hold `quantity`.
void CheckPlausible(const Place& where, double x, const InputQuantity& quantity);

/// CheckPlausible for a length in m whose most likely slip is a smaller unit: the message
/// names cm or mm when x/100 or x/1000 m would be plausible ("is it in cm? 5 m would be").
void CheckPlausibleLength(const Place& where, double x, const InputQuantity& quantity);

/// A parameter value of `family` on `dof` of `vehicle`, relative to the vehicle's own scale
/// (M or M·L² for an inertia, M·g or M·g·L for a force at 1 m/s, (1 m/s)² or at rest):
/// m from 1e-3 of it to 50× (added mass is at most a few times the body's), drag forces up to
/// 100 weights, constant forces up to 10. Families without a range (effects') are not checked.
void CheckPlausibleParameter(const Place& where, double x, const model::ParameterFamily& family,
                             model::Dof dof, const model::Vehicle& vehicle);

/// A thruster's largest thrust against the weight of a vehicle of `mass` kg.
void CheckPlausibleThruster(const Place& where, const model::Thruster& thruster, double mass);

}  // namespace uuvplan::io
