#include "uuvplan/model/thrust_reference.h"

#include <cmath>
#include <string>

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::model {
namespace {

// The terms on the vehicle's side of the force balance (the header's list).
bool ScalesWithThrust(const std::string& name) {
  for (const char* n : {param::kMass, param::kLinearDrag, param::kQuadraticDrag, param::kBias,
                        param::kBiasStep, param::kLinearDragNeg, param::kQuadraticDragNeg}) {
    if (name == n) return true;
  }
  return StartsWith(name, param::kCouplingPrefix);
}

}  // namespace

bool RestateThrustReference(double reference, DofParameters* model) {
  const auto p = model->params.find(param::kThrustExponent);
  const auto r = model->settings.find(param::kThrustReference);
  if (p == model->params.end() || r == model->settings.end() || r->second == reference) {
    return false;
  }
  const double c = std::pow(reference / r->second, p->second);
  for (auto& [name, value] : model->params) {
    // The advance-speed loss c_a·√|φ|·ξ: the delivered force is c times the restated one, so
    // c_a·√c·√|φ'|·ξ, divided by c: c_a/√c.
    const double scale = ScalesWithThrust(name)        ? c
                         : name == param::kAdvanceLoss ? std::sqrt(c)
                                                       : 1.0;
    value /= scale;
    if (auto s = model->sigma.find(name); s != model->sigma.end()) s->second /= scale;
  }
  r->second = reference;
  return true;
}

}  // namespace uuvplan::model
