#include "uuvplan/model/dof_model.h"

#include <cmath>

#include "uuvplan/model/effects.h"
#include "force_terms_impl.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::model {

namespace {
constexpr int kMaxTermParameters = 64;  // scratch size for one term's partials
}

template <typename T>
void DofModel::Adopt(std::unique_ptr<T> term, Typed<T>* typed) {
  if (term->num_parameters() > kMaxTermParameters) {
    throw InputError(std::string(DofName(structure_.dof)),
                     "too many parameters in one term (" + std::to_string(term->num_parameters()) +
                         "); at most 64");
  }
  typed->term = term.get();
  typed->offset = static_cast<int>(names_.size());
  term_offsets_.push_back(typed->offset);
  for (const auto& n : term->parameter_names()) names_.push_back(n);
  terms_.push_back(std::move(term));
}

template <typename Visitor>
void DofModel::VisitTerms(Visitor&& visit) const {
  if (drag_.term) visit(*drag_.term, drag_.offset);
  if (constant_.term) visit(*constant_.term, constant_.offset);
  visit(*thrust_.term, thrust_.offset);
  if (advance_.term) visit(*advance_.term, advance_.offset);
  if (coupling_.term) visit(*coupling_.term, coupling_.offset);
  if (drift_.term) visit(*drift_.term, drift_.offset);
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
  if (deadzone_index_ < 0) return phi_n;
  const double d = theta[deadzone_index_];
  const double excess = std::abs(phi_n) - d;
  return excess > 0 ? std::copysign(excess, phi_n) : 0.0;
}

InputSample DofModel::SampleInput(double t, const TrialConditions& c) const {
  InputSample in;
  if (c.input) c.input->Sample(t, &in.phi_n, &in.mapping);
  if (needs_aux_ && c.aux) c.aux->At(t, &in.velocities);
  return in;
}

TermContext DofModel::Context(double t, const double* x, const InputSample& in,
                              const TrialConditions& c, const double* theta) const {
  TermContext tc;
  tc.xi = x[1];
  tc.phi = has_lag() ? x[2] : ActuatorInput(in.phi_n, theta);
  tc.mapping = in.mapping;
  tc.t_campaign = c.start_time + t;
  tc.ballast_steps = c.ballast_steps;
  if (needs_aux_) tc.velocities = in.velocities;
  return tc;
}

double DofModel::TotalForce(const TermContext& tc, const double* theta) const {
  // Summed as a tree, not left to right: the state-dependent terms (drag, advance loss,
  // coupling) then meet the others after two additions instead of five.
  auto value = [&](const auto& typed) {
    return typed.term ? typed.term->Value(tc, theta + typed.offset) : 0.0;
  };
  return (value(drag_) + value(advance_)) + (value(coupling_) + value(thrust_)) +
         (value(constant_) + value(drift_));
}

void DofModel::Derivative(double t, const double* x, const InputSample& in,
                          const TrialConditions& c, const double* theta, double* dx) const {
  // 1/m and 1/T do not depend on the state: as multipliers they stay off the RK4 stages'
  // dependency chain (a division there costs ~4× a multiplication in latency).
  const double inv_m = 1.0 / theta[0];
  const TermContext tc = Context(t, x, in, c, theta);
  dx[0] = x[1];
  dx[1] = TotalForce(tc, theta) * inv_m;
  if (has_lag()) {
    const double inv_T = 1.0 / theta[lag_index_];
    dx[2] = (ActuatorInput(in.phi_n, theta) - x[2]) * inv_T;
  }
}

void DofModel::Linearize(double t, const double* x, const InputSample& in,
                         const TrialConditions& c, const double* theta, double* dx,
                         Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::MatrixXd> B) const {
  const TermContext tc = Context(t, x, in, c, theta);
  const double m = theta[0];
  A.setZero();
  B.setZero();
  double force = 0.0, d_xi = 0.0, d_phi = 0.0;
  double J[kMaxTermParameters];
  VisitTerms([&](const auto& term, int offset) {
    const TermPartials p = term.Partials(tc, theta + offset, J);
    force += p.value;
    d_xi += p.d_xi;
    d_phi += p.d_phi;
    for (int i = 0; i < term.num_parameters(); ++i) B(1, offset + i) = J[i] / m;
  });
  dx[0] = x[1];
  dx[1] = force / m;
  A(0, 1) = 1.0;
  A(1, 1) = d_xi / m;
  B(1, 0) = -force / (m * m);

  const double phi_n = in.phi_n;
  const double u = ActuatorInput(phi_n, theta);
  // du/dd of the dead zone u = sign(phi_n)·max(|phi_n| - d, 0).
  const double du_dd =
      (deadzone_index_ >= 0 && std::abs(phi_n) > theta[deadzone_index_]) ? -std::copysign(1.0, phi_n)
                                                                          : 0.0;
  if (has_lag()) {
    const double T = theta[lag_index_];
    A(1, 2) = d_phi / m;
    A(2, 2) = -1.0 / T;
    dx[2] = (u - x[2]) / T;
    B(2, lag_index_) = -(u - x[2]) / (T * T);
    if (deadzone_index_ >= 0) B(2, deadzone_index_) = du_dd / T;
  } else if (deadzone_index_ >= 0) {
    B(1, deadzone_index_) = d_phi * du_dd / m;
  }
}

}  // namespace uuvplan::model
