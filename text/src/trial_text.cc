// Trial designs for people (trial_text.h).
#include "uuvplan/text/trial_text.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "uuvplan/model/util/text.h"

namespace uuvplan::text {
namespace {

// Segments listed one by one up to this many; a longer square wave is summarised.
constexpr std::size_t kListedSegments = 4;

// "switched-square 1.2 N·m yaw-all / -0.4 N·m yaw-all, 97 pieces of 0.2–1.4 s": a square wave
// (switched_design.h) of more than kListedSegments pieces, by its two levels.
bool SquareText(const model::TrialDesign& d, const std::string& unit, std::ostream& s) {
  const bool square =
      d.family == model::InputFamily::kSwitchedSquare || d.family == model::InputFamily::kPiecewise;
  if (!square || d.segments.size() <= kListedSegments) return false;
  double shortest = d.segments.front().duration, longest = shortest;
  for (const auto& g : d.segments) {
    shortest = std::min(shortest, g.duration);
    longest = std::max(longest, g.duration);
  }
  const auto level = [&](const model::SegmentDesign& g) {
    return model::Significant(g.force, 3) + unit + " " +
           (g.mapping.empty() ? d.mapping : g.mapping);
  };
  s << model::InputFamilyName(d.family) << " " << level(d.segments[0]) << " / "
    << level(d.segments[1]) << ", " << d.segments.size() << " pieces of "
    << model::Significant(shortest, 2) << "–" << model::Significant(longest, 2) << " s";
  return true;
}

void SegmentsText(const model::TrialDesign& d, const ForceTextStyle& style, const std::string& unit,
                  std::ostream& s) {
  if (SquareText(d, unit, s)) return;
  for (std::size_t i = 0; i < d.segments.size(); ++i) {
    const auto& g = d.segments[i];
    const bool named =
        !g.mapping.empty() && (style.every_segment_mapping || g.mapping != d.mapping);
    s << (i ? " | " : "") << g.force << unit << " " << model::Significant(g.duration, 2)
      << style.segment_seconds << (named ? " " + g.mapping : "");
  }
}

// "switched-sine 10.0 + 120.0·sin(0.21t + 0.00) N, surge-front / surge-rear".
void SwitchedText(const model::TrialDesign& d, const std::string& unit, std::ostream& s) {
  s << model::InputFamilyName(d.family) << " " << d.offset;
  for (const auto& c : d.components) {
    s << " + " << std::abs(c.amplitude) << "·sin(" << std::setprecision(3) << c.omega << "t + "
      << std::setprecision(2) << c.phase << ")" << std::setprecision(1);
  }
  s << unit << ", " << d.mapping << " / " << d.mapping_neg;
}

}  // namespace

std::string ForceText(const model::TrialDesign& d, const ForceTextStyle& style) {
  const std::string unit = style.unit ? " " + std::string(model::ForceUnit(d.dof)) : "";
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  switch (d.kind) {
    case model::TrialKind::kSteady:
      s << d.force << unit;
      break;
    case model::TrialKind::kSine:
      s << d.offset << " ± " << d.amplitude << unit;
      if (style.sine_omega) {
        s << ", ω " << std::setprecision(3) << d.omega << " rad/s (T " << std::setprecision(1)
          << 2 * M_PI / d.omega << " s)";
      } else {
        s << ", T " << 2 * M_PI / d.omega << " s";
      }
      break;
    case model::TrialKind::kSegments:
      SegmentsText(d, style, unit, s);
      break;
    case model::TrialKind::kSwitched:
      SwitchedText(d, unit, s);
      break;
  }
  return s.str();
}

std::string TravelText(model::Dof dof, double lo, double hi) {
  if (!model::IsRotational(dof)) {
    return "[" + model::Significant(lo, 3) + ", " + model::Significant(hi, 3) + "] m";
  }
  const double to_degrees = 180.0 / M_PI;
  std::string text = "[" + model::Significant(lo * to_degrees, 4) + "°, " +
                     model::Significant(hi * to_degrees, 4) + "°]";
  const double turns = std::max(std::abs(lo), std::abs(hi)) / (2 * M_PI);
  if (turns >= 1.0) text += " (" + model::Significant(turns, 3) + " turns)";
  return text;
}

std::string TrialLine(const model::TrialDesign& d) {
  std::ostringstream s;
  s << std::left << std::setw(9) << model::TrialKindName(d.kind) << std::setw(22) << d.mapping
    << std::right << std::setw(9) << model::DurationText(d.duration) << "  "
    << ForceText(d, kLoopForceStyle);
  if (d.ballast_steps != 0) s << ", ballast " << d.ballast_steps;
  return s.str();
}

}  // namespace uuvplan::text
