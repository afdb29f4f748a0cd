#include "uuvplan/model/derived_mappings.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "uuvplan/model/configuration_matrix.h"
#include "uuvplan/model/jet_clearance.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::model {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A share below this fraction of the largest is a thruster the allocation does not use (zero
// by the geometry, left by rounding).
constexpr double kZeroShare = 1e-9;
// Singular values below this fraction of the largest are a rank deficiency (thrusters on one
// line); the same fraction of a unit force is "no force at all".
constexpr double kRankThreshold = 1e-9;

// The rows of B a mapping of `dof` must hold: its own and every DOF not restoring, moments
// divided by L so that a residual moment reads as a force (F = M / L).
struct Problem {
  Dof dof = Dof::kSurge;
  std::vector<Dof> row_dofs;
  int target_row = 0;
  MatrixXd scaled;
  Eigen::RowVectorXd physical_row;  // the DOF's own row of B: N (N·m) per N of thrust
};

Problem ProblemOf(const MatrixXd& b, Dof dof, const MappingDerivationOptions& options,
                  double length) {
  Problem p;
  p.dof = dof;
  for (Dof d : kAllDofs) {
    const bool restoring =
        std::find(options.restoring.begin(), options.restoring.end(), d) != options.restoring.end();
    if (d != dof && restoring) continue;
    if (d == dof) p.target_row = static_cast<int>(p.row_dofs.size());
    p.row_dofs.push_back(d);
  }
  p.scaled.resize(static_cast<Eigen::Index>(p.row_dofs.size()), b.cols());
  for (std::size_t r = 0; r < p.row_dofs.size(); ++r) {
    const Dof d = p.row_dofs[r];
    p.scaled.row(static_cast<Eigen::Index>(r)) = b.row(Index(d)) / (IsRotational(d) ? length : 1.0);
  }
  p.physical_row = b.row(Index(dof));
  return p;
}

// The allocation of a unit force on the problem's DOF among `columns`: the least-squares
// minimum-norm s = A⁺·e_k, accepted when the force it gives on every other row is within
// `tolerance` of its own (and, with `full_rank`, when the columns are independent).
struct Allocation {
  std::optional<VectorXd> shares;  // tau_i = shares_i·phi, phi in N (N·m)
  double worst_residual = 1.0;     // largest other-row force / own force (1: none reached)
  Dof worst_dof = Dof::kSurge;
};

Allocation Allocate(const Problem& p, const std::vector<int>& columns, double tolerance,
                    bool full_rank) {
  MatrixXd a(p.scaled.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t c = 0; c < columns.size(); ++c)
    a.col(Eigen::Index(c)) = p.scaled.col(columns[c]);
  Eigen::JacobiSVD<MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(kRankThreshold);
  Allocation out;
  out.worst_dof = p.dof;
  if (full_rank && svd.rank() < a.cols()) return out;
  VectorXd e = VectorXd::Zero(a.rows());
  e(p.target_row) = 1.0;
  VectorXd s = svd.solve(e);
  const VectorXd w = a * s;
  const double own = w(p.target_row);  // = |projection of e_k on range(A)|² in [0, 1]
  if (!(own > kRankThreshold)) return out;
  out.worst_residual = 0.0;
  for (Eigen::Index r = 0; r < w.size(); ++r) {
    if (r == p.target_row || std::abs(w(r)) / own <= out.worst_residual) continue;
    out.worst_residual = std::abs(w(r)) / own;
    out.worst_dof = p.row_dofs[static_cast<std::size_t>(r)];
  }
  if (out.worst_residual > tolerance) return out;
  double physical = 0.0;  // the DOF's force of s (N or N·m): divide it out for phi = 1
  for (std::size_t c = 0; c < columns.size(); ++c)
    physical += p.physical_row(columns[c]) * s(Eigen::Index(c));
  out.shares = s / physical;
  return out;
}

ThrustMapping MappingOf(const Problem& p, const std::vector<int>& columns, const VectorXd& s,
                        const std::vector<Thruster>& thrusters, double clearance) {
  ThrustMapping m;
  m.dof = p.dof;
  const double largest = s.cwiseAbs().maxCoeff();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const double share = s(Eigen::Index(c));
    if (std::abs(share) > kZeroShare * largest) m.shares.emplace_back(columns[c], share);
  }
  m.open_water = OpenWaterOf(m.shares, thrusters, clearance);
  return m;
}

