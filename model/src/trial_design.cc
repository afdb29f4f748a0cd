#include "uuvplan/model/trial_design.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/model/input_error.h"

namespace uuvplan::model {
namespace {

int Sign(double x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

const SegmentDesign* SegmentAt(const TrialDesign& d, double t) {
  const SegmentDesign* in_force = nullptr;
  double start = 0.0;
  for (const auto& s : d.segments) {
    if (in_force != nullptr && start > t) break;
    in_force = &s;
    start += s.duration;
  }
  return in_force;
}

int MappingOf(const Vehicle& v, const std::string& name, const TrialDesign& d) {
  if (name.empty()) return -1;
  const int i = v.MappingIndex(name);
  if (i < 0) {
    throw InputError("trial '" + d.id + "'",
                     "mapping '" + name + "' is not a mapping of vehicle '" + v.name + "'");
  }
  return i;
}

}  // namespace

std::string_view TrialKindName(TrialKind kind) { return kTrialKindNames.Name(kind); }
std::string_view InputFamilyName(InputFamily family) { return kInputFamilyNames.Name(family); }

namespace {
// The wave with mapping indices left unresolved (-1 / -2 stand for mapping / mapping_neg).
SwitchedWave WaveOf(const TrialDesign& d) {
  SwitchedWave w;
  w.offset = d.offset;
  w.components = d.components;
  w.floor_pos = d.floor_pos;
  w.floor_neg = d.floor_neg;
  w.mapping_pos = 0;
  w.mapping_neg = 1;
  return w;
}
// Bound of |w - offset|: Σ|a_i|.
double WaveSwing(const TrialDesign& d) {
  double s = 0.0;
  for (const auto& c : d.components) s += std::abs(c.amplitude);
  return s;
}
}  // namespace

double TrialDesign::NominalForce(double t) const {
  switch (kind) {
    case TrialKind::kSteady:
      return force;
    case TrialKind::kSine:
      return offset + amplitude * std::sin(omega * t);
    case TrialKind::kSegments: {
      const SegmentDesign* s = SegmentAt(*this, t);
      return s != nullptr ? s->force : 0.0;
    }
    case TrialKind::kSwitched: {
      int which = 0;
      return WaveOf(*this).Force(t, &which);
    }
  }
  return 0.0;
}

const std::string& TrialDesign::MappingAt(double t) const {
  if (kind == TrialKind::kSwitched) {
    int which = 0;
    WaveOf(*this).Force(t, &which);
    return which == 0 ? mapping : mapping_neg;
  }
  if (kind != TrialKind::kSegments) return mapping;
  const SegmentDesign* s = SegmentAt(*this, t);
  return s != nullptr && !s->mapping.empty() ? s->mapping : mapping;
}

std::vector<ForceDemand> TrialDesign::Demands() const {
  switch (kind) {
    case TrialKind::kSteady:
      return {{mapping, force, force}};
    case TrialKind::kSine:
      return {{mapping, offset - std::abs(amplitude), offset + std::abs(amplitude)}};
    case TrialKind::kSegments: {
      std::vector<ForceDemand> out;
      for (const auto& s : segments) {
        out.push_back({s.mapping.empty() ? mapping : s.mapping, s.force, s.force});
      }
      return out;
    }
    case TrialKind::kSwitched: {
      std::vector<ForceDemand> out;
      const double swing = WaveSwing(*this);
      if (offset + swing >= 0)
        out.push_back({mapping, floor_pos, std::max(floor_pos, offset + swing)});
      if (offset - swing < 0) {
        out.push_back({mapping_neg, std::min(-floor_neg, offset - swing), -floor_neg});
      }
      return out;
    }
  }
  return {};
}

bool TrialDesign::Pushes(const std::string& name, int sign) const {
  for (const ForceDemand& d : Demands()) {
    if (d.mapping == name && (Sign(d.max) == sign || Sign(d.min) == sign)) return true;
  }
  return false;
}

std::unique_ptr<Excitation> MakeExcitation(const Vehicle& vehicle, const TrialDesign& d) {
  const int mapping = MappingOf(vehicle, d.mapping, d);
  switch (d.kind) {
    case TrialKind::kSteady:
      return MakeSteadyExcitation(d.force, mapping, d.duration);
    case TrialKind::kSine:
      return MakeSineExcitation(d.offset, d.amplitude, d.omega, mapping, d.duration);
    case TrialKind::kSegments: {
      std::vector<Segment> segs;
      for (const auto& s : d.segments) {
        segs.push_back(
            {s.force, s.duration, s.mapping.empty() ? mapping : MappingOf(vehicle, s.mapping, d)});
      }
      return MakeSegmentsExcitation(std::move(segs));
    }
    case TrialKind::kSwitched:
      return MakeSwitchedExcitation(SwitchedWaveOf(vehicle, d), d.duration);
  }
  return nullptr;
}

SwitchedWave SwitchedWaveOf(const Vehicle& vehicle, const TrialDesign& d) {
  SwitchedWave w = WaveOf(d);
  w.mapping_pos = MappingOf(vehicle, d.mapping, d);
  w.mapping_neg = MappingOf(vehicle, d.mapping_neg, d);
  return w;
}

std::string CombinedTrialDesign::Check() const {
  const std::string where = "combined trial '" + id + "' (" + DofList(dofs) + ")";
  if (!(duration > 0)) return where + ": duration must be a positive number of seconds";
  for (Dof d : kAllDofs) {
    const long n = std::count_if(inputs.begin(), inputs.end(),
                                 [&](const TrialDesign& in) { return in.dof == d; });
    const long want = std::count(dofs.begin(), dofs.end(), d);
    if (n != want) {
      return where + ": expected " + (want ? "one input" : "no input") + " for " +
             std::string(DofName(d)) + ", found " + std::to_string(n);
    }
  }
  return "";
}

const TrialDesign* CombinedTrialDesign::InputOf(Dof dof) const {
  for (const TrialDesign& in : inputs) {
    if (in.dof == dof) return &in;
  }
  return nullptr;
}

}  // namespace uuvplan::model
