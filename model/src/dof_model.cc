#include "uuvplan/model/dof_model.h"

#include <cmath>

#include "dof_model_kernel.h"
#include "force_terms_impl.h"
#include "uuvplan/model/effects.h"
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

// The standard terms (ref 000 eq. 3): drag, constant force, thrust. Asymmetric drag's k_neg,
// kq_neg and the free η of installation loss enter these terms (EffectSite::kStandardTerm).
void DofModel::AdoptStandardTerms(const Vehicle& vehicle) {
  const ModelStructure& s = structure_;
  const bool linear = s.Has(param::kLinearDrag), quadratic = s.Has(param::kQuadraticDrag);
  const bool asymmetric = s.Has(param::kLinearDragNeg) || s.Has(param::kQuadraticDragNeg);
  if (linear || quadratic) {
    Adopt(std::make_unique<internal::DragTerm>(linear, quadratic, asymmetric), &drag_);
  }
  const bool bias = s.Has(param::kBias), ballast = s.Has(param::kBiasStep);
  if (bias || ballast) Adopt(std::make_unique<internal::ConstantTerm>(bias, ballast), &constant_);
  std::vector<std::string> mapping_names;
  for (const auto& m : vehicle.mappings) mapping_names.push_back(m.name);
  Adopt(internal::MakeThrust(mapping_names, s.WithPrefix(param::kEtaPrefix)), &thrust_);
}

// An effect's own force term, held by its final type where the simulation loop knows it.
void DofModel::AdoptEffectTerm(std::unique_ptr<ForceTerm> term) {
  const int offset = static_cast<int>(names_.size());
  ForceTerm* raw = term.get();
  if (auto* a = dynamic_cast<internal::AdvanceLossTerm*>(raw)) {
    advance_ = {a, offset};
  } else if (auto* c = dynamic_cast<internal::CouplingTerm*>(raw)) {
    coupling_ = {c, offset};
  } else if (auto* d = dynamic_cast<internal::DriftTerm*>(raw)) {
    drift_ = {d, offset};
  } else {
    others_.push_back({raw, offset});
  }
  needs_aux_ = needs_aux_ || raw->NeedsOtherVelocities();
  term_offsets_.push_back(offset);
  for (const auto& n : raw->parameter_names()) names_.push_back(n);
  terms_.push_back(std::move(term));
}

// theta = [m, standard terms, effects' force terms, actuator and sensor parameters], each
// group in the effect table's order (effects.h).
DofModel::DofModel(const Vehicle& vehicle, const ModelStructure& s) : structure_(s) {
  names_.push_back(param::kMass);
  AdoptStandardTerms(vehicle);
  const auto& effects = Effects().entries();
  for (const EffectEntry& e : effects) {
    if (e.site != EffectSite::kForceTerm) continue;
    if (const auto parameters = s.Of(e); !parameters.empty()) {
      AdoptEffectTerm(e.make_term(s.dof, parameters));
    }
  }
  for (const EffectEntry& e : effects) {
    if (e.site != EffectSite::kActuator && e.site != EffectSite::kSensor) continue;
    for (const std::string& p : s.Of(e)) names_.push_back(p);
  }
  for (const std::string& p : s.parameters) {
    if (ParameterIndex(p) < 0) {
      throw InputError(std::string(DofName(s.dof)), "parameter '" + p +
                                                        "' is not in the vocabulary of the model "
                                                        "(docs/formats.md)");
    }
  }
  lag_index_ = ParameterIndex(param::kLag);
  deadzone_index_ = ParameterIndex(param::kDeadzone);
  delay_index_ = ParameterIndex(param::kSensorDelay);
  thrust_exponent_index_ = ParameterIndex(param::kThrustExponent);
  thrust_reference_ = s.Setting(param::kThrustReference, 1.0);
  if (thrust_exponent_index_ >= 0 && !(thrust_reference_ > 0 && std::isfinite(thrust_reference_))) {
    throw InputError(std::string(DofName(s.dof)), "thrust reference force " +
                                                      std::to_string(thrust_reference_) +
                                                      ": expected a positive number");
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

TermInputs DofModel::TermInputsAt(double t, const double* x, const InputSample& in,
                                  const TrialConditions& c) const {
  return internal::DofModelKernel::TermInputsAt(*this, t, x, in, c);
}

double DofModel::TotalForce(const TermInputs& tc, const double* theta) const {
  return internal::DofModelKernel::TotalForce(*this, tc, theta);
}

void DofModel::Derivative(double t, const double* x, const InputSample& in,
                          const TrialConditions& c, const double* theta, double* dx) const {
  internal::DofModelKernel::Derivative(*this, t, x, in, c, theta,
                                       internal::DofModelKernel::Invert(*this, theta), dx);
}

void DofModel::Linearize(double t, const double* x, const InputSample& in, const TrialConditions& c,
                         const double* theta, double* dx, Eigen::Ref<Eigen::MatrixXd> A,
                         Eigen::Ref<Eigen::MatrixXd> B) const {
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
