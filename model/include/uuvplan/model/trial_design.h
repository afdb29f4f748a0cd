// One planned trial of a schedule (contract §schedule): steady, sine or segments, on one DOF,
// from rest. The planner produces them, the virtual pool and the pool team run them.
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

enum class TrialKind { kSteady, kSine, kSegments };
inline constexpr EnumNames<TrialKind, 3> kTrialKindNames{{{
    {TrialKind::kSteady, "steady"},
    {TrialKind::kSine, "sine"},
    {TrialKind::kSegments, "segments"},
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
  double omega = 0.0;     ///< rad/s
  std::vector<SegmentDesign> segments;
  int ballast_steps = 0;  ///< heave weight tests: known ballast steps during this trial

  /// Commanded nominal force phi_n(t) at t s from the start (contract §schedule; a segment
  /// holds from its start to the next one's, the last one after the end).
  double NominalForce(double t) const;
  /// The mapping in force at t (the trial's unless a segment names another).
  const std::string& MappingAt(double t) const;
  /// The trial's pushes: steady one (force), sine one (offset ± |amplitude|), segments one
  /// per segment (its mapping resolved).
  std::vector<ForceDemand> Demands() const;
  /// Whether phi_n takes the sign `sign` (±1) in `mapping` at some time: what excites the
  /// installation coefficient of that direction.
  bool Pushes(const std::string& mapping, int sign) const;
};

std::string_view TrialKindName(TrialKind kind);

/// The excitation of a design; throws InputError if it names an unknown mapping.
std::unique_ptr<Excitation> MakeExcitation(const Vehicle& vehicle, const TrialDesign& design);

}  // namespace uuvplan::model
