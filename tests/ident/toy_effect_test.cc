// docs/architecture.md, "How to add an effect", done in a test: a toy effect (cubic drag,
// F = −c3·ξ³) registered through the public effect table, with its own force term and its
// finding's sentence and nothing else, is simulated by the virtual pool, named by diagnosis
// and estimated within 3σ.
#include <gtest/gtest.h>

#include <cmath>

#include "support/hidden_effect.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/virtual_pool.h"
#include "uuvplan/text/finding_text.h"

namespace uuvplan {
namespace {

// Step 1 of the walk-through: the force term, with its partials and regressor.
class CubicDragTerm final : public model::ForceTerm {
 public:
  CubicDragTerm() : ForceTerm({"c3"}) {}
  double Value(const model::TermInputs& c, const double* theta) const override {
    return -theta[0] * c.xi * c.xi * c.xi;
  }
  model::TermPartials Partials(const model::TermInputs& c, const double* theta,
                               double* J) const override {
    J[0] = -c.xi * c.xi * c.xi;
    return {theta[0] * J[0], -3.0 * theta[0] * c.xi * c.xi, 0.0};
  }
  bool Regressor(const model::TermInputs& c, double* h, double* h0) const override {
    h[0] = -c.xi * c.xi * c.xi;
    *h0 = 0.0;
    return true;
  }
};

// Step 2: the table entry.
model::EffectEntry CubicDrag() {
  model::EffectEntry e;
  e.name = "cubic_drag";
  e.physics = "drag grows with the cube of the speed";
  e.site = model::EffectSite::kForceTerm;
  e.parameters = {{"c3", "cubic drag", "N·s³/m³", "N·m·s³/rad³", 0.0, 0.0, 1e9}};
  e.make_term = [](model::Dof, const std::vector<std::string>&) {
    return std::make_unique<CubicDragTerm>();
  };
  e.propose = [](const model::ProposalEvidence& c) {
    if (c.Has("c3")) return std::vector<model::Proposal>{};
    model::Proposal p;
    p.start.push_back({"c3", 0.0});
    return std::vector<model::Proposal>{p};
  };
  return e;
}

// Step 2b: the finding's sentence.
std::string CubicDragSentence(const text::FindingQuotes&) {
  return "the simulation is too fast at high speed: drag grows faster than ξ²";
}

TEST(ToyEffectTest, VocabularyKnowsTheRegisteredEffect) {
  EXPECT_EQ(model::FamilyOf("c3"), nullptr);
  {
    const model::ScopedEffect toy(CubicDrag());
    ASSERT_NE(model::FamilyOf("c3"), nullptr);
    EXPECT_EQ(model::Unit("c3", model::Dof::kSurge), "N·s³/m³");
    EXPECT_EQ(model::Effects().OwnerOf("c3")->name, "cubic_drag");
    const auto names = model::Effects().Diagnosable();
    EXPECT_EQ(names.back(), "cubic_drag");
  }
  EXPECT_EQ(model::Effects().Find("cubic_drag"), nullptr);  // unregistered with its scope
}

TEST(ToyEffectTest, DofModelCarriesItsTermAndPartials) {
  const model::ScopedEffect toy(CubicDrag());
  const testing::HiddenEffectCase c = testing::DrawHiddenEffectCase(std::nullopt, 1);
  model::ModelStructure s;
  s.dof = c.dof;
  s.Add("c3");
  const model::DofModel dm(c.truth.vehicle, s);
  const int i = dm.ParameterIndex("c3");
  ASSERT_GE(i, 0);
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(dm.num_parameters());
  theta[0] = 100.0;
  theta[i] = 7.0;
  const double x[2] = {0.0, 0.5};
  double dx[2];
  Eigen::MatrixXd A(2, 2), B(2, dm.num_parameters());
  const model::TrialConditions conditions;
  dm.Linearize(0.0, x, conditions, theta.data(), dx, A, B);
  EXPECT_NEAR(dx[1], -7.0 * 0.125 / 100.0, 1e-12);         // −c3·ξ³/m
  EXPECT_NEAR(B(1, i), -0.125 / 100.0, 1e-12);             // ∂(F/m)/∂c3
  EXPECT_NEAR(A(1, 1), -3.0 * 7.0 * 0.25 / 100.0, 1e-12);  // ∂(F/m)/∂ξ
}

// Steady speed v where k·v + kq·v² = F.
double SteadySpeed(double k, double kq, double force) {
  return kq > 0 ? (-k + std::sqrt(k * k + 4 * kq * force)) / (2 * kq) : force / k;
}

TEST(ToyEffectTest, DiagnosisNamesAndEstimatesTheToyEffect) {
  const model::ScopedEffect toy(CubicDrag());
  const text::ScopedFindingSentence sentence("cubic_drag", CubicDragSentence);
  for (std::uint64_t seed : {1u, 2u}) {
    testing::HiddenEffectCase c = testing::DrawHiddenEffectCase(std::nullopt, seed);
    auto& params = c.truth.dofs.at(c.dof).params;
    // A cubic drag worth 30% of the typical force at its steady speed: visible, not dominant.
    const double v = SteadySpeed(params.at("k"), params.at("kq"), c.typical_force);
    const double c3 = 0.3 * c.typical_force / (v * v * v);
    params["c3"] = c3;
    c.effect = "cubic_drag";
    c.effect_params = {{"c3", c3}};
    const model::Campaign campaign = testing::RunHiddenEffectCase(c, seed);
    ident::DiagnoseOptions options = testing::DiagnoseOptionsFor(c);
    options.candidates = {"cubic_drag", "thruster_lag", "asymmetric_drag"};
    const ident::DiagnosisResult r = ident::Diagnose(campaign, options);
    const testing::Verdict verdict = testing::Judge(c, r);
    EXPECT_TRUE(verdict.correct) << "seed " << seed << ": found [" << verdict.found << "]";
    EXPECT_TRUE(verdict.within_3_sigma) << "seed " << seed;
    ASSERT_FALSE(r.findings.empty());
    EXPECT_GT(r.findings[0].gain.relative, 0.0);
    EXPECT_NE(text::FindingSentence(r, r.findings[0]).find("drag grows faster"), std::string::npos);
  }
}

}  // namespace
}  // namespace uuvplan
