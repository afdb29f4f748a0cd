// Design criteria on Fisher information (see criteria.h for the equations).
#include "uuvplan/planner/design/criteria.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::planner {

constexpr model::EnumNames<Criterion, 4> kCriterionNames{
    {{{Criterion::kD, "D"}, {Criterion::kDs, "Ds"}, {Criterion::kA, "A"}, {Criterion::kE, "E"}}}};

std::string_view CriterionName(Criterion c) { return kCriterionNames.Name(c); }

Eigen::MatrixXd RelativeInformation(const Eigen::MatrixXd& M, const Eigen::VectorXd& theta) {
  Eigen::VectorXd d(theta.size());
  for (int i = 0; i < theta.size(); ++i) d[i] = theta[i] != 0.0 ? std::abs(theta[i]) : 1.0;
  return d.asDiagonal() * M * d.asDiagonal();
}

std::vector<int> InformedParameters(const Eigen::MatrixXd& M_rel) {
  const double top = std::max(1.0, M_rel.diagonal().maxCoeff());
  std::vector<int> out;
  for (int i = 0; i < M_rel.rows(); ++i) {
    if (M_rel(i, i) > 1e-12 * top) out.push_back(i);
  }
  return out;
}

namespace {

// Information on the interest block with the nuisance marginalised (Schur complement; a
// pseudo-inverse of M_nn, so that a nuisance combination no trial reaches does not matter).
Eigen::MatrixXd InterestInformation(const Eigen::MatrixXd& M, const std::vector<int>& s,
                                    const std::vector<int>& n) {
  Eigen::MatrixXd Mss = ident::SubMatrix(M, s);
  if (n.empty()) return Mss;
  const Eigen::MatrixXd Mnn = ident::SubMatrix(M, n);
  const Eigen::MatrixXd Msn = ident::SubMatrix(M, s, n);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Mnn);
  const Eigen::VectorXd& lam = es.eigenvalues();
  Eigen::VectorXd inv(lam.size());
  for (int i = 0; i < lam.size(); ++i) inv[i] = lam[i] > kSingularThreshold ? 1.0 / lam[i] : 0.0;
  const Eigen::MatrixXd P = Msn * es.eigenvectors();
  return Mss - P * inv.asDiagonal() * P.transpose();
}

}  // namespace

CriterionValue EvaluateCriterion(const Eigen::MatrixXd& M_rel, Criterion criterion,
                                 const std::vector<int>& interest) {
  CriterionValue out;
  const std::vector<int> informed = InformedParameters(M_rel);
  std::vector<int> s, n;
  if (interest.empty() || criterion == Criterion::kD) {
    s = informed;
    if (criterion == Criterion::kD) {
      // D: every informed parameter and every requested one (an uninformed one floors it).
      for (int i : interest) {
        if (!std::count(s.begin(), s.end(), i)) {
          s.push_back(i);
          out.uninformed_interest.push_back(i);
        }
      }
    }
  } else {
    for (int i : interest) {
      s.push_back(i);
      if (!std::count(informed.begin(), informed.end(), i)) out.uninformed_interest.push_back(i);
    }
    for (int i : informed) {
      if (!std::count(s.begin(), s.end(), i)) n.push_back(i);
    }
  }
  if (s.empty()) {
    out.singular = true;
    out.value = std::log(kSingularFloor);
    return out;
  }
  const Eigen::MatrixXd C = InterestInformation(M_rel, s, n);
  const Eigen::VectorXd lam =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(C, Eigen::EigenvaluesOnly).eigenvalues();
  out.singular = lam.minCoeff() < kSingularThreshold || !out.uninformed_interest.empty();
  switch (criterion) {
    case Criterion::kD:
    case Criterion::kDs: {
      double v = 0.0;
      for (int i = 0; i < lam.size(); ++i) v += std::log(std::max(lam[i], kSingularFloor));
      out.value = v;
      break;
    }
    case Criterion::kA: {
      double tr = 0.0;
      for (int i = 0; i < lam.size(); ++i) tr += 1.0 / std::max(lam[i], kSingularFloor);
      out.value = -std::log(tr);
      break;
    }
    case Criterion::kE:
      out.value = std::log(std::max(lam.minCoeff(), kSingularFloor));
      break;
  }
  return out;
}

Eigen::VectorXd PredictedSigma(const Eigen::MatrixXd& M, const Eigen::VectorXd& theta) {
  const int np = static_cast<int>(M.rows());
  Eigen::VectorXd sigma = Eigen::VectorXd::Constant(np, std::numeric_limits<double>::quiet_NaN());
  const Eigen::MatrixXd M_rel = RelativeInformation(M, theta);
  const std::vector<int> informed = InformedParameters(M_rel);
  if (informed.empty()) return sigma;
  const Eigen::MatrixXd C = ident::SubMatrix(M_rel, informed);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C);
  const Eigen::VectorXd& lam = es.eigenvalues();
  const Eigen::MatrixXd& V = es.eigenvectors();
  for (std::size_t a = 0; a < informed.size(); ++a) {
    double var = 0.0;
    bool unidentified = false;
    for (int k = 0; k < lam.size(); ++k) {
      const double w = V(a, k) * V(a, k);
      if (lam[k] < kSingularThreshold) {
        if (w > 1e-6) unidentified = true;
        continue;
      }
      var += w / lam[k];
    }
    const int i = informed[a];
    const double scale = theta[i] != 0.0 ? std::abs(theta[i]) : 1.0;
    sigma[i] = unidentified ? std::numeric_limits<double>::infinity() : std::sqrt(var) * scale;
  }
  return sigma;
}

}  // namespace uuvplan::planner
