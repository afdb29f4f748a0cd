// Combined-mode designs (planner/design/combined_design.h) of the coupled horizontal model
// (planner/design/coupled_design.h) on the ASV of ref 003 (cases/asv), replayed by an
// integrator of this file's own over the prior box.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iostream>

#include "uuvplan/ident/estimators/joint_ls.h"
#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/io/combined_design_json.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/virtual_pool.h"
#include "uuvplan/planner/design/coupled_design.h"

namespace uuvplan::planner {
namespace {

using Vec3 = std::array<double, 3>;

std::string Case(const char* file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/asv/" + file;
}

// Ref 003's 3-DOF equations (model/coupled_model.h's header), written out again here so that
// the replay does not share the planner's simulator: θ = [m, k, kq, bias] per DOF.
Vec3 Acceleration(const std::array<double, 12>& th, const Vec3& nu, const Vec3& tau) {
  const double u = nu[0], v = nu[1], r = nu[2];
  const Vec3 coriolis = {th[4] * v * r, -th[0] * u * r, (th[0] - th[4]) * u * v};
  Vec3 a;
  for (int i = 0; i < 3; ++i) {
    const double x = nu[i];
    a[i] = (coriolis[i] - th[4 * i + 1] * x - th[4 * i + 2] * std::abs(x) * x + th[4 * i + 3] +
            tau[i]) /
           th[4 * i];
  }
  return a;
}

struct Replay {
  double x_min = 1e9, x_max = -1e9, y_min = 1e9, y_max = -1e9, turns = 0.0;
};

// RK4 on [x, y, ψ, u, v, r] with a 0.01 s step (the planner's is 0.2 s), the pose in the
// pool frame from the planned start pose.
int HorizontalIndex(model::Dof dof) {
  return static_cast<int>(
      std::find(model::kHorizontalDofs.begin(), model::kHorizontalDofs.end(), dof) -
      model::kHorizontalDofs.begin());
}

Replay ReplayTrack(const std::array<double, 12>& th, const model::CombinedTrialDesign& trial,
                   const CombinedDesign& d) {
  auto f = [&](double t, const std::array<double, 6>& s) {
    Vec3 tau = {0, 0, 0};
    for (const auto& in : trial.inputs) tau[HorizontalIndex(in.dof)] = in.NominalForce(t);
    const Vec3 a = Acceleration(th, {s[3], s[4], s[5]}, tau);
    const double c = std::cos(s[2]), sn = std::sin(s[2]);
    return std::array<double, 6>{
        c * s[3] - sn * s[4], sn * s[3] + c * s[4], s[5], a[0], a[1], a[2]};
  };
  std::array<double, 6> s = {d.start[0], d.start[1], d.start[2], 0, 0, 0};
  Replay r;
  const double h = 0.01;
  for (double t = 0; t < trial.duration - 1e-9; t += h) {
    auto add = [](std::array<double, 6> a, const std::array<double, 6>& b, double w) {
      for (int i = 0; i < 6; ++i) a[i] += w * b[i];
      return a;
    };
    const auto k1 = f(t, s), k2 = f(t + h / 2, add(s, k1, h / 2)),
               k3 = f(t + h / 2, add(s, k2, h / 2)), k4 = f(t + h, add(s, k3, h));
    for (int i = 0; i < 6; ++i) s[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    r.x_min = std::min(r.x_min, s[0]);
    r.x_max = std::max(r.x_max, s[0]);
    r.y_min = std::min(r.y_min, s[1]);
    r.y_max = std::max(r.y_max, s[1]);
    r.turns = std::max(r.turns, std::abs(s[2] - d.start[2]) / (2 * M_PI));
  }
  return r;
}

// The schedule JSON replays the trial: a profile at most 0.1 s apart whose forces are the
// inputs' and whose thruster forces keep one sign, min_thrust clear of zero.
void ExpectJsonProfileReplaysTheTrial(const CombinedDesign& d, const model::Vehicle& vehicle,
                                      const model::Pool& pool) {
  const nlohmann::json j =
      io::CombinedDesignJson(d, model::CoupledHorizontalModel(vehicle), vehicle, pool,
                             {model::kCoupledModelName, kCoupledSigmaAssumption});
  const auto& profile = j.at("trial").at("profile");
  const auto t = profile.at("t").get<std::vector<double>>();
  ASSERT_GE(t.size(), 2u);
  EXPECT_NEAR(t.back(), d.trial.duration, 0.1);
  for (std::size_t k = 1; k < t.size(); ++k) EXPECT_LE(t[k] - t[k - 1], 0.1 + 1e-12);
  for (const auto& in : d.trial.inputs) {
    const auto f =
        profile.at("force").at(std::string(model::DofName(in.dof))).get<std::vector<double>>();
    ASSERT_EQ(f.size(), t.size());
    for (std::size_t k = 0; k < t.size(); k += 97)
      EXPECT_DOUBLE_EQ(f[k], in.offset + in.amplitude * std::sin(in.omega * t[k]));
  }
  for (const auto& th : vehicle.thrusters) {
    const auto f = profile.at("thrusters").at(th.name).get<std::vector<double>>();
    const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
    EXPECT_GE(std::max(*lo, -*hi), vehicle.min_thrust) << th.name;
  }
  EXPECT_EQ(j.at("fits"), true);
  EXPECT_DOUBLE_EQ(j.at("trial").at("start").at("x").get<double>(), d.start[0]);
  // Its σ say what they rest on (a bound: start known, efficient estimator), as the terminal.
  EXPECT_EQ(j.at("cramer_rao_assumption"), kCoupledSigmaAssumption);
}

CombinedDesign PlannedAsvDesign(const std::string& mode) {
  const model::Vehicle vehicle = io::ReadVehicle(Case("vehicle.yaml"));
  return PlanCombinedDesign(model::CoupledHorizontalModel(vehicle), vehicle,
                            io::ReadPool(Case("pool.yaml")),
                            CoupledDesignOptions(*model::ParseDofList(mode)));
}

// The planned trial flown in the virtual pool by the case's truth (cases/asv/truth.yaml: its
// quadratic drags lie below the prior box's, which only moves the track) and identified by the
// joint least squares (ident/estimators/joint_ls.h): the inertias — the coupling's coefficients —
// within 3σ of the truth (a 0.3% chance each to miss) and determined to better than 3% (the
// plan promises 0.5–0.9% at the box's worst for an efficient estimator; the one-step rows,
// one Savitzky–Golay window apart, give 0.3–1.2%). The drag terms are not asserted: under the
// spin a quadratic drag may be negative and insignificant and is then dropped, the linear one
// taking its part (6 seeds on the earlier finite-difference plan: every inertia within 1.7σ).
void ExpectPlannedTrialIdentifiesTheCoupledModel(const CombinedDesign& d) {
  const model::Truth truth = io::ReadTruth(Case("truth.yaml"));
  model::VirtualPoolOptions pool;
  pool.seed = 1903;
  const model::MultiDofModel truth_model = model::CoupledModelOfTruth(truth);
  const model::TrialLog log = model::RunCombinedTrial(
      truth, truth_model, model::CoupledThetaOfTruth(truth_model, truth), d.trial, pool);
  const model::MultiDofModel coupled = model::CoupledHorizontalModel(truth.vehicle);
  const Eigen::VectorXd want = model::CoupledThetaOfTruth(coupled, truth);
  const ident::JointLsResult r =
      ident::JointOneStepLeastSquares(coupled, {&log}, ident::JointLsOptions{});
  ASSERT_TRUE(r.ok()) << r.message;
  for (int i = 0; i < 3; ++i) {
    const int j = 4 * i;  // m of surge, sway, yaw
    std::cout << r.names[j] << " = " << r.theta[j] << " ± " << r.Sigma(j) << " (true " << want[j]
              << ")\n";
    EXPECT_LT(std::abs(r.theta[j] - want[j]), 3 * r.Sigma(j)) << r.names[j];
    EXPECT_LT(r.Sigma(j), 0.03 * want[j]) << r.names[j];
  }
  // What the rest of the fit may do: drop a negative, insignificant drag (joint_ls.h step 3).
  for (const auto& dropped : r.dropped) {
    EXPECT_LT(dropped.value, 0.0) << r.names[dropped.index];
    EXPECT_GT(ident::PercentileError(dropped.value, dropped.sigma),
              ident::kInsignificantPercentileError)
        << r.names[dropped.index];
  }
}

class CoupledDesignModes : public ::testing::TestWithParam<std::string> {};

// The box's centre, vertices and yaw drag sweep (the design's check points before the exchange),
// and 30 seeded interior points other than the planner's probes (options.probe_seed).
std::vector<Eigen::VectorXd> ReplayPoints(const model::MultiDofModel& coupled,
                                          const ParameterBox& box) {
  std::vector<ParameterValues> points = {box.nominal};
  for (const ParameterValues& p : box.CheckPoints(2)) points.push_back(p);
  for (std::size_t a = 0; a < box.axes.size(); ++a) {
    if (box.axes[a].name != "yaw.drag") continue;
    std::vector<double> factors(box.axes.size(), 1.0);
    for (int k = 1; k < 16; ++k) {
      factors[a] = box.axes[a].lo + (box.axes[a].hi - box.axes[a].lo) * k / 16;
      points.push_back(box.At(factors));
    }
  }
  for (const ParameterValues& p : box.Sample(30, 19)) points.push_back(p);
  std::vector<Eigen::VectorXd> thetas;
  for (const ParameterValues& p : points) thetas.push_back(ThetaAt(coupled, p));
  return thetas;
}

// "the planner's combined designs stay inside the pool over the prior box in an
// independent simulation". The ASV's design of each combined mode, 120 s, replayed at every vertex
// of the six-axis prior box, its centre and 30 seeded interior points (other than the planner's
// probes): the track keeps the pool's
// margin, the heading the tether's turns, and every thruster (its force from the design's
// profile every 0.01 s) one sign, min_thrust clear of zero, within its limit; and the JSON's
// profile replays the same trial.
TEST_P(CoupledDesignModes, AsvCombinedDesignStaysInThePoolOverThePriorBox) {
  const model::Vehicle vehicle = io::ReadVehicle(Case("vehicle.yaml"));
  const model::Pool pool = io::ReadPool(Case("pool.yaml"));
  const CombinedDesignOptions options = CoupledDesignOptions();
  const CombinedDesign d = PlannedAsvDesign(GetParam());
  ASSERT_TRUE(d.fits) << d.reasons.front() << "; " << d.solver.BriefReport();
  for (const auto& in : d.trial.inputs) {
    std::cout << model::DofName(in.dof) << ": " << in.offset << " + " << in.amplitude << " sin("
              << in.omega << " t) in " << in.mapping << "\n";
  }
  const model::MultiDofModel coupled = model::CoupledHorizontalModel(vehicle);
  const ParameterBox box = JointAPrioriBox(vehicle, coupled, options.box, nullptr);
  for (model::Dof dof : model::kHorizontalDofs) {  // the replay spans the vehicle file's bounds
    const auto bounds = vehicle.InertiaBounds(dof);
    const std::string m = std::string(model::DofName(dof)) + ".m";
    const auto axis = std::find_if(box.axes.begin(), box.axes.end(), [&](const BoxAxis& a) {
      return a.params == std::vector<std::string>{m};
    });
    ASSERT_NE(axis, box.axes.end()) << m;
    EXPECT_NEAR(box.Nominal(m) * axis->lo, bounds[0], 1e-9 * bounds[1]);
    EXPECT_NEAR(box.Nominal(m) * axis->hi, bounds[1], 1e-9 * bounds[1]);
  }
  for (const Eigen::VectorXd& theta : ReplayPoints(coupled, box)) {
    std::array<double, 12> th;
    for (int j = 0; j < 12; ++j) th[j] = theta[j];
    const Replay r = ReplayTrack(th, d.trial, d);
    EXPECT_GE(r.x_min, pool.margin);
    EXPECT_LE(r.x_max, pool.length - pool.margin);
    EXPECT_GE(r.y_min, pool.margin);
    EXPECT_LE(r.y_max, pool.width - pool.margin);
    EXPECT_LE(r.turns, pool.max_turns);
  }
  // The thrusters, from the design's profile and the vehicle's shares, written out here.
  for (std::size_t i = 0; i < vehicle.thrusters.size(); ++i) {
    double lo = 1e9, hi = -1e9;
    for (double t = 0; t <= d.trial.duration; t += 0.01) {
      double tau = 0;
      for (const auto& in : d.trial.inputs) {
        for (const auto& [ti, share] : vehicle.mappings[vehicle.MappingIndex(in.mapping)].shares) {
          if (ti == static_cast<int>(i)) tau += share * in.NominalForce(t);
        }
      }
      lo = std::min(lo, tau);
      hi = std::max(hi, tau);
    }
    const auto& th = vehicle.thrusters[i];
    EXPECT_GE(std::max(lo, -hi), vehicle.min_thrust)
        << th.name << " in [" << lo << ", " << hi << "] N";
    EXPECT_LE(hi, th.MaxForwardThrust()) << th.name;
    EXPECT_GE(lo, -th.MaxReverseThrust()) << th.name;
  }
  ExpectJsonProfileReplaysTheTrial(d, vehicle, pool);
  // A trial of surge+yaw or sway+yaw alone pushes no sway or surge, which the coupled fit
  // refuses (CoupledLeastSquares.ATrialSetThatPushesNoSwayFailsNamingIt); the two together
  // identify it (planning.md §5).
  if (GetParam() == "surge+sway+yaw") ExpectPlannedTrialIdentifiesTheCoupledModel(d);
}

// The sensors bound the fastest wave (model::kDefaultSamplesPerPeriod samples per period): the
// ASV's surge DVL slowed to 0.5 Hz resolves periods of 20 s and longer, so surge's sine in the
// surge+yaw mode has ω ≤ 2π/20 s = 0.314 rad/s (yaw's 10 Hz compass leaves it free); at
// 0.01 Hz not even the slowest combined wave (ω_min 0.1 rad/s) is resolved: refused, naming it.
TEST(CombinedDesignSensors, ASlowSensorBoundsItsDofsWave) {
  model::Vehicle vehicle = io::ReadVehicle(Case("vehicle.yaml"));
  const model::Pool pool = io::ReadPool(Case("pool.yaml"));
  CombinedDesignOptions options = CoupledDesignOptions({model::Dof::kSurge, model::Dof::kYaw});
  // The bound is in the design variables (ω spans [ω_min, ω_max of the DOF]), so any point the
  // solver returns shows it: a short search.
  options.exchange_rounds = 0;
  options.solver.max_global_evaluations = 20;
  options.solver.max_local_evaluations = 20;
  vehicle.sensors.at(model::Dof::kSurge).velocity->rate_hz = 0.5;
  const CombinedDesign d =
      PlanCombinedDesign(model::CoupledHorizontalModel(vehicle), vehicle, pool, options);
  const auto surge =
      std::find_if(d.trial.inputs.begin(), d.trial.inputs.end(),
                   [](const model::TrialDesign& in) { return in.dof == model::Dof::kSurge; });
  ASSERT_NE(surge, d.trial.inputs.end());
  EXPECT_LE(surge->omega, 2 * M_PI / 20.0 * (1 + 1e-12));
  EXPECT_GE(surge->omega, options.omega_min);
  vehicle.sensors.at(model::Dof::kSurge).velocity->rate_hz = 0.01;
  try {
    PlanCombinedDesign(model::CoupledHorizontalModel(vehicle), vehicle, pool, options);
    ADD_FAILURE() << "a 0.01 Hz sensor was accepted";
  } catch (const model::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sensors.surge"), std::string::npos) << e.what();
  }
}

// Ref 003 Table I's combined modes (5–16 s a plan).
INSTANTIATE_TEST_SUITE_P(Modes, CoupledDesignModes,
                         ::testing::Values("surge+yaw", "sway+yaw", "surge+sway+yaw"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name;
                           const std::vector<model::Dof> dofs = *model::ParseDofList(info.param);
                           for (const model::Dof d : dofs) {
                             std::string dof(model::DofName(d));
                             dof[0] = static_cast<char>(std::toupper(dof[0]));
                             name += dof;
                           }
                           return name;
                         });

}  // namespace
}  // namespace uuvplan::planner
