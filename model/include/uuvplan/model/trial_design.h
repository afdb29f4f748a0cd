// One planned trial of a schedule (contract §schedule): steady, sine or segments, on one DOF,
// from rest. The planner produces them, the virtual pool and the pool team run them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

enum class TrialKind { kSteady, kSine, kSegments };

struct SegmentDesign {
  double force = 0.0;     ///< N or N·m
  double duration = 0.0;  ///< s
  std::string mapping;    ///< empty: the trial's mapping
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
};

std::string_view TrialKindName(TrialKind kind);

/// The excitation of a design; throws InputError if it names an unknown mapping.
std::unique_ptr<Excitation> MakeExcitation(const Vehicle& vehicle, const TrialDesign& design);

}  // namespace uuvplan::model
