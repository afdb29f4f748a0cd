// Trust in a DOF's estimates (loop_trust.h): physical ranges from the parameter families, the
// χ² consistency test of each new trial, and the validation of the identified model.
#include "loop/loop_trust.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/ident/stats/chi_square.h"
#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/parameter_box.h"

namespace uuvplan::planner {

std::string NonPhysical(const model::Vehicle& vehicle, model::Dof dof, const std::string& name,
                        double value) {
  const model::ParameterFamily* f = model::FamilyOf(name);
  if (f == nullptr) return "";
  const std::string unit = model::Unit(name, dof) == "1" ? "" : " " + model::Unit(name, dof);
  if (!f->Physical(value)) {
    return name + " = " + model::Significant(value, 4) + unit + " is non-physical (expected " +
           f->PhysicalExpected() + ")";
  }
  // Translations only: the dry mass is weighed (LeastInertia), a rotational inertia is computed
  // from an assumed mass distribution (ROMEO's file gives 93.75 kg·m² for a uniform box, the
  // seed measured 84 ± 5, §IV-D) and is no hard bound (the designs only stay above half of it).
  if (f->above_dry_mass && !model::IsRotational(dof) && value <= LeastInertia(vehicle, dof)) {
    return name + " = " + model::Significant(value, 4) + unit +
           " is non-physical (below the vehicle's dry mass " + model::Significant(vehicle.mass, 4) +
           unit + ": added mass is positive)";
  }
  return "";
}

namespace internal {
namespace {

bool Usable(const ident::DofIdentification& id, int j) {
  const ident::ParameterEstimate& p = id.params[j];
  return p.state == ident::ParameterState::kEstimated && std::isfinite(p.value) &&
         std::isfinite(p.sigma) && p.sigma > 0 && !Held(id, p.name) &&
         id.covariance.rows() == static_cast<int>(id.params.size());
}

}  // namespace

bool Held(const ident::DofIdentification& id, const std::string& name) {
  if (std::find(id.unreliable.begin(), id.unreliable.end(), name) != id.unreliable.end()) {
    return true;
  }
  const ident::ParameterEstimate* e = id.Param(name);
  return e != nullptr && e->state == ident::ParameterState::kFixed;
}

ConsistencyTest TestConsistency(const ident::DofIdentification& previous,
                                const ident::DofIdentification& current, double level) {
  ConsistencyTest t;
  t.level = level;
  std::vector<int> a, b;  // indices in previous, current
  std::vector<std::string> names;
  for (int j = 0; j < static_cast<int>(current.params.size()); ++j) {
    const int i = ident::FindEstimate(previous.params, current.params[j].name);
    if (i < 0 || !Usable(previous, i) || !Usable(current, j)) continue;
    // A variance the covariance holds as 0 (a parameter its fit held) tests nothing.
    if (!(previous.covariance(i, i) > 0) || !(current.covariance(j, j) > 0)) continue;
    a.push_back(i);
    b.push_back(j);
    names.push_back(current.params[j].name);
  }
  const int n = static_cast<int>(names.size());
  if (n == 0 || previous.status == ident::IdentifyStatus::kFailed ||
      current.status == ident::IdentifyStatus::kFailed) {
    t.text = "no earlier estimate to test the newest trial against";
    return t;
  }
  Eigen::VectorXd d(n);
  for (int r = 0; r < n; ++r) d(r) = current.params[b[r]].value - previous.params[a[r]].value;
  const Eigen::MatrixXd c =
      ident::SubMatrix(previous.covariance, a) + ident::SubMatrix(current.covariance, b);
  // Scaled to unit diagonal: parameters differ by orders of magnitude (kg against η).
  const Eigen::VectorXd s = c.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd z = s.asDiagonal() * d;
  const Eigen::MatrixXd cz = s.asDiagonal() * c * s.asDiagonal();
  t.chi2 = z.dot(cz.completeOrthogonalDecomposition().solve(z));
  if (!std::isfinite(t.chi2)) {
    t.text =
        "the newest trial cannot be tested against the estimate before it (their "
        "covariance is not finite)";
    return t;
  }
  t.tested = true;
  t.dof = n;
  t.p_value = ident::ChiSquareSurvival(t.chi2, n);
  t.consistent = t.p_value >= level;
  int w = 0;
  z.cwiseAbs().maxCoeff(&w);
  t.worst = names[w];
  t.worst_sigmas = z(w);
  t.text = "newest trial against the estimate before it: χ² = " + model::Significant(t.chi2, 3) +
           " on " + std::to_string(n) + " parameter(s), p = " + model::Significant(t.p_value, 2) +
           (t.consistent ? " (consistent at " : " (INCONSISTENT at ") +
           model::Significant(100 * level, 3) + "%; " + t.worst + " moved " +
           model::Significant(t.worst_sigmas, 2) + " combined σ)";
  return t;
}

std::vector<std::string> ValidationDoubts(const ident::DofIdentification& id,
                                          double max_residual_lag1) {
  std::vector<std::string> out;
  if (id.status == ident::IdentifyStatus::kFailed) {
    out.push_back("identification failed: " + id.message);
    return out;
  }
  for (const auto& t : id.fit.trials) {
    if (!std::isfinite(t.velocity_mae)) {
      out.push_back("the free run of " + t.name + " with the identified model diverges");
      break;
    }
  }
  if (id.output_error && id.output_error->ok() &&
      id.output_error->residual_lag1 > max_residual_lag1) {
    out.push_back(
        "the model does not explain the measurements to their noise (output-error "
        "residuals' lag-1 autocorrelation " +
        model::Significant(id.output_error->residual_lag1, 3) + " > " +
        model::Significant(max_residual_lag1, 3) + ")");
  }
  return out;
}

}  // namespace internal
}  // namespace uuvplan::planner
