// What drives a trial: the commanded nominal force phi_n(t) on the DOF and the thrust mapping
// in force, and the trial kinds of the contract's schedule (steady, sine, segments), plus a
// recorded log's commands held between rows (zero-order hold, notes/pitfalls.md).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/times_view.h"

namespace uuvplan::model {

/// A trial's commanded input. Its const methods may cache the last answer (the sines rotate
/// their last value, held samples remember their index): one object per thread.
class Excitation {
 public:
  virtual ~Excitation() = default;
  /// Commanded nominal force phi_n at time t (s from the trial start).
  virtual double Force(double t) const = 0;
  /// Vehicle mapping index in force at t (-1 = none).
  virtual int Mapping(double t) const = 0;
  /// Both at once (one lookup for held samples).
  virtual void Sample(double t, double* force, int* mapping) const {
    *force = Force(t);
    *mapping = Mapping(t);
  }
  /// Times in (0, duration), ascending, where Force or Mapping may jump; integration steps end
  /// there. A view of the excitation's own times, valid while it lives (a log whose force
  /// changes at every row has one a row: a copy per simulation cost 8 MB of new pages each).
  virtual TimesView Breakpoints() const { return {}; }
  /// True when Force and Mapping change only at Breakpoints() (steady, segments, held logs):
  /// the input is then constant over every integration step.
  virtual bool piecewise_constant() const { return false; }
  virtual double duration() const = 0;
};

/// phi_n = force from rest (contract §schedule `steady`).
std::unique_ptr<Excitation> MakeSteadyExcitation(double force, int mapping, double duration);
/// phi_n = offset + amplitude·sin(omega·t) (ref 000 eq. 15, contract §schedule `sine`).
std::unique_ptr<Excitation> MakeSineExcitation(double offset, double amplitude, double omega,
                                               int mapping, double duration);

struct Segment {
  double force = 0.0;
  double duration = 0.0;
  int mapping = -1;
};
/// Piecewise-constant force (contract §schedule `segments`).
std::unique_ptr<Excitation> MakeSegmentsExcitation(std::vector<Segment> segments);
/// Zero-order hold of samples (t_i, force_i, mapping_i): force_i holds on [t_i, t_{i+1}).
/// NaN forces are skipped (the previous value holds). Before t_0 the first value holds.
std::unique_ptr<Excitation> MakeHeldExcitation(TimesView t, const std::vector<double>& force,
                                               const std::vector<int>& mapping, double duration);
/// MakeHeldExcitation over the caller's rows, which are not copied when each is a command of
/// its own (no NaN force, none repeating the previous row's force and mapping, `mapping` as
/// long as `force`): `t`'s array (a clock is held by value), `force` and `mapping` must then
/// stay alive and unchanged while the excitation lives. A prepared trial's log of a force that
/// changes at every row: 28 bytes a row not held twice.
std::unique_ptr<Excitation> MakeHeldExcitationOver(TimesView t, const std::vector<double>& force,
                                                   const std::vector<int>& mapping,
                                                   double duration);

/// One sinusoid of a waveform: amplitude·sin(omega·t + phase).
struct SineComponent {
  double amplitude = 0.0;  ///< N or N·m
  double omega = 0.0;      ///< rad/s
  double phase = 0.0;      ///< rad
};

/// A mapping-switched waveform: w(t) = offset + Σ_i a_i·sin(ω_i·t + p_i). Where
/// w >= 0 the force is max(w, floor_pos) in mapping_pos, where w < 0 it is min(w, -floor_neg)
/// in mapping_neg: each sign in the mapping that pushes that way in open water (ref 000 Table
/// I), so no thruster reverses, and |phi_n| never drops below the floors (min_thrust / share:
/// at a zero crossing the force jumps from one mapping's floor to the other's).
struct SwitchedWave {
  double offset = 0.0;
  std::vector<SineComponent> components;
  double floor_pos = 0.0, floor_neg = 0.0;  ///< >= 0 (N or N·m)
  int mapping_pos = -1, mapping_neg = -1;

  double Wave(double t) const;
  /// phi_n(t) and the mapping in force.
  double Force(double t, int* mapping) const;
  /// The force and mapping for a wave value w (Force(t, ·) = Switch(Wave(t), ·)).
  double Switch(double w, int* mapping) const;
  /// Zero crossings of w in (0, duration) (where the mapping switches), to 1e-9 s.
  std::vector<double> Switches(double duration) const;
};
/// The switched waveform as an excitation; its switches are breakpoints.
std::unique_ptr<Excitation> MakeSwitchedExcitation(SwitchedWave wave, double duration);

/// Velocities of the other DOFs during a trial (for coupling terms): at time t, fills
/// v[Index(dof)] for every DOF other than the trial's own.
class AuxVelocities {
 public:
  virtual ~AuxVelocities() = default;
  virtual void At(double t, std::array<double, kNumDofs>* v) const = 0;
};

}  // namespace uuvplan::model
