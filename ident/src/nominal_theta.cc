// The nominal-θ policy of identification: the a priori value of every parameter, where the
// estimators start.
#include "uuvplan/ident/identify.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

Eigen::VectorXd PriorTheta(const model::Vehicle& v, const model::DofModel& model,
                           const std::map<std::string, double>& guess) {
  const model::Dof dof = model.dof();
  const auto bounds = v.InertiaBounds(dof);
  const double m = 0.5 * (bounds[0] + bounds[1]) > 0 ? 0.5 * (bounds[0] + bounds[1]) : 1.0;
  double k = m / 5.0, kq = 0.0;  // a 5 s time constant when nothing is known
  if (auto it = v.priors.find(dof); it != v.priors.end() && it->second.drag) {
    k = it->second.drag->k;
    kq = it->second.drag->kq;
  }
  const auto& names = model.parameter_names();
  Eigen::VectorXd theta(model.num_parameters());
  for (int j = 0; j < model.num_parameters(); ++j) {
    const std::string& n = names[j];
    double value = 0.0;
    if (n == model::param::kMass) value = m;
    else if (n == model::param::kLinearDrag || n == model::param::kLinearDragNeg) value = k;
    else if (n == model::param::kQuadraticDrag || n == model::param::kQuadraticDragNeg) value = kq;
    else if (model::StartsWith(n, model::param::kEtaPrefix)) value = 1.0;
    else if (n == model::param::kLag) value = 0.1;
    if (auto g = guess.find(n); g != guess.end()) value = g->second;
    theta[j] = value;
  }
  return theta;
}

}  // namespace uuvplan::ident
