#include "uuvplan/model/coupled_model.h"

#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::model {
namespace {

// Each DOF's Coriolis product and its coefficient in the global inertias (header).
struct Coriolis {
  Dof dof;
  const char* pair;
  const char* coefficient;
  std::vector<std::pair<std::string, double>> inertias;
};
const std::array<Coriolis, 3>& CoriolisTerms() {
  static const std::array<Coriolis, 3> terms = {{
      {Dof::kSurge, "vr", "m_v", {{"sway.m", 1.0}}},
      {Dof::kSway, "ur", "−m_u", {{"surge.m", -1.0}}},
      {Dof::kYaw, "uv", "m_u − m_v", {{"surge.m", 1.0}, {"sway.m", -1.0}}},
  }};
  return terms;
}

}  // namespace

MultiDofModel CoupledHorizontalModel(const Vehicle& vehicle,
                                     std::vector<ModelStructure> structures) {
  structures.resize(kHorizontalDofs.size());
  std::vector<ParameterTie> ties;
  for (std::size_t i = 0; i < kHorizontalDofs.size(); ++i) {
    const Coriolis& c = CoriolisTerms()[i];
    const std::string coupling = param::kCouplingPrefix + std::string(c.pair);
    structures[i].dof = c.dof;
    structures[i].Add(coupling);
    ties.push_back({c.dof, coupling, c.inertias});
  }
  return MultiDofModel(vehicle, structures, ties);
}

MultiDofModel CoupledModelOfTruth(const Truth& truth) {
  std::vector<ModelStructure> structures;
  for (Dof d : kHorizontalDofs) structures.push_back(TruthStructure(truth, d));
  return CoupledHorizontalModel(truth.vehicle, structures);
}

Eigen::VectorXd CoupledThetaOfTruth(const MultiDofModel& model, const Truth& truth) {
  std::map<Dof, std::map<std::string, double>> values;
  for (Dof d : kHorizontalDofs) {
    const auto it = truth.dofs.find(d);
    if (it == truth.dofs.end() || !it->second.params.count(param::kMass)) {
      throw InputError("truth '" + truth.vehicle.name + "'",
                       "dofs." + std::string(DofName(d)) +
                           ".params.m: the coupled horizontal "
                           "model needs the inertia of surge, sway and yaw");
    }
    values[d] = it->second.params;
  }
  const std::map<std::string, double> neutral = {
      {param::kLinearDrag, 0.0}, {param::kQuadraticDrag, 0.0}, {param::kBias, 0.0}};
  return model.Theta(values, &neutral);
}

CoriolisTerm CoriolisTermOf(Dof dof) {
  for (const Coriolis& c : CoriolisTerms()) {
    if (c.dof == dof) return {c.pair, c.coefficient};
  }
  return {};
}

}  // namespace uuvplan::model
