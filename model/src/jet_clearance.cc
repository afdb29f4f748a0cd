#include "uuvplan/model/jet_clearance.h"

#include <Eigen/Core>

#include "uuvplan/model/configuration_matrix.h"

namespace uuvplan::model {

namespace {

// A point exactly abeam of the jet's origin (projection 0, e.g. a thruster mounted beside it)
// is not downstream; 1 µm absorbs the rounding of a projection that is 0 by construction.
constexpr double kDownstream = 1e-6;

// True when point q lies downstream of the jet (origin p, unit axis `jet`) within `clearance`
// of its axis: projection s = (q − p)·jet > 0, distance |(q − p) − s·jet| < clearance.
bool InJet(const Eigen::Vector3d& p, const Eigen::Vector3d& jet, const Eigen::Vector3d& q,
           double clearance) {
  const Eigen::Vector3d v = q - p;
  const double s = v.dot(jet);
  return s > kDownstream && (v - s * jet).norm() < clearance;
}

}  // namespace

double DefaultJetClearance(const std::array<double, 3>& size) { return DerivationLength(size); }

bool JetIsClear(const std::vector<Thruster>& thrusters, int index, double thrust_sign,
                double clearance) {
  const Thruster& t = thrusters.at(static_cast<std::size_t>(index));
  if (!t.geometry || thrust_sign == 0) return true;
  const Eigen::Vector3d p(t.geometry->position.data());
  const Eigen::Vector3d jet =
      -(thrust_sign > 0 ? 1.0 : -1.0) * Eigen::Vector3d(t.geometry->direction.data()).normalized();
  if (InJet(p, jet, Eigen::Vector3d::Zero(), clearance)) return false;
  for (std::size_t j = 0; j < thrusters.size(); ++j) {
    if (static_cast<int>(j) == index || !thrusters[j].geometry) continue;
    if (InJet(p, jet, Eigen::Vector3d(thrusters[j].geometry->position.data()), clearance)) {
      return false;
    }
  }
  return true;
}

OpenWater OpenWaterOf(const std::vector<std::pair<int, double>>& shares,
                      const std::vector<Thruster>& thrusters, double clearance) {
  bool positive = true, negative = true;  // phi > 0: tau_i has the sign of share_i
  for (const auto& [index, share] : shares) {
    positive = positive && JetIsClear(thrusters, index, share, clearance);
    negative = negative && JetIsClear(thrusters, index, -share, clearance);
  }
  if (positive && negative) return OpenWater::kBoth;
  if (positive) return OpenWater::kPositive;
  return negative ? OpenWater::kNegative : OpenWater::kNone;
}

}  // namespace uuvplan::model
