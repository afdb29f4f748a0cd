// Thruster models of the papers: the force a single thruster produces for a command.
//   square (ref 000 eq. 6):  tau = c·V|V|, c = c_pos for V >= 0, c_neg for V < 0 (N/V²)
//   poly2  (ref 002 eq. 1):  tau = a·V² + b·V for V >= 0, odd-extended: tau(-V) = -tau(V)
// Both may carry a thrust deduction t (ref 003): tau_a = (1 - t)·tau. V is the command's distance
// from the thruster's neutral (the command at which it stops: 0 V, or 1500 µs for a PWM ESC).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "uuvplan/model/thruster_geometry.h"

namespace uuvplan::model {

struct ThrustModel {
  enum class Kind { kSquare, kPoly2 };
  Kind kind = Kind::kSquare;
  double c_pos = 1.0;      ///< square: N/V² for V >= 0
  double c_neg = 1.0;      ///< square: N/V² for V < 0
  double a = 1.0;          ///< poly2: N/V²
  double b = 0.0;          ///< poly2: N/V
  double deduction = 0.0;  ///< thrust deduction t in [0, 1) (ref 003)
  /// Commands with |V| below it give no thrust (command units, >= 0); beyond it the curve
  /// above holds as measured from neutral (a T200's ±25 µs about 1500 µs).
  double dead_band = 0.0;

  /// Thrust (N) for V, the command from neutral (command units, e.g. volts); 0 inside the
  /// dead band.
  double Thrust(double v) const;
  /// The V that gives `thrust` (N): the inverse of Thrust outside the dead band (both models
  /// are odd-signed and monotonic), in closed form; it may lie outside a thruster's command
  /// range, and inside the dead band for a thrust below EdgeThrust (which none then gives).
  double Command(double thrust) const;
  /// The least thrust magnitude (N) the thruster gives pushing with `sign` (+1 or -1): that at
  /// the dead band's edge, 0 without a dead band.
  double EdgeThrust(int sign) const;
};

struct Thruster {
  std::string name;
  ThrustModel model;
  double command_min = -1.0;  ///< lowest command (e.g. V, or µs of PWM)
  double command_max = 1.0;   ///< highest command
  double neutral = 0.0;       ///< the command at which it stops, in [command_min, command_max]
  /// Position and direction; absent when the vehicle file gives none (mappings from its table).
  std::optional<ThrusterGeometry> geometry;
  /// Built to run both ways in service (e.g. a T200). The papers' rule is false: a trial keeps
  /// each thruster's sign (ref 000 §II-B).
  bool reversible = false;

  /// Thrust (N) for a command as the thruster takes it: the model of its distance from neutral.
  double Thrust(double command) const { return model.Thrust(command - neutral); }
  /// The command as the thruster takes it that gives `thrust` (N); neutral for none.
  double Command(double thrust) const { return neutral + model.Command(thrust); }
  /// The command range as distances from neutral: the V range of its thrust model.
  std::array<double, 2> SpanFromNeutral() const {
    return {command_min - neutral, command_max - neutral};
  }

  /// Largest positive thrust over the command range (N, >= 0).
  double MaxForwardThrust() const;
  /// Largest reverse thrust magnitude over the command range (N, >= 0).
  double MaxReverseThrust() const;
};

}  // namespace uuvplan::model
