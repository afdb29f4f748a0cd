// The DOF model and its simulator: RK4 order against the analytic linear solution, Jacobians
// and sensitivities against finite differences with every effect on, breakpoints, a priori
// inertia.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/every_effect.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/simulator.h"

namespace uuvplan::model {
namespace {

// m·dxi/dt = -k·xi + a + b·sin(w·t) from rest:
//   xi(t) = a/k·(1 - e^{-t/tc}) + b/(k² + m²w²)·(k·sin wt - m·w·cos wt + m·w·e^{-t/tc})
double LinearSineVelocity(double m, double k, double a, double b, double w, double t) {
  const double tc = m / k;
  const double d = k * k + m * m * w * w;
  return a / k * (1 - std::exp(-t / tc)) +
         b / d * (k * std::sin(w * t) - m * w * std::cos(w * t) + m * w * std::exp(-t / tc));
}

// Surge of the front/rear vehicle with linear drag only: m·dξ/dt = −k·ξ + F, θ = (m, k).
struct LinearSurge {
  static ModelStructure Structure() {
    ModelStructure s;
    s.dof = Dof::kSurge;
    s.Remove("kq");
    s.Remove("bias");
    return s;
  }
  const Vehicle vehicle = testing::FrontRearVehicle();
  const DofModel model{vehicle, Structure()};
};

TEST(SimulatorTest, Rk4ConvergesAtFourthOrderOnTheLinearModel) {
  const LinearSurge linear;
  const DofModel& model = linear.model;
  const double m = 890, k = 212.25, a = 35, b = 25, w = 2 * M_PI / 26;  // ref 000 §IV-D
  Eigen::VectorXd theta(2);
  theta << m, k;
  const auto input = MakeSineExcitation(a, b, w, 0, 60);
  const TrialConditions c{input.get()};
  const double t_end = 60.0;
  std::vector<double> errors;
  for (double h : {2.0, 1.0, 0.5, 0.25}) {
    SimulationOptions o;
    o.step_s = h;
    const Trajectory tr = Simulate(model, theta, c, std::vector<double>{t_end}, o);
    errors.push_back(std::abs(tr.x(0, 1) - LinearSineVelocity(m, k, a, b, w, t_end)));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    // Halving the step divides a 4th-order method's global error by 2⁴ = 16; the observed
    // order log2(e_{h}/e_{h/2}) must lie within 0.3 of 4 in this asymptotic range.
    const double order = std::log2(errors[i - 1] / errors[i]);
    EXPECT_NEAR(order, 4.0, 0.3) << "h = " << 2.0 / (1 << i);
  }
  EXPECT_LT(errors.back(), 1e-8);
}

TEST(SimulatorTest, StepsEndAtSegmentBreakpoints) {
  // A force step at t = 1.3 s inside a 1 s RK4 step would cost the method its order; steps
  // end at breakpoints, so the coarse simulation matches the analytic one to RK4 accuracy.
  const LinearSurge linear;
  const DofModel& model = linear.model;
  Eigen::VectorXd theta(2);
  theta << 100.0, 50.0;  // t_c = 2 s
  const auto input = MakeSegmentsExcitation({{20.0, 1.3, 0}, {-10.0, 3.0, 1}});
  SimulationOptions o;
  o.step_s = 0.25;
  const Trajectory tr =
      Simulate(model, theta, TrialConditions{input.get()}, std::vector<double>{1.3, 4.3}, o);
  const double xi1 = 20.0 / 50.0 * (1 - std::exp(-1.3 / 2.0));
  const double xi2 = -10.0 / 50.0 + (xi1 + 10.0 / 50.0) * std::exp(-3.0 / 2.0);
  // RK4 local error ~ (h/t_c)^5/120 per step: ~1e-7 of the speed here.
  EXPECT_NEAR(tr.x(0, 1), xi1, 1e-6);
  EXPECT_NEAR(tr.x(1, 1), xi2, 1e-6);
}

// Every effect on: asymmetric drag, two mappings with free eta, ballast, lag, dead zone,
// advance loss, coupling to an exogenous yaw rate, drift, sensor delay, thrust-map shape.
struct FullModel {
  Vehicle vehicle = testing::FrontRearVehicle();
  ModelStructure structure;
  std::unique_ptr<DofModel> model;
  Eigen::VectorXd theta;
  FullModel() {
    structure = testing::EveryEffectStructure(40.0);
    model = std::make_unique<DofModel>(vehicle, structure);
    theta = model->Theta(testing::EveryEffectValues());
  }
};

class YawRate final : public AuxVelocities {
 public:
  void At(double t, std::array<double, kNumDofs>* v) const override {
    (*v)[Index(Dof::kYaw)] = 0.2 * std::sin(0.3 * t);
  }
};

TEST(DofModelTest, ParameterLayoutFollowsTheVocabulary) {
  FullModel f;
  const std::vector<std::string> expected = {"m",
                                             "k",
                                             "k_neg",
                                             "kq",
                                             "kq_neg",
                                             "bias",
                                             "bias_step",
                                             "eta.front.neg",
                                             "eta.rear.pos",
                                             "advance_loss",
                                             "coupling.rr",
                                             "drift",
                                             "lag",
                                             "deadzone",
                                             "sensor_delay",
                                             "thrust_exponent"};
  EXPECT_EQ(f.model->parameter_names(), expected);
  EXPECT_EQ(f.model->num_states(), 3);
}

// A = ∂f/∂x and B = ∂f/∂θ of Linearize against central differences of Derivative at states x
// (nx = 2 or 3 entries each).
void ExpectLinearizeMatchesFiniteDifferences(const DofModel& model, const Eigen::VectorXd& theta,
                                             const TrialConditions& c, double t,
                                             const std::vector<double>& x) {
  const int nx = model.num_states(), np = model.num_parameters();
  double dx[3];
  Eigen::MatrixXd A(nx, nx), B(nx, np);
  model.Linearize(t, x.data(), c, theta.data(), dx, A, B);
  const double h = 1e-6;
  for (int s = 0; s < nx; ++s) {
    std::vector<double> xp = x, xm = x;
    double fp[3], fm[3];
    xp[s] += h;
    xm[s] -= h;
    model.Derivative(t, xp.data(), c, theta.data(), fp);
    model.Derivative(t, xm.data(), c, theta.data(), fm);
    for (int r = 0; r < nx; ++r) {
      // FD error O(h²) on O(1) derivatives plus rounding 1e-16·|f|/h: 1e-6 absolute.
      EXPECT_NEAR(A(r, s), (fp[r] - fm[r]) / (2 * h), 1e-6) << "A(" << r << "," << s << ")";
    }
  }
  for (int j = 0; j < np; ++j) {
    Eigen::VectorXd tp = theta, tm = theta;
    const double hj = 1e-6 * std::max(1.0, std::abs(theta[j]));
    tp[j] += hj;
    tm[j] -= hj;
    double fp[3], fm[3];
    model.Derivative(t, x.data(), c, tp.data(), fp);
    model.Derivative(t, x.data(), c, tm.data(), fm);
    for (int r = 0; r < nx; ++r) {
      EXPECT_NEAR(B(r, j), (fp[r] - fm[r]) / (2 * hj), 1e-6 * std::max(1.0, std::abs(B(r, j))))
          << "B(" << r << ", " << model.parameter_names()[j] << ") at t = " << t;
    }
  }
}

TEST(DofModelTest, LinearizeMatchesFiniteDifferences) {
  FullModel f;
  const auto input = MakeSegmentsExcitation({{40.0, 5.0, 0}, {-30.0, 5.0, 1}, {2.0, 5.0, 0}});
  const YawRate aux;
  const TrialConditions c{input.get(), 2, 100.0, &aux};
  // States away from the drag kink at xi = 0 and the dead-zone kinks at |phi| = d.
  for (double t : {1.0, 7.0, 12.0}) {
    for (double xi : {-0.3, 0.05, 0.25}) {
      ExpectLinearizeMatchesFiniteDifferences(*f.model, f.theta, c, t,
                                              {1.0, xi, t < 5 ? 25.0 : -20.0});
    }
  }
}

TEST(DofModelTest, LinearizeWithoutLagMatchesFiniteDifferences) {
  // Without lag the actuator path (dead zone, thrust-map shape) enters ∂(ΣF/m)/∂θ directly.
  Vehicle vehicle = testing::FrontRearVehicle();
  ModelStructure s;
  s.dof = Dof::kSurge;
  s.Add("deadzone");
  s.Add("thrust_exponent");
  s.settings["thrust_reference"] = 40.0;
  const DofModel model(vehicle, s);
  const Eigen::VectorXd theta = model.Theta({{"m", 890},
                                             {"k", 46.9},
                                             {"kq", 306.2},
                                             {"bias", 1.5},
                                             {"deadzone", 3.0},
                                             {"thrust_exponent", 0.25}});
  EXPECT_EQ(model.num_states(), 2);
  const auto input = MakeSegmentsExcitation({{40.0, 5.0, 0}, {-30.0, 5.0, 1}, {7.0, 5.0, 0}});
  const TrialConditions c{input.get(), 0, 0.0, nullptr};
  for (double t : {1.0, 7.0, 12.0}) {
    for (double xi : {-0.3, 0.05, 0.25})
      ExpectLinearizeMatchesFiniteDifferences(model, theta, c, t, {1.0, xi});
  }
}

// Every effect's model on a 40 s sine (30 ± 20 N, 0.25 rad/s) with a yaw rate beside it,
// sampled every second.
struct SineTrial {
  FullModel f;
  std::unique_ptr<Excitation> input = MakeSineExcitation(30.0, 20.0, 0.25, 0, 40.0);
  YawRate aux;
  TrialConditions c{input.get(), 1, 50.0, &aux};
  std::vector<double> times = [] {
    std::vector<double> t;
    for (int i = 1; i <= 40; ++i) t.push_back(i * 1.0);
    return t;
  }();
  Trajectory Run(const SimulationOptions& o, const Eigen::VectorXd& theta) const {
    return SimulateMeasured(*f.model, theta, c, times, o);
  }
  Trajectory Run(const SimulationOptions& o) const { return Run(o, f.theta); }
};

TEST(SimulatorTest, SensitivitiesMatchFiniteDifferencesOfTheSimulation) {
  const SineTrial trial;
  const FullModel& f = trial.f;
  SimulationOptions o;
  o.step_s = 0.02;
  o.sensitivities = true;
  const Trajectory tr = trial.Run(o);
  o.sensitivities = false;
  for (int j = 0; j < f.model->num_parameters(); ++j) {
    const double h = 1e-5 * std::max(1.0, std::abs(f.theta[j]));
    Eigen::VectorXd tp = f.theta, tm = f.theta;
    tp[j] += h;
    tm[j] -= h;
    const Trajectory yp = trial.Run(o, tp);
    const Trajectory ym = trial.Run(o, tm);
    for (int s = 0; s < 2; ++s) {
      const Eigen::VectorXd fd = (yp.x.col(s) - ym.x.col(s)) / (2 * h);
      const double scale = std::max(1e-3, fd.cwiseAbs().maxCoeff());
      // The sensitivity equations are integrated with the same RK4 stages as the state, so
      // they agree with the FD of the discrete simulation to FD accuracy (~1e-6 relative).
      EXPECT_LT((tr.S[s].col(j) - fd).cwiseAbs().maxCoeff(), 1e-4 * scale)
          << f.model->parameter_names()[j] << " output " << s;
    }
  }
}

// ∂x/∂ξ0 as the last sensitivity column: on the linear model m·dξ/dt = −k·ξ + F the velocity's
// is e^{−t/tc} and the position's tc·(1 − e^{−t/tc}), tc = m/k (from rest or not: linear).
TEST(SimulatorTest, InitialVelocityColumnIsTheClosedForm) {
  const LinearSurge linear;
  const DofModel& model = linear.model;
  const double m = 890, k = 212.25, tc = m / k;
  Eigen::VectorXd theta(2);
  theta << m, k;
  const auto input = MakeSineExcitation(35, 25, 2 * M_PI / 26, 0, 60);
  std::vector<double> times;
  for (int i = 1; i <= 60; ++i) times.push_back(i * 1.0);
  SimulationOptions o;
  o.step_s = 0.05;
  o.sensitivities = true;
  o.initial_velocity_column = true;
  const Trajectory tr = Simulate(model, theta, TrialConditions{input.get()}, times, o);
  ASSERT_EQ(tr.S[1].cols(), 3);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double e = std::exp(-times[i] / tc);
    // RK4 at h = 0.05 s ≪ tc = 4.2 s: a global error ~ (h/tc)⁴ ≈ 2e-8 of the response.
    EXPECT_NEAR(tr.S[1](i, 2), e, 1e-7) << "t = " << times[i];
    EXPECT_NEAR(tr.S[0](i, 2), tc * (1 - e), 1e-6) << "t = " << times[i];
  }
}

// The local step (time_constant_fraction, from a largest step of 1 s) on every effect, the lag
// included: the same state and sensitivities as a fine fixed step, to the accuracy that half the
// local time constant gives.
TEST(SimulatorTest, LocalStepFollowsTheLocalTimeConstant) {
  const SineTrial trial;
  SimulationOptions fine;
  fine.step_s = 0.001;
  fine.sensitivities = true;
  fine.initial_velocity_column = true;
  const Trajectory ref = trial.Run(fine);
  SimulationOptions local = fine;
  local.step_s = 1.0;
  local.time_constant_fraction = 0.5;
  const Trajectory tr = trial.Run(local);
  for (int s = 0; s < 2; ++s) {
    const double scale = std::max(1e-3, ref.x.col(s).cwiseAbs().maxCoeff());
    // RK4 at h·ρ ≤ 0.5: a local error ≤ 0.5⁵/120 ≈ 3e-4 of the fastest mode per step, which
    // decays within a time constant: well within 1e-3 of the response's scale.
    EXPECT_LT((tr.x.col(s) - ref.x.col(s)).cwiseAbs().maxCoeff(), 1e-3 * scale) << "state " << s;
    for (int j = 0; j < tr.S[s].cols(); ++j) {
      const double sj = std::max(1e-6, ref.S[s].col(j).cwiseAbs().maxCoeff());
      EXPECT_LT((tr.S[s].col(j) - ref.S[s].col(j)).cwiseAbs().maxCoeff(), 1e-3 * sj)
          << "state " << s << " column " << j;
    }
  }
}

// The same held input, once declared piecewise constant (sampled once per step) and once not
// (sampled at every RK4 stage time): the fast path must not change the answer. With the sensor
// delay (0.3 s) the shifted output times fall a rounding error after the 0.05 s breakpoints,
// which once made the per-stage sampling read the previous piece in the tiny step between.
class UndeclaredHeld final : public Excitation {
 public:
  explicit UndeclaredHeld(const Excitation* held) : held_(held) {}
  double Force(double t) const override { return held_->Force(t); }
  int Mapping(double t) const override { return held_->Mapping(t); }
  TimesView Breakpoints() const override { return held_->Breakpoints(); }
  double duration() const override { return held_->duration(); }