std::string SubsetName(Dof dof, const std::vector<int>& columns,
                       const std::vector<Thruster>& thrusters) {
  std::string name(DofName(dof));
  for (int c : columns) name += "-" + thrusters[static_cast<std::size_t>(c)].name;
  return name;
}

std::vector<int> Support(const ThrustMapping& m) {
  std::vector<int> support;
  for (const auto& [index, share] : m.shares) support.push_back(index);
  return support;
}

// Every minimal subset whose unique allocation drives the DOF alone with every thruster
// working, by size then file order.
std::vector<ThrustMapping> SubsetMappings(const Problem& p, const std::vector<Thruster>& thrusters,
                                          const MappingDerivationOptions& options,
                                          double clearance) {
  std::vector<std::vector<int>> subsets;
  const int n = static_cast<int>(thrusters.size());
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    std::vector<int> columns;
    for (int i = 0; i < n; ++i) {
      if (mask & (1u << i)) columns.push_back(i);
    }
    subsets.push_back(std::move(columns));
  }
  std::sort(subsets.begin(), subsets.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  std::vector<ThrustMapping> mappings;
  for (const std::vector<int>& columns : subsets) {
    const Allocation a = Allocate(p, columns, options.purity_tolerance, true);
    if (!a.shares) continue;
    ThrustMapping m = MappingOf(p, columns, *a.shares, thrusters, clearance);
    if (m.shares.size() != columns.size()) continue;  // a smaller subset's allocation
    m.name = SubsetName(p.dof, columns, thrusters);
    mappings.push_back(std::move(m));
  }
  return mappings;
}

std::string UnreachableText(const Problem& p, const Allocation& all) {
  std::string text(DofName(p.dof));
  if (all.worst_dof == p.dof) {
    return text + ": the thrusters give no " + (IsRotational(p.dof) ? "moment" : "force") +
           " on it";
  }
  return text + ": no allocation of the thrusters drives it alone (the least-squares one also " +
         "gives " + std::string(DofName(all.worst_dof)) + " " +
         Significant(100.0 * all.worst_residual, 3) + "% of it" +
         (IsRotational(all.worst_dof) || IsRotational(p.dof) ? ", moments as forces at the mean "
                                                               "half-side of the size box)"
                                                             : ")");
}

}  // namespace

DerivedMappings DeriveMappings(const std::vector<Thruster>& thrusters,
                               const std::array<double, 3>& size,
                               const MappingDerivationOptions& options,
                               const std::vector<Dof>& dofs) {
  DerivedMappings out;
  if (thrusters.empty() || !options.IsValid()) return out;
  const MatrixXd b = ConfigurationMatrix(thrusters);
  const double length = DerivationLength(size);
  const double clearance = options.jet_clearance.value_or(DefaultJetClearance(size));
  std::vector<int> every(thrusters.size());
  for (std::size_t i = 0; i < every.size(); ++i) every[i] = static_cast<int>(i);
  for (Dof dof : kAllDofs) {
    if (std::find(dofs.begin(), dofs.end(), dof) == dofs.end()) continue;
    const Problem p = ProblemOf(b, dof, options, length);
    const Allocation all = Allocate(p, every, options.purity_tolerance, false);
    if (!all.shares) {
      out.unreachable.push_back(UnreachableText(p, all));
      continue;
    }
    ThrustMapping all_mapping = MappingOf(p, every, *all.shares, thrusters, clearance);
    all_mapping.name = std::string(DofName(dof)) + "-all";
    const std::vector<int> all_support = Support(all_mapping);
    out.mappings.push_back(std::move(all_mapping));
    if (static_cast<int>(thrusters.size()) > options.max_subset_thrusters) continue;
    for (ThrustMapping& m : SubsetMappings(p, thrusters, options, clearance)) {
      if (Support(m) != all_support) out.mappings.push_back(std::move(m));
    }
  }
  return out;
}

}  // namespace uuvplan::model
