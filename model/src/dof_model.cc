#include "uuvplan/model/dof_model.h"

#include <cmath>

#include "uuvplan/model/effects.h"
#include "dof_model_kernel.h"
#include "force_terms_impl.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::model {

template <typename T>
void DofModel::Adopt(std::unique_ptr<T> term, Typed<T>* typed) {
  typed->term = term.get();
  typed->offset = static_cast<int>(names_.size());
  term_offsets_.push_back(typed->offset);
  for (const auto& n : term->parameter_names()) names_.push_back(n);
  terms_.push_back(std::move(term));
}

DofModel::DofModel(const Vehicle& vehicle, const ModelStructure& s) : structure_(s) {
  names_.push_back(param::kMass);
  if (s.linear_drag || s.quadratic_drag) {
    Adopt(std::make_unique<internal::DragTerm>(s.linear_drag, s.quadratic_drag, s.asymmetric_drag),
          &drag_);
  }
  if (s.bias || s.ballast) {
    Adopt(std::make_unique<internal::ConstantTerm>(s.bias, s.ballast), &constant_);
  }
  std::vector<std::string> mapping_names;
  for (const auto& m : vehicle.mappings) mapping_names.push_back(m.name);
  Adopt(internal::MakeThrust(mapping_names, s.free_eta), &thrust_);
  if (s.advance_speed_loss) Adopt(std::make_unique<internal::AdvanceLossTerm>(), &advance_);
  if (!s.coupling.empty()) {
    Adopt(std::make_unique<internal::CouplingTerm>(s.dof, s.coupling), &coupling_);
  }
  if (s.parameter_drift) Adopt(std::make_unique<internal::DriftTerm>(), &drift_);
  needs_aux_ = !s.coupling.empty();

  if (s.thruster_lag) {
    lag_index_ = static_cast<int>(names_.size());
    names_.push_back(param::kLag);
  }
  if (s.deadzone) {
    deadzone_index_ = static_cast<int>(names_.size());
    names_.push_back(param::kDeadzone);
  }
  if (s.sensor_delay) {
    delay_index_ = static_cast<int>(names_.size());
    names_.push_back(param::kSensorDelay);
  }
  if (s.thrust_map) {
    if (!(s.thrust_reference > 0) || !std::isfinite(s.thrust_reference)) {
      throw InputError(std::string(DofName(s.dof)),
                       "thrust_map reference force " + std::to_string(s.thrust_reference) +
                           ": expected a positive number");
    }
    thrust_exponent_index_ = static_cast<int>(names_.size());
    names_.push_back(param::kThrustExponent);
  }
}

int DofModel::ParameterIndex(std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return static_cast<int>(i);
  }
  return -1;
}

Eigen::VectorXd DofModel::Theta(const std::map<std::string, double>& values,
                                const std::map<std::string, double>* fallback) const {
  Eigen::VectorXd theta(num_parameters());
  for (int i = 0; i < num_parameters(); ++i) {
    if (auto it = values.find(names_[i]); it != values.end()) {
      theta[i] = it->second;
    } else if (fallback && fallback->count(names_[i])) {
      theta[i] = fallback->at(names_[i]);
    } else {
      throw InputError(std::string(DofName(dof())), "no value for parameter '" + names_[i] + "'");
    }
  }
  return theta;
}

double DofModel::ActuatorInput(double phi_n, const double* theta) const {
  return internal::DofModelKernel::ActuatorInput(*this, phi_n, theta);
}

InputSample DofModel::SampleInput(double t, const TrialConditions& c, const double* theta) const {
  return internal::DofModelKernel::SampleInput(*this, t, c, theta);
}

TermContext DofModel::Context(double t, const double* x, const InputSample& in,
                              const TrialConditions& c) const {
  return internal::DofModelKernel::Context(*this, t, x, in, c);
}

double DofModel::TotalForce(const TermContext& tc, const double* theta) const {
  return internal::DofModelKernel::TotalForce(*this, tc, theta);
}

void DofModel::Derivative(double t, const double* x, const InputSample& in,
                          const TrialConditions& c, const double* theta, double* dx) const {
  internal::DofModelKernel::Derivative(*this, t, x, in, c, theta,
                                       internal::DofModelKernel::Invert(*this, theta), dx);
}

void DofModel::Linearize(double t, const double* x, const InputSample& in,
                         const TrialConditions& c, const double* theta, double* dx,
                         Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::MatrixXd> B) const {
  using Kernel = internal::DofModelKernel;
  const int nx = num_states(), np = num_parameters();
  double a[9];
  std::vector<double> b(static_cast<std::size_t>(nx * np));
  if (has_lag()) {
    Kernel::Linearize<3>(*this, t, x, in, c, theta, Kernel::Invert(*this, theta), dx, a, b.data());
  } else {
    Kernel::Linearize<2>(*this, t, x, in, c, theta, Kernel::Invert(*this, theta), dx, a, b.data());
  }
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < nx; ++j) A(i, j) = a[i * nx + j];
    for (int j = 0; j < np; ++j) B(i, j) = b[i * np + j];
  }
}

}  // namespace uuvplan::model
