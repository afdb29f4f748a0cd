// Identification's starting point: the model's one nominal-value policy (model/prior.h), with
// the user's initial guesses on top.
#include "uuvplan/ident/identify.h"
#include "uuvplan/model/prior.h"

namespace uuvplan::ident {

Eigen::VectorXd PriorTheta(const model::Vehicle& v, const model::DofModel& model,
                           const std::map<std::string, double>& guess) {
  const auto& names = model.parameter_names();
  std::map<std::string, double> values = model::NominalValues(v, model.dof(), names);
  for (const auto& [name, value] : guess) {
    if (values.count(name)) values[name] = value;
  }
  Eigen::VectorXd theta(model.num_parameters());
  for (int j = 0; j < model.num_parameters(); ++j) theta[j] = values.at(names[j]);
  return theta;
}

}  // namespace uuvplan::ident
