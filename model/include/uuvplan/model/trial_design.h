// One planned trial of a schedule (contract §schedule): steady, sine, segments or switched, on
// one DOF, from rest. The planner produces them, the virtual pool and the pool team run them.
//
// A design answers its own questions — the nominal force phi_n(t) and the mapping it commands
// at a time, the pushes it asks of each mapping (what excites which installation coefficient,
// what the thrusters must give) — so that callers need not switch on its kind.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

enum class TrialKind { kSteady, kSine, kSegments, kSwitched };
inline constexpr EnumNames<TrialKind, 4> kTrialKindNames{{{
    {TrialKind::kSteady, "steady"},
    {TrialKind::kSine, "sine"},
    {TrialKind::kSegments, "segments"},
    {TrialKind::kSwitched, "switched"},
}}};

/// The input family a trial was designed in (docs/planning.md §Designs): a plain
/// steady run, leg chain or single-mapping sine (ref 000), or one of the mapping-switched
/// families, where each sign of phi_n is pushed by the mapping that works in open water for it
/// (ref 000 Table I: surge-front forward, surge-rear backward), so the vehicle oscillates about
/// its start with no propeller reversing: a square wave (a `segments` trial alternating the two
/// mappings), a sine or a multi-sine (`switched` trials), and a free piecewise-constant
/// sequence (`segments`).
enum class InputFamily { kPlain, kSwitchedSquare, kSwitchedSine, kMultisine, kPiecewise };
inline constexpr EnumNames<InputFamily, 5> kInputFamilyNames{{{
    {InputFamily::kPlain, "plain"},
    {InputFamily::kSwitchedSquare, "switched-square"},
    {InputFamily::kSwitchedSine, "switched-sine"},
    {InputFamily::kMultisine, "multisine"},
    {InputFamily::kPiecewise, "piecewise"},
}}};

struct SegmentDesign {
  double force = 0.0;     ///< N or N·m
  double duration = 0.0;  ///< s
  std::string mapping;    ///< empty: the trial's mapping
};

/// One push of a trial: a mapping and the range of phi_n (N or N·m) it commands in it.
struct ForceDemand {
  std::string mapping;
  double min = 0.0;
  double max = 0.0;
};

struct TrialDesign {
  std::string id;
  Dof dof = Dof::kSurge;
  TrialKind kind = TrialKind::kSteady;
  std::string mapping;
  double duration = 0.0;  ///< s
  double force = 0.0;     ///< steady: constant phi_n
  double offset = 0.0;    ///< sine: phi_n = offset + amplitude·sin(omega·t)
  double amplitude = 0.0;
  double omega = 0.0;  ///< rad/s
  std::vector<SegmentDesign> segments;
  /// switched: phi_n from w(t) = offset + Σ components (excitation.h SwitchedWave): `mapping`
  /// where w >= 0 (|phi_n| >= floor_pos), `mapping_neg` where w < 0 (|phi_n| >= floor_neg).
  std::string mapping_neg;
  std::vector<SineComponent> components;
  double floor_pos = 0.0, floor_neg = 0.0;  ///< N or N·m
  InputFamily family = InputFamily::kPlain;
  int ballast_steps = 0;  ///< heave weight tests: known ballast steps during this trial

  /// Commanded nominal force phi_n(t) at t s from the start (contract §schedule; a segment
  /// holds from its start to the next one's, the last one after the end).
  double NominalForce(double t) const;
  /// The mapping in force at t (the trial's unless a segment names another).
  const std::string& MappingAt(double t) const;
  /// The trial's pushes: steady one (force), sine one (offset ± |amplitude|), segments one
  /// per segment (its mapping resolved), switched one per mapping its wave reaches (the floor
  /// to the wave's bound offset ± Σ|a_i|).
  std::vector<ForceDemand> Demands() const;
  /// Whether phi_n takes the sign `sign` (±1) in `mapping` at some time: what excites the
  /// installation coefficient of that direction.
  bool Pushes(const std::string& mapping, int sign) const;
};

/// A trial that pushes several DOFs at once (ref 003 Table I's combined modes): one input per
/// DOF of `dofs` (a design above in a mapping of that DOF; its own duration is ignored, the
/// trial's holds), all over `duration` from rest. The DOFs it does not move are commanded 0.
struct CombinedTrialDesign {
  std::string id;
  std::vector<Dof> dofs;  ///< the DOFs it moves: its mode (DofList: "surge+sway+yaw")
  double duration = 0.0;  ///< s
  std::vector<TrialDesign> inputs;

  /// "" when the inputs are exactly one per DOF of `dofs`, else what is wrong.
  std::string Check() const;
  /// The input that moves `dof`, or null.
  const TrialDesign* InputOf(Dof dof) const;
};

std::string_view TrialKindName(TrialKind kind);
std::string_view InputFamilyName(InputFamily family);
/// The switched wave of a `switched` design, mappings resolved in `vehicle` (InputError if one
/// is unknown).
SwitchedWave SwitchedWaveOf(const Vehicle& vehicle, const TrialDesign& design);

/// The excitation of a design; throws InputError if it names an unknown mapping.
std::unique_ptr<Excitation> MakeExcitation(const Vehicle& vehicle, const TrialDesign& design);

}  // namespace uuvplan::model
