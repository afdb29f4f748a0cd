// Every force term's analytic partials against central finite differences (manif-style:
// at zero, near zero and random points), and every regressor against the term's value.
#include <gtest/gtest.h>

#include <random>

#include "uuvplan/model/force_term.h"

namespace uuvplan::model {
namespace {

// Central differences have truncation error O(h²·F''') and rounding O(eps·|F|/h); with
// h = 1e-6 on O(1) inputs both stay below 1e-7 relative, so 1e-6 is a safe bound.
constexpr double kStep = 1e-6;
constexpr double kTol = 1e-6;

struct Point {
  TermInputs c;
  std::vector<double> theta;
};

std::vector<std::unique_ptr<ForceTerm>> AllTerms() {
  std::vector<std::unique_ptr<ForceTerm>> t;
  t.push_back(MakeDragTerm(true, false, false));
  t.push_back(MakeDragTerm(false, true, false));
  t.push_back(MakeDragTerm(true, true, false));
  t.push_back(MakeDragTerm(true, true, true));
  t.push_back(MakeThrustTerm({"a", "b"}, {"eta.a.neg", "eta.b.pos", "eta.b.neg"}));
  t.push_back(MakeConstantTerm(true, false));
  t.push_back(MakeConstantTerm(false, true));
  t.push_back(MakeConstantTerm(true, true));
  t.push_back(MakeAdvanceLossTerm());
  t.push_back(MakeCouplingTerm(Dof::kSurge, {"vr", "rr"}));
  t.push_back(MakeCouplingTerm(Dof::kYaw, {"ur", "uv"}));
  t.push_back(MakeDriftTerm());
  return t;
}

std::vector<Point> Points(int n_params, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Point> pts;
  // Zero, near-zero (but away from the |xi| kink by more than the FD step), random.
  for (double scale : {0.0, 1e-3, 1.0}) {
    for (int rep = 0; rep < 4; ++rep) {
      Point p;
      p.c.xi = scale == 0.0 ? 0.0 : scale * u(rng);
      if (std::abs(p.c.xi) < 10 * kStep) p.c.xi = scale == 0.0 ? 0.0 : 20 * kStep;
      p.c.phi = 5.0 * u(rng);
      if (std::abs(p.c.phi) < 0.1) p.c.phi = 0.5;
      p.c.mapping = rep % 3 - 1;  // -1, 0, 1
      p.c.t_campaign = 100.0 * std::abs(u(rng));
      p.c.ballast_steps = rep;
      for (auto& v : p.c.velocities) v = u(rng);
      for (int i = 0; i < n_params; ++i) p.theta.push_back(1.0 + 0.4 * u(rng));
      pts.push_back(p);
    }
  }
  return pts;
}

TEST(ForceTermTest, PartialsMatchCentralDifferences) {
  std::mt19937_64 rng(42);
  for (const auto& term : AllTerms()) {
    const int np = term->num_parameters();
    for (Point p : Points(np, rng)) {
      std::vector<double> J(np);
      const TermPartials a = term->Partials(p.c, p.theta.data(), J.data());
      EXPECT_NEAR(a.value, term->Value(p.c, p.theta.data()), 1e-12);
      for (int j = 0; j < np; ++j) {
        auto th = p.theta;
        th[j] += kStep;
        const double fp = term->Value(p.c, th.data());
        th[j] -= 2 * kStep;
        const double fm = term->Value(p.c, th.data());
        EXPECT_NEAR(J[j], (fp - fm) / (2 * kStep), kTol) << term->parameter_names()[j];
      }
      // d/dxi: the coupling terms read the own DOF's velocity through xi only.
      TermInputs cp = p.c, cm = p.c;
      cp.xi += kStep;
      cm.xi -= kStep;
      const double d_xi =
          (term->Value(cp, p.theta.data()) - term->Value(cm, p.theta.data())) / (2 * kStep);
      if (p.c.xi != 0.0) {  // |xi| has a kink at 0: its one-sided partials differ there
        EXPECT_NEAR(a.d_xi, d_xi, kTol);
      }
      cp = p.c;
      cm = p.c;
      cp.phi += kStep;
      cm.phi -= kStep;
      const double d_phi =
          (term->Value(cp, p.theta.data()) - term->Value(cm, p.theta.data())) / (2 * kStep);
      EXPECT_NEAR(a.d_phi, d_phi, kTol);
    }
  }
}

TEST(ForceTermTest, RegressorReproducesValue) {
  std::mt19937_64 rng(7);
  for (const auto& term : AllTerms()) {
    const int np = term->num_parameters();
    for (const Point& p : Points(np, rng)) {
      std::vector<double> h(np);
      double h0 = 0.0;
      ASSERT_TRUE(term->Regressor(p.c, h.data(), &h0));
      double f = h0;
      for (int j = 0; j < np; ++j) f += h[j] * p.theta[j];
      EXPECT_NEAR(f, term->Value(p.c, p.theta.data()), 1e-12);
    }
  }
}

TEST(ForceTermTest, ThrustUsesEtaOnlyOutsideOpenWater) {
  // Mapping "a" works in open water when pushing positive: eta.a.pos is not a parameter.
  auto thrust = MakeThrustTerm({"a"}, {"eta.a.neg"});
  const double eta_neg = 0.56;  // ref 000 Table II
  TermInputs c;
  c.mapping = 0;
  c.phi = 10.0;
  EXPECT_DOUBLE_EQ(thrust->Value(c, &eta_neg), 10.0);
  c.phi = -10.0;
  EXPECT_DOUBLE_EQ(thrust->Value(c, &eta_neg), -5.6);
}

TEST(ForceTermTest, AsymmetricDragSplitsBySign) {
  auto drag = MakeDragTerm(true, true, true);
  ASSERT_EQ(drag->parameter_names(), (std::vector<std::string>{"k", "k_neg", "kq", "kq_neg"}));
  // Ref 000 Table IV, technological payload: forward k 46.9 kq 306.2, backward 57.9 / 331.4.
  const double theta[4] = {46.9, 57.9, 306.2, 331.4};
  TermInputs c;
  c.xi = 0.2;
  EXPECT_DOUBLE_EQ(drag->Value(c, theta), -46.9 * 0.2 - 306.2 * 0.04);
  c.xi = -0.2;
  EXPECT_DOUBLE_EQ(drag->Value(c, theta), 57.9 * 0.2 + 331.4 * 0.04);
}

}  // namespace
}  // namespace uuvplan::model
