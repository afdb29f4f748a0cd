// The RLS convergence figure (ref 004 Fig. 11; report/identification_figures.h): after
// --method rls each DOF has one panel per RLS coefficient with the estimate after every
// update and its ±1σ band, ending at the final estimate; other methods have no such figure.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ident/ident_cases.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/report/identification_figures.h"
#include "uuvplan/report/render.h"

namespace uuvplan::report {
namespace {

const Figure* Named(const std::vector<Figure>& figures, const std::string& name) {
  for (const Figure& f : figures) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

TEST(ReportFigures, RlsConvergenceOfUrisYaw) {
  const auto designs = ident::testing::UrisDesigns();
  const model::Campaign c =
      ident::VirtualCampaign(ident::testing::CaseTruth("uris"), {designs[2], designs[3]}, 4);
  ident::IdentifyOptions o;
  o.method = ident::Method::kRls;
  const ident::IdentifyResult r = ident::Identify(c, o);
  ASSERT_EQ(r.dofs.size(), 1u);
  const ident::RlsDofResult& rls = *r.dofs[0].rls;
  const auto figures = IdentificationFigures(r);
  const Figure* f = Named(figures, "identification-yaw-rls");
  ASSERT_NE(f, nullptr);
  ASSERT_EQ(f->panels.size(), rls.coefficient_names.size());  // γ, k/m, bias/m (kq dropped)
  for (std::size_t j = 0; j < f->panels.size(); ++j) {
    const Panel& p = f->panels[j];
    SCOPED_TRACE(p.title);
    ASSERT_EQ(p.series.size(), 2u);  // band, estimate
    const Series& band = p.series[0];
    const Series& line = p.series[1];
    ASSERT_GT(line.x.size(), 10u);
    EXPECT_EQ(band.x.size(), line.x.size());
    for (std::size_t k = 0; k < band.x.size(); ++k) {
      EXPECT_LT(band.y_low[k], line.y[k]);
      EXPECT_GT(band.y_high[k], line.y[k]);
    }
    // The last point is the final estimate, as printed by identify.
    EXPECT_DOUBLE_EQ(line.y.back(), rls.psi.theta(rls.psi.theta.rows() - 1, static_cast<int>(j)));
    EXPECT_NE(p.y_label.find("/kg·m²"), std::string::npos);  // per unit of yaw inertia
  }
  EXPECT_GT(Render(*f, Format::kPng).size(), 1000u);

  o.method = ident::Method::kOneStep;
  EXPECT_EQ(Named(IdentificationFigures(ident::Identify(c, o)), "identification-yaw-rls"), nullptr);
}

}  // namespace
}  // namespace uuvplan::report
