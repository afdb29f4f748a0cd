// Seeded random vehicles and pools (random_vehicle.h).
#include "support/random_vehicle.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "uuvplan/model/mapping.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/prior.h"
#include "uuvplan/model/util/seed.h"

namespace uuvplan::testing {
namespace {

using model::Dof;

double Uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

int UniformInt(std::mt19937_64& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

// n thrusters for `dof`, and the mapping that drives it: equal shares for a translation; for
// yaw alternate sides at arm `arm` (shares ±1/(n·arm), at least one each way when n ≥ 2).
void AddDof(std::mt19937_64& rng, Dof dof, double thrust, double arm, model::Vehicle* v) {
  const int n = UniformInt(rng, 1, 4);
  model::ThrustMapping m;
  m.name = std::string(model::DofName(dof)) + "-all";
  m.dof = dof;
  for (int i = 0; i < n; ++i) {
    model::Thruster t;
    t.name = std::string(model::DofName(dof)) + "-t" + std::to_string(i);
    t.model.c_pos = thrust;
    t.model.c_neg = thrust * Uniform(rng, 0.6, 0.9);  // reverse thrust 60-90% of forward
    v->thrusters.push_back(t);
    const int index = static_cast<int>(v->thrusters.size()) - 1;
    const double share = dof == Dof::kYaw ? (i % 2 == 0 ? 1.0 : -1.0) / (n * arm) : 1.0 / n;
    m.shares.push_back({index, share});
  }
  const int ow = UniformInt(rng, 0, 2);  // both ways open water, or only one
  m.open_water = ow == 0 ? model::OpenWater::kBoth
                         : (ow == 1 ? model::OpenWater::kPositive : model::OpenWater::kNegative);
  v->mappings.push_back(m);
  v->sensors[dof].position = model::SensorSpec{Uniform(rng, 5.0, 12.5),
                                               dof == Dof::kYaw ? 0.01 : Uniform(rng, 0.01, 0.05)};
}

}  // namespace

RandomCase MakeRandomCase(std::uint64_t seed, int max_dofs) {
  std::mt19937_64 rng(seed);
  RandomCase c;
  model::Vehicle& v = c.vehicle;
  v.name = "random-" + std::to_string(seed);
  v.mass = std::exp(Uniform(rng, std::log(15.0), std::log(500.0)));
  const double side = std::cbrt(v.mass / 1000.0);  // a box of water's density
  v.size = {side * Uniform(rng, 1.0, 2.5), side, side * Uniform(rng, 0.6, 1.0)};
  // Thrusters sized to the vehicle: 0.2-1 N per kg^0.75 each (ROMEO: 4 × ~150 N for 450 kg).
  const double thrust = Uniform(rng, 0.2, 1.0) * std::pow(v.mass, 0.75);
  const std::vector<Dof> all = {Dof::kSurge, Dof::kSway, Dof::kHeave, Dof::kYaw};
  for (Dof d : all) AddDof(rng, d, thrust, 0.5 * v.size[0], &v);
  v.min_thrust = Uniform(rng, 0.02, 0.05) * thrust * 0.6;  // of the weakest reverse thrust
  std::vector<Dof> pick = all;
  std::shuffle(pick.begin(), pick.end(), rng);
  pick.resize(std::clamp(max_dofs, 1, 4));
  for (Dof d : all) {
    if (std::find(pick.begin(), pick.end(), d) != pick.end()) c.dofs.push_back(d);
  }
  c.pool.name = "pool-" + std::to_string(seed);
  c.pool.length = Uniform(rng, 4.0, 30.0);
  c.pool.width = Uniform(rng, 4.0, c.pool.length);
  c.pool.depth = Uniform(rng, 2.0, 8.0);
  c.pool.margin = std::min(0.5 * v.size[0], 0.45 * std::min(c.pool.width, c.pool.depth));
  return c;
}

model::Truth MakeRandomTruth(const RandomCase& c, std::uint64_t seed) {
  // A stream apart from MakeRandomCase's (which seeds with `seed` itself).
  std::mt19937_64 rng(model::StreamSeed(seed, 0x7275746852ULL));
  model::Truth truth;
  truth.vehicle = c.vehicle;
  for (Dof dof : c.dofs) {
    model::DofTruth& t = truth.dofs[dof];
    const auto mb = c.vehicle.InertiaBounds(dof);
    const model::APrioriDrag drag = model::DragOf(c.vehicle, dof, 0.5);
    const double factor = std::exp(Uniform(rng, std::log(0.5), std::log(2.0)));
    t.params[model::param::kMass] = Uniform(rng, mb[0], mb[1]);
    t.params[model::param::kLinearDrag] = factor * drag.drag.k;
    t.params[model::param::kQuadraticDrag] = factor * drag.drag.kq;
    t.params[model::param::kBias] = Uniform(rng, -0.02, 0.02) * drag.thrust;
    for (int i : c.vehicle.MappingsOf(dof)) {
      const model::ThrustMapping& m = c.vehicle.mappings[i];
      for (model::Direction d : {model::Direction::kPos, model::Direction::kNeg}) {
        if (!m.IsOpenWater(d)) t.params[model::EtaName(m.name, d)] = Uniform(rng, 0.55, 0.95);
      }
    }
  }
  return truth;
}

}  // namespace uuvplan::testing
