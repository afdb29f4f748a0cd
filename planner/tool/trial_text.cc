#include "trial_text.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace uuvplan::tool {
namespace {

void SegmentsText(const model::TrialDesign& d, const ForceTextStyle& style,
                  const std::string& unit, std::ostream& s) {
  for (std::size_t i = 0; i < d.segments.size(); ++i) {
    const auto& g = d.segments[i];
    const bool named = !g.mapping.empty() && (style.every_segment_mapping || g.mapping != d.mapping);
    s << (i ? " | " : "") << g.force << unit << " " << std::setprecision(0) << g.duration
      << style.segment_seconds << std::setprecision(1) << (named ? " " + g.mapping : "");
  }
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
        s << ", ω " << std::setprecision(3) << d.omega << " (T " << std::setprecision(1)
          << 2 * M_PI / d.omega << " s)";
      } else {
        s << ", T " << 2 * M_PI / d.omega << " s";
      }
      break;
    case model::TrialKind::kSegments:
      SegmentsText(d, style, unit, s);
      break;
  }
  return s.str();
}

}  // namespace uuvplan::tool
