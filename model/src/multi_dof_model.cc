#include "uuvplan/model/multi_dof_model.h"

#include "multi_dof_kernel.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::model {

MultiDofModel::MultiDofModel(const Vehicle& vehicle, const std::vector<ModelStructure>& structures,
                             const std::vector<ParameterTie>& ties) {
  offsets_.push_back(0);
  for (const ModelStructure& s : structures) {
    if (DofIndex(s.dof) >= 0) {
      throw InputError(std::string(DofName(s.dof)), "listed twice in a multi-DOF model");
    }
    dofs_.emplace_back(vehicle, s);
    offsets_.push_back(offsets_.back() + dofs_.back().num_states());
  }
  AddTies(ties);
  planar_ = DofIndex(Dof::kSurge) >= 0 && DofIndex(Dof::kSway) >= 0 && DofIndex(Dof::kYaw) >= 0;
}

// The global θ: DOF by DOF, every local parameter no tie defines; then T_i's entries of the
// tied ones, each a combination of global parameters.
void MultiDofModel::AddTies(const std::vector<ParameterTie>& ties) {
  std::vector<std::vector<const ParameterTie*>> tied(dofs_.size());
  for (std::size_t i = 0; i < dofs_.size(); ++i) tied[i].assign(dofs_[i].num_parameters(), nullptr);
  for (const ParameterTie& t : ties) {
    const int i = DofIndex(t.dof);
    const int j = i < 0 ? -1 : dofs_[i].ParameterIndex(t.parameter);
    if (j < 0) {
      throw InputError(std::string(DofName(t.dof)),
                       "a tie defines '" + t.parameter + "', which the model does not have");
    }
    tied[i][j] = &t;
  }
  ties_.resize(dofs_.size());
  for (std::size_t i = 0; i < dofs_.size(); ++i) {
    for (int j = 0; j < dofs_[i].num_parameters(); ++j) {
      if (tied[i][j]) continue;
      ties_[i].push_back({j, num_parameters(), 1.0});
      owner_.push_back({static_cast<int>(i), j});
      names_.push_back(std::string(DofName(dof(static_cast<int>(i)))) + "." +
                       dofs_[i].parameter_names()[j]);
    }
  }
  for (std::size_t i = 0; i < dofs_.size(); ++i) {
    for (int j = 0; j < dofs_[i].num_parameters(); ++j) {
      if (!tied[i][j]) continue;
      for (const auto& [name, coefficient] : tied[i][j]->terms) {
        const int g = ParameterIndex(name);
        if (g < 0)
          throw InputError(tied[i][j]->parameter, "tied to unknown parameter '" + name + "'");
        ties_[i].push_back({j, g, coefficient});
      }
    }
  }
}

int MultiDofModel::DofIndex(Dof d) const {
  for (int i = 0; i < num_dofs(); ++i) {
    if (dof(i) == d) return i;
  }
  return -1;
}

std::string MultiDofModel::PositionName(int i) const {
  if (planar_) {
    if (dof(i) == Dof::kSurge) return "x";
    if (dof(i) == Dof::kSway) return "y";
    if (dof(i) == Dof::kYaw) return "heading";
  }
  return std::string(DofName(dof(i)));
}

int MultiDofModel::ParameterIndex(std::string_view name) const {
  for (std::size_t j = 0; j < names_.size(); ++j) {
    if (names_[j] == name) return static_cast<int>(j);
  }
  return -1;
}

std::pair<Dof, std::string> MultiDofModel::LocalName(int j) const {
  const auto [i, local] = owner_[j];
  return {dof(i), dofs_[i].parameter_names()[local]};
}

std::string MultiDofModel::ParameterUnit(int j) const {
  const auto [d, local] = LocalName(j);
  return Unit(local, d);
}

Eigen::VectorXd MultiDofModel::LocalTheta(int i, const Eigen::VectorXd& theta) const {
  Eigen::VectorXd local = Eigen::VectorXd::Zero(dofs_[i].num_parameters());
  for (const TieEntry& e : ties_[i]) local[e.local] += e.coefficient * theta[e.global];
  return local;
}

Eigen::VectorXd MultiDofModel::Theta(const std::map<Dof, std::map<std::string, double>>& values,
                                     const std::map<std::string, double>* fallback) const {
  Eigen::VectorXd theta(num_parameters());
  for (int j = 0; j < num_parameters(); ++j) {
    const auto [d, local] = LocalName(j);
    const auto of_dof = values.find(d);
    if (of_dof != values.end() && of_dof->second.count(local)) {
      theta[j] = of_dof->second.at(local);
    } else if (fallback && fallback->count(local)) {
      theta[j] = fallback->at(local);
    } else {
      throw InputError(std::string(DofName(d)), "no value for parameter '" + local + "'");
    }
  }
  return theta;
}

std::string MultiDofModel::Inadmissible(const Eigen::VectorXd& theta) const {
  for (int j = 0; j < num_parameters(); ++j) {
    const ParameterFamily* family = FamilyOf(LocalName(j).second);
    if (family && family->Admissible(theta[j])) continue;
    return names_[j] + " = " + Significant(theta[j], 4) + " " + ParameterUnit(j) + " is not " +
           (family ? family->Expected() : "in the vocabulary");
  }
  return "";
}

Eigen::RowVectorXd MultiDofModel::EquationRegressor(
    int i, const Eigen::Ref<const Eigen::RowVectorXd>& nu) const {
  const DofModel& m = dofs_[i];
  TermInputs tc;
  tc.xi = nu[i];
  for (int j = 0; j < num_dofs(); ++j) tc.velocities[Index(dof(j))] = nu[j];
  std::vector<double> h(m.num_parameters(), 0.0);
  for (std::size_t k = 0; k < m.terms().size(); ++k) {
    double h0 = 0.0;
    m.terms()[k]->Regressor(tc, h.data() + m.term_offset(static_cast<int>(k)), &h0);
  }
  Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(num_parameters());
  for (const TieEntry& e : ties_[i]) r[e.global] -= h[e.local] * e.coefficient;
  return r;
}

void MultiDofModel::Derivative(double t, const double* x, const JointConditions& c,
                               const Eigen::VectorXd& theta, double* dx) const {
  const internal::JointSystem system(*this, c, theta);
  system.Derivative(t, x, system.Sample(t), dx);
}

void MultiDofModel::Linearize(double t, const double* x, const JointConditions& c,
                              const Eigen::VectorXd& theta, double* dx,
                              Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::MatrixXd> B) const {
  const internal::JointSystem system(*this, c, theta);
  const int nx = num_states(), np = num_parameters();
  std::vector<double> a(static_cast<std::size_t>(nx * nx)), b(static_cast<std::size_t>(nx * np));
  system.Linearize(t, x, system.Sample(t), dx, a.data(), b.data());
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < nx; ++j) A(i, j) = a[i * nx + j];
    for (int j = 0; j < np; ++j) B(i, j) = b[i * np + j];
  }
}

}  // namespace uuvplan::model
