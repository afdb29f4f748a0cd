// Optimal-design criteria on a Fisher information matrix (Walter & Pronzato, "Identification
// of parametric models", ch. 6; ref 000 §III-B for D). Every criterion is written so that
// larger is better and in logarithmic form:
//
//   D   log det M                                  (ref 000: J = -log det M minimised)
//   Ds  log det (M_ss - M_sn M_nn⁻¹ M_ns)          interest s, nuisance n marginalised
//   A   -log tr (C_ss),  C = M⁻¹                   (A_s: trace of the interest block)
//   E   log λ_min (M_ss - M_sn M_nn⁻¹ M_ns)
//
// M is taken in relative units, M_rel = D·M·D with D = diag(|theta_i|) (|theta_i| = 0: unit
// scale), so that the criteria weigh percentile errors (ref 000 §III-A: 100·σ/|θ|) and are
// comparable between the points of the a priori box. The log form makes the box average the
// "ED" criterion (expected log det) and does not change any argmax or maximin solution.
//
// Parameters the information does not reach at all (zero row, e.g. the eta of a direction a
// trial never uses) are dropped: they are not part of the design. An information matrix that
// is singular on the remaining ones (e.g. eta and m together in one mapping: scaling m, drag,
// bias and eta by one factor leaves the motion unchanged) is flagged and its eigenvalues floored
// at kSingularFloor so that solvers still see a finite, very poor value.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <string_view>
#include <vector>

namespace uuvplan::planner {

enum class Criterion { kD, kDs, kA, kE };

std::string_view CriterionName(Criterion c);

/// Eigenvalue floor in relative units (1/σ_rel²): 1e-8 is a relative σ of 10⁴.
inline constexpr double kSingularFloor = 1e-8;
/// Below this eigenvalue (relative σ above 1000, i.e. 100000%) the design is called singular.
inline constexpr double kSingularThreshold = 1e-6;

/// M_rel = D·M·D, D = diag(|theta_i| or 1 when theta_i = 0).
Eigen::MatrixXd RelativeInformation(const Eigen::MatrixXd& M, const Eigen::VectorXd& theta);

/// Indices of parameters with information: M_rel(i, i) > 1e-12·max(1, max_j M_rel(j, j)).
std::vector<int> InformedParameters(const Eigen::MatrixXd& M_rel);

struct CriterionValue {
  double value = 0.0;
  bool singular = false;
  /// Parameters of interest without any information (value is then the floor's).
  std::vector<int> uninformed_interest;
};

/// The criterion on M_rel (np × np). `interest`: indices of the parameters of interest (Ds, and
/// the interest block for A and E); empty means all informed parameters. Uninformed parameters
/// that are not of interest are dropped; informed non-interest ones are nuisance (marginalised).
CriterionValue EvaluateCriterion(const Eigen::MatrixXd& M_rel, Criterion criterion,
                                 const std::vector<int>& interest);

/// Predicted 1σ of every parameter (absolute units) from the information M (np × np):
/// sqrt(diag(M⁻¹)) over the informed parameters; NaN for uninformed ones and +inf when M is
/// singular on the informed ones.
Eigen::VectorXd PredictedSigma(const Eigen::MatrixXd& M, const Eigen::VectorXd& theta);

}  // namespace uuvplan::planner
