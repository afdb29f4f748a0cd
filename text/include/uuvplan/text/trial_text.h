// How a trial design reads in the commands' tables and lines: the one printer of the
// three kinds (steady, sine, segments), so a kind prints the same way wherever it is listed.
// Numbers are fixed-point with one decimal (segment durations whole seconds); the tables
// differ only in what they show beside the forces (ForceTextStyle).
#pragma once

#include <string>

#include "uuvplan/model/trial_design.h"

namespace uuvplan::text {

struct ForceTextStyle {
  bool unit = false;                   ///< the DOF's force unit after each force ("35.0 N")
  bool sine_omega = false;             ///< sine: ", ω 0.262 (T 24.0 s)" rather than ", T 24.0 s"
  const char* segment_seconds = " s";  ///< after a segment's duration ("10 s" or "10s")
  /// Name every segment's mapping, or only one other than the trial's.
  bool every_segment_mapping = false;
};

/// The schedule table's force column: "35.0 N"; "-5.0 ± 4.0 N·m, ω 0.262 rad/s (T 24.0 s)";
/// "60.0 N 10 s vertical-all | -60.0 N 10 s vertical-all".
inline constexpr ForceTextStyle kScheduleForceStyle{true, true, " s", true};
/// The loop's trial lines: "35.0 N"; "-5.0 ± 4.0 N, T 24.0 s"; "60.0 N 10 s | -60.0 N 10 s".
inline constexpr ForceTextStyle kLoopForceStyle{true, false, " s", false};

std::string ForceText(const model::TrialDesign& d, const ForceTextStyle& style);

/// A trial's travel for people: "[-0.12, 3.4] m", or for a rotation in degrees and turns
/// "[0°, 1080°] (3 turns)".
std::string TravelText(model::Dof dof, double lo, double hi);

/// "sine     surge-front            2:00 min  35.0 ± 25.0 N, T 26.0 s" — kind, mapping,
/// duration and force in fixed-width fields (the trial lines of `next` and `loop`).
std::string TrialLine(const model::TrialDesign& d);

}  // namespace uuvplan::text
