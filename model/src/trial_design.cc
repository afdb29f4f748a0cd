#include "uuvplan/model/trial_design.h"

#include "uuvplan/model/input_error.h"

namespace uuvplan::model {

std::string_view TrialKindName(TrialKind kind) {
  switch (kind) {
    case TrialKind::kSteady: return "steady";
    case TrialKind::kSine: return "sine";
    case TrialKind::kSegments: return "segments";
  }
  return "steady";
}

namespace {
int MappingOf(const Vehicle& v, const std::string& name, const TrialDesign& d) {
  if (name.empty()) return -1;
  const int i = v.MappingIndex(name);
  if (i < 0) {
    throw InputError("trial '" + d.id + "'", "mapping '" + name + "' is not a mapping of vehicle '" +
                                                 v.name + "'");
  }
  return i;
}
}  // namespace

std::unique_ptr<Excitation> MakeExcitation(const Vehicle& vehicle, const TrialDesign& d) {
  const int mapping = MappingOf(vehicle, d.mapping, d);
  switch (d.kind) {
    case TrialKind::kSteady: return MakeSteadyExcitation(d.force, mapping, d.duration);
    case TrialKind::kSine:
      return MakeSineExcitation(d.offset, d.amplitude, d.omega, mapping, d.duration);
    case TrialKind::kSegments: {
      std::vector<Segment> segs;
      for (const auto& s : d.segments) {
        segs.push_back({s.force, s.duration, s.mapping.empty() ? mapping : MappingOf(vehicle, s.mapping, d)});
      }
      return MakeSegmentsExcitation(std::move(segs));
    }
  }
  return nullptr;
}

}  // namespace uuvplan::model
