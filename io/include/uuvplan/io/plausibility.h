// Physical plausibility of what input files give (issue #15): a value may be a valid number
// and still nonsense for a pool trial (a 1e-300 kg vehicle, a 1e308 N force, a time column in
// ms). The ranges are the model's (model/parameter.h: InputQuantity and the families'
// plausible ratios, scaled by the vehicle); this file applies them with the file, line and key
// in the message. An implausible value is refused (model::InputError, exit 2) unless the user
// accepted implausible values (`uuvplan --accept-implausible`): then it is a warning. The work
// limits (model/work_limits.h) hold either way.
#pragma once

#include <functional>
#include <string>

#include "uuvplan/io/place.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// From now on, an implausible value is passed to `warn` instead of refused (nullptr: refused).
/// The command line sets it once, for --accept-implausible.
void AcceptImplausible(std::function<void(const std::string& warning)> warn);

/// Refuses (or warns about) what `where` holds: "<where>: implausible: <what> (if it is
/// right, pass --accept-implausible)".
void Implausible(const Place& where, const std::string& what);

/// `x` must hold `quantity`.
void CheckPlausible(const Place& where, double x, const model::InputQuantity& quantity);

/// CheckPlausible for a length in m whose most likely slip is a smaller unit: the message
/// names cm or mm when x/100 or x/1000 m would be plausible ("is it in cm? 5 m would be").
void CheckPlausibleLength(const Place& where, double x, const model::InputQuantity& quantity);

/// A parameter value of `family` on `dof` of `vehicle`, against the family's plausible ratio to
/// the vehicle's scale (model::PlausibleScale).
void CheckPlausibleParameter(const Place& where, double x, const model::ParameterFamily& family,
                             model::Dof dof, const model::Vehicle& vehicle);

/// A thruster's largest thrust against the weight of a vehicle of `mass` kg.
void CheckPlausibleThruster(const Place& where, const model::Thruster& thruster, double mass);

}  // namespace uuvplan::io
