// A payload on a known vehicle (payload.h; the rules in docs/planning.md, "A payload on a known
// vehicle").
#include "uuvplan/model/payload.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/prior.h"

namespace uuvplan::model {
namespace {

bool IsDrag(const std::string& name) {
  return name == param::kLinearDrag || name == param::kQuadraticDrag ||
         name == param::kLinearDragNeg || name == param::kQuadraticDragNeg;
}

double SigmaOf(const DofParameters& model, const std::string& name) {
  const auto it = model.sigma.find(name);
  return it == model.sigma.end() ? 0.0 : it->second;
}

// A parameter known to lie in [lo, hi] written as value ± σ: the middle, σ = (hi − lo)/6, so
// that the planner's ± 3σ box (BoxOptions::estimate_sigmas) is [lo, hi] again.
void SetRange(const std::string& name, double lo, double hi, DofParameters* model) {
  model->params[name] = 0.5 * (lo + hi);
  model->sigma[name] = (hi - lo) / 6.0;
}

// The base's value ± 3σ, then the payload's change: m + [add_lo, add_hi].
void AddRange(const std::string& name, double add_lo, double add_hi, DofParameters* model) {
  const double v = model->params.at(name), s3 = 3.0 * SigmaOf(*model, name);
  SetRange(name, v - s3 + add_lo, v + s3 + add_hi, model);
}

// The base's value ± 3σ (not below 0), then scaled by [f_lo, f_hi]: a drag coefficient.
void ScaleRange(const std::string& name, const std::array<double, 2>& f, DofParameters* model) {
  const double v = model->params.at(name), s3 = 3.0 * SigmaOf(*model, name);
  SetRange(name, std::max(0.0, v - s3) * f[0], (v + s3) * f[1], model);
}

// "<mapping>.<pos|neg>" → the mapping loses that open-water direction.
void Block(const std::string& qualifier, Vehicle* vehicle) {
  const auto q = ParseEtaQualifier(qualifier);
  const int index = q ? vehicle->MappingIndex(q->first) : -1;
  if (index < 0) {
    throw InputError("payload.blocks",
                     "expected <mapping>.<pos|neg> of the base, got '" + qualifier + "'");
  }
  OpenWater& ow = vehicle->mappings[index].open_water;
  const bool pos = q->second == Direction::kPos;
  if (ow == OpenWater::kBoth) {
    ow = pos ? OpenWater::kNegative : OpenWater::kPositive;
  } else if (ow == (pos ? OpenWater::kPositive : OpenWater::kNegative)) {
    ow = OpenWater::kNone;
  }
}

// The base's model of `dof` with the payload: inertia + the payload's rigid inertia times
// (1 + its added-mass range), drag × DragFactorRange, the heave bias + the payload's weight
// less its buoyancy, the blocked η unknown again; thruster and sensor effects as the base's.
DofParameters PayloadModel(DofParameters model, const Payload& payload, Dof dof,
                           const std::array<double, 2>& drag, const std::string& origin) {
  model.origin = origin;
  const double rigid = PayloadRigidInertia(payload, dof);
  if (model.params.count(param::kMass)) {
    AddRange(param::kMass, rigid * (1.0 + payload.added_mass[0]),
             rigid * (1.0 + payload.added_mass[1]), &model);
  }
  for (auto& [name, value] : model.params) {
    if (IsDrag(name)) ScaleRange(name, drag, &model);
  }
  if (auto bias = model.params.find(param::kBias); bias != model.params.end()) {
    bias->second += PayloadBiasChange(payload, dof);
  }
  for (const std::string& blocked : payload.blocks) {
    const std::string eta = param::kEtaPrefix + blocked;
    model.params.erase(eta);
    model.sigma.erase(eta);
  }
  return model;
}

// An a priori drag fit k, kq ± rel_sigma scaled by [f_lo, f_hi]: the middle of the scaled
// range, its half-width relative to it.
DragPrior ScaledDrag(const DragPrior& d, const std::array<double, 2>& f) {
  const double lo = std::max(0.0, 1.0 - d.rel_sigma) * f[0], hi = (1.0 + d.rel_sigma) * f[1];
  const double mid = 0.5 * (lo + hi);
  return {d.k * mid, d.kq * mid, (hi - lo) / (hi + lo)};
}

}  // namespace

std::array<double, 3> CombinedSize(const std::array<double, 3>& base, const Payload& payload) {
  std::array<double, 3> size{};
  for (int i = 0; i < 3; ++i) {
    const double lo = std::min(-0.5 * base[i], payload.cg[i] - 0.5 * payload.size[i]);
    const double hi = std::max(0.5 * base[i], payload.cg[i] + 0.5 * payload.size[i]);
    size[i] = hi - lo;
  }
  return size;
}

// A box's inertia about its centre, m·(a² + b²)/12 (a, b its sides across the axis), plus
// m·d² for its centre at distance d from the axis through the base's origin.
double PayloadRigidInertia(const Payload& p, Dof dof) {
  const double l = p.size[0], w = p.size[1], h = p.size[2];
  const double x = p.cg[0], y = p.cg[1], z = p.cg[2];
  switch (dof) {
    case Dof::kRoll:
      return p.mass * ((w * w + h * h) / 12.0 + y * y + z * z);
    case Dof::kPitch:
      return p.mass * ((l * l + h * h) / 12.0 + x * x + z * z);
    case Dof::kYaw:
      return p.mass * ((l * l + w * w) / 12.0 + x * x + y * y);
    default:
      return p.mass;
  }
}

std::array<double, 2> DragFactorRange(const std::array<double, 3>& base_size,
                                      const std::array<double, 3>& combined_size, Dof dof) {
  const double ratio =
      BluffBodyQuadraticDrag(combined_size, dof) / BluffBodyQuadraticDrag(base_size, dof);
  return {1.0, std::max(1.0, ratio)};
}

double PayloadBiasChange(const Payload& payload, Dof dof) {
  if (dof != Dof::kHeave) return 0.0;
  return (payload.mass - kPoolWaterDensity * payload.volume) * kGravity;
}

Vehicle WithPayload(const Vehicle& base, const Payload& payload, const std::string& name,
                    const std::string& origin) {
  Vehicle v = base;
  v.name = name;
  v.mass = base.mass + payload.mass;
  v.size = CombinedSize(base.size, payload);
  for (Dof dof : {Dof::kRoll, Dof::kPitch, Dof::kYaw}) {
    v.inertia[dof] = base.RigidInertia(dof) + PayloadRigidInertia(payload, dof);
  }
  for (const std::string& blocked : payload.blocks) Block(blocked, &v);
  for (auto& [dof, model] : v.models) {
    model = PayloadModel(model, payload, dof, DragFactorRange(base.size, v.size, dof), origin);
  }
  for (auto& [dof, prior] : v.priors) {
    if (prior.drag) prior.drag = ScaledDrag(*prior.drag, DragFactorRange(base.size, v.size, dof));
  }
  return v;
}

}  // namespace uuvplan::model
