#include "uuvplan/model/coupled_model.h"

#include <cmath>
#include <cstring>

#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::model {

int HorizontalIndex(Dof dof) {
  for (int i = 0; i < 3; ++i) {
    if (kHorizontalDofs[i] == dof) return i;
  }
  return -1;
}

int CoupledIndex(int i, const char* parameter) {
  for (int p = 0; p < 4; ++p) {
    if (std::strcmp(kCoupledDofParameters[p], parameter) == 0) return 4 * i + p;
  }
  return -1;
}

std::vector<std::string> CoupledParameterNames() {
  std::vector<std::string> names;
  for (Dof d : kHorizontalDofs) {
    for (const char* p : kCoupledDofParameters) names.push_back(std::string(DofName(d)) + "." + p);
  }
  return names;
}

std::string CoupledParameterUnit(int j) {
  return Unit(kCoupledDofParameters[j % 4], kHorizontalDofs[j / 4]);
}

Horizontal CoupledHorizontalModel::Coriolis(const Horizontal& nu) const {
  const double m_u = Inertia(0), m_v = Inertia(1);
  const double u = nu[0], v = nu[1], r = nu[2];
  return {m_v * v * r, -m_u * u * r, (m_u - m_v) * u * v};
}

CoriolisTerm CoriolisTermOf(Dof dof) {
  switch (dof) {
    case Dof::kSurge: return {"vr", "m_v"};
    case Dof::kSway: return {"ur", "−m_u"};
    case Dof::kYaw: return {"uv", "m_u − m_v"};
    default: return {};
  }
}

Horizontal CoupledHorizontalModel::DragAndBias(const Horizontal& nu) const {
  Horizontal f;
  for (int i = 0; i < 3; ++i) {
    const double x = nu[i];
    f[i] = -theta[4 * i + 1] * x - theta[4 * i + 2] * std::abs(x) * x + theta[4 * i + 3];
  }
  return f;
}

Horizontal CoupledHorizontalModel::Acceleration(const Horizontal& nu,
                                                const Horizontal& tau) const {
  const Horizontal f = Coriolis(nu) + DragAndBias(nu) + tau;
  return {f[0] / Inertia(0), f[1] / Inertia(1), f[2] / Inertia(2)};
}

bool CoupledHorizontalModel::Admissible(std::string* why) const {
  const std::vector<std::string> names = CoupledParameterNames();
  for (int j = 0; j < kCoupledParameterCount; ++j) {
    const ParameterFamily* family = FamilyOf(kCoupledDofParameters[j % 4]);
    if (family && family->Admissible(theta[j])) continue;
    if (why) {
      *why = names[j] + " = " + Significant(theta[j], 4) + " " + CoupledParameterUnit(j) +
             " is not " + (family ? family->Expected() : "in the vocabulary");
    }
    return false;
  }
  return true;
}

Eigen::Matrix<double, kCoupledParameterCount, 1> CoupledRegressor(int i, const Horizontal& nu) {
  Eigen::Matrix<double, kCoupledParameterCount, 1> h =
      Eigen::Matrix<double, kCoupledParameterCount, 1>::Zero();
  const double u = nu[0], v = nu[1], r = nu[2];
  // The Coriolis terms moved to the left-hand side (seed 003 speed and steering equations).
  if (i == 0) h[CoupledIndex(1, "m")] = -v * r;
  if (i == 1) h[CoupledIndex(0, "m")] = u * r;
  if (i == 2) {
    h[CoupledIndex(0, "m")] = -u * v;
    h[CoupledIndex(1, "m")] = u * v;
  }
  const double x = nu[i];
  h[CoupledIndex(i, "k")] = x;
  h[CoupledIndex(i, "kq")] = std::abs(x) * x;
  h[CoupledIndex(i, "bias")] = -1.0;
  return h;
}

CoupledHorizontalModel CoupledModelOfTruth(const Truth& truth) {
  CoupledHorizontalModel model;
  for (int i = 0; i < 3; ++i) {
    const std::string dof(DofName(kHorizontalDofs[i]));
    const auto it = truth.dofs.find(kHorizontalDofs[i]);
    if (it == truth.dofs.end() || !it->second.params.count(param::kMass)) {
      throw InputError("truth '" + truth.vehicle.name + "'",
                       "dofs." + dof + ".params.m: the coupled horizontal model needs the "
                       "inertia of surge, sway and yaw");
    }
    for (int p = 0; p < 4; ++p) {
      const auto value = it->second.params.find(kCoupledDofParameters[p]);
      model.theta[4 * i + p] = value == it->second.params.end() ? 0.0 : value->second;
    }
  }
  return model;
}

}  // namespace uuvplan::model