 private:
  const Excitation* held_;
};

TEST(SimulatorTest, PiecewiseConstantInputIsSampledOncePerStepWithTheSameResult) {
  FullModel f;
  std::vector<double> t, force;
  for (int i = 0; i <= 400; ++i) {
    t.push_back(i * 0.05);
    force.push_back(30.0 + 20.0 * std::sin(0.25 * i * 0.05) - (i % 97 == 0 ? 60.0 : 0.0));
  }
  const auto held = MakeHeldExcitation(t, force, std::vector<int>(t.size(), 0), 20.0);
  ASSERT_TRUE(held->piecewise_constant());
  const UndeclaredHeld slow(held.get());
  const YawRate aux;
  std::vector<double> times;
  for (int i = 0; i <= 200; ++i) times.push_back(i * 0.1);
  SimulationOptions o;
  o.step_s = 0.01;
  const Trajectory fast =
      SimulateMeasured(*f.model, f.theta, {held.get(), 1, 50.0, &aux}, times, o);
  const Trajectory reference =
      SimulateMeasured(*f.model, f.theta, {&slow, 1, 50.0, &aux}, times, o);
  // Same arithmetic on the same samples: equal to rounding.
  EXPECT_LT((fast.x - reference.x).cwiseAbs().maxCoeff(),
            1e-12 * (1 + reference.x.cwiseAbs().maxCoeff()));
}

TEST(ExcitationTest, SineAgreesWithLibmAtStageTimesShiftsAndRevisits) {
  // SineExcitation answers an evenly spaced run of times by rotating its last value
  // (excitation.cc). Whatever the order of the queries, the answer must be
  // offset + amplitude·sin(ω·t) to rounding: 1e-12 of |offset| + |amplitude| (the argument ω·t
  // itself carries ~1e-14 relative rounding at t = 600 s, a rotation 1e-16, 256 between anchors).
  const double offset = 35.0, amplitude = 25.0, omega = 2 * M_PI / 26;
  const auto sine = MakeSineExcitation(offset, amplitude, omega, 0, 600.0);
  const double tol = 1e-12 * (offset + amplitude);
  double worst = 0.0;
  auto check = [&](double t) {
    worst = std::max(worst, std::abs(sine->Force(t) - (offset + amplitude * std::sin(omega * t))));
  };
  // RK4 stages of a 0.01 s step, on a grid shifted by a sensor delay of 0.3 s (spacings that
  // differ by ~1e-12 s from step to step), each step end asked twice.
  for (int k = 0; k < 60000; ++k) {
    const double ta = k * 0.01 - 0.3, te = (k + 1) * 0.01 - 0.3;
    check(ta + 0.5 * (te - ta));
    check(te);
    check(te);
  }
  // Back in time, an irregular spacing, then a new even run.
  for (double t : {12.0, 11.5, 11.5 + 1e-7, 300.123, 300.133, 300.143, 300.153, 0.0}) check(t);
  EXPECT_LE(worst, tol);
}

// SwitchedWave::Switches as it was written with libm alone: the wave sampled h apart, each sign
// change bisected to 1e-9 s.
std::vector<double> LibmSwitches(const SwitchedWave& wave, double duration, double h) {
  std::vector<double> out;
  double t0 = 0.0, w0 = wave.Wave(0.0);
  for (std::size_t i = 1; i <= static_cast<std::size_t>(std::ceil(duration / h)); ++i) {
    const double t1 = std::min(duration, i * h), w1 = wave.Wave(t1);
    if ((w0 >= 0) != (w1 >= 0)) {
      double a = t0, b = t1;
      while (b - a > 1e-9) {
        const double c = 0.5 * (a + b);
        ((wave.Wave(c) >= 0) == (w0 >= 0) ? a : b) = c;
      }
      if (b > 0 && b < duration) out.push_back(b);
    }
    t0 = t1;
    w0 = w1;
  }
  return out;
}

TEST(ExcitationTest, SwitchedMultisineAgreesWithLibmAtStageTimesAndSwitches) {
  // The switched excitation rotates each component's sine too (rotating_sine.h): its force and
  // mapping must be SwitchedWave::Force's (libm) to rounding, 1e-12 of |offset| + Σ|a_i| as
  // above, at the RK4 stage times of a 0.01 s step, after going back in time, and on both
  // sides of every switch; the switches (scanned with rotated sines, bisected with libm) must be
  // exactly those of a libm scan.
  SwitchedWave wave;
  wave.offset = 3.0;
  wave.components = {{40.0, 0.371, 2.78}, {4.6, 0.742, 1.41}, {32.0, 1.113, 3.17}};
  wave.floor_pos = 2.0;
  wave.floor_neg = 2.5;
  wave.mapping_pos = 0;
  wave.mapping_neg = 1;
  const auto switched = MakeSwitchedExcitation(wave, 120.0);
  // Switches' scan step: 1/100 of the shortest period, at most 0.05 s.
  const std::vector<double> switches =
      LibmSwitches(wave, 120.0, std::min(0.05, 2 * M_PI / 1.113 / 100.0));
  ASSERT_GE(switches.size(), 4u);  // the wave does switch, several times in 120 s
  EXPECT_EQ(switched->Breakpoints().ToVector(), switches);
  const double tol = 1e-12 * (3.0 + 40.0 + 4.6 + 32.0);
  double worst = 0.0;
  int mapping_mismatches = 0;
  auto check = [&](double t) {
    double force = 0.0;
    int mapping = -1, libm_mapping = -1;
    switched->Sample(t, &force, &mapping);
    worst = std::max(worst, std::abs(force - wave.Force(t, &libm_mapping)));
    mapping_mismatches += mapping != libm_mapping;
  };
  for (int k = 0; k < 12000; ++k) {
    const double ta = k * 0.01, te = (k + 1) * 0.01;
    check(ta + 0.5 * (te - ta));
    check(te);
  }
  for (double t : {60.0, 59.5, 0.0, 100.001, 100.011, 100.021}) check(t);
  // Just before and after each switch (the integrator's steps end there): far enough from the
  // zero (1e-6 s, |w| ~ 1e-5 N) that rounding cannot flip the sign.
  for (double b : switches) {
    check(b - 1e-6);
    check(b + 1e-6);
  }
  EXPECT_LE(worst, tol);
  EXPECT_EQ(mapping_mismatches, 0);
}

TEST(VehicleTest, RomeoYawInertiaOfAUniformBox) {
  // Ref 000 §IV-D: I_r = (1/12)·450·(1.3² + 0.9²) = 93.75 kg·m².
  Vehicle v = testing::FrontRearVehicle();
  EXPECT_NEAR(v.RigidInertia(Dof::kYaw), 93.75, 1e-12);
  EXPECT_DOUBLE_EQ(v.RigidInertia(Dof::kSurge), 450.0);
  v.inertia[Dof::kYaw] = 84.0;  // a given inertia wins over the box
  EXPECT_DOUBLE_EQ(v.RigidInertia(Dof::kYaw), 84.0);
  const auto bounds = v.InertiaBounds(Dof::kSurge);  // added mass 10–100% (ref 000 §III-B)
  EXPECT_DOUBLE_EQ(bounds[0], 495.0);
  EXPECT_DOUBLE_EQ(bounds[1], 900.0);
}

TEST(ThrusterTest, SeedModels) {
  ThrustModel sq;  // ref 000 §IV-C: c_V = 1.02 / 1.09 N/V²
  sq.c_pos = 1.02;
  sq.c_neg = 1.09;
  EXPECT_DOUBLE_EQ(sq.Thrust(5.0), 25.5);
  EXPECT_DOUBLE_EQ(sq.Thrust(-5.0), -27.25);
  ThrustModel p2;  // ref 002 §2.2: a = 10.84 N/V², b = -5.019 N/V, odd-extended
  p2.kind = ThrustModel::Kind::kPoly2;
  p2.a = 10.84;
  p2.b = -5.019;
  EXPECT_NEAR(p2.Thrust(2.0), 10.84 * 4 - 5.019 * 2, 1e-12);
  EXPECT_NEAR(p2.Thrust(-2.0), -(10.84 * 4 - 5.019 * 2), 1e-12);
  sq.deduction = 0.1;  // ref 003: T_a = (1 - t)·T
  EXPECT_DOUBLE_EQ(sq.Thrust(5.0), 0.9 * 25.5);
}

}  // namespace
}  // namespace uuvplan::model
