#include "diagnosis_internal.h"

namespace uuvplan::ident::diagnosis {

// Every parameter starts at `start` where given, else at its null value ("no effect"); those in
// `fixed` are held at their value there.
StructureFit FitStructure(const model::Vehicle& vehicle, const model::ModelStructure& structure,
                          const Trials& trials, const Values& start,
                          const std::set<std::string>& dropped, const OutputErrorOptions& options,
                          const Values& fixed) {
  StructureFit f;
  f.structure = structure;
  f.model = std::make_shared<model::DofModel>(vehicle, structure);
  f.dropped = dropped;
  const int np = f.model->num_parameters();
  Eigen::VectorXd theta0(np);
  std::vector<ParameterState> state(np, ParameterState::kEstimated);
  for (int i = 0; i < np; ++i) {
    const std::string& n = f.model->parameter_names()[i];
    const auto it = start.find(n);
    theta0[i] = it != start.end() ? it->second : model::NullValue(n);
    if (dropped.count(n)) {
      state[i] = ParameterState::kDropped;
      theta0[i] = 0.0;
    } else if (const auto held = fixed.find(n); held != fixed.end()) {
      state[i] = ParameterState::kFixed;
      theta0[i] = held->second;
    }
  }
  OutputErrorOptions o = options;
  o.prune_insignificant = false;  // structures are compared as given
  f.oe = OutputErrorFit(*f.model, trials, theta0, state, o);
  for (int i = 0; i < np; ++i) f.values[f.model->parameter_names()[i]] = f.oe.theta[i];
  for (const auto& s : f.oe.state) f.free_parameters += s == ParameterState::kEstimated;
  for (const auto& init : f.oe.initial) {
    f.free_parameters += init.chi0_estimated + init.xi0_estimated;
  }
  return f;
}

}  // namespace uuvplan::ident::diagnosis
