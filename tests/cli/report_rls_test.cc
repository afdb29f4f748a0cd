// `uuvplan report CAMPAIGN --no-diagnosis --method rls`: the RLS convergence figure of each DOF
// (ref 004 Fig. 11, docs/report.md) beside the estimates; --method other than chain needs
// --no-diagnosis (the diagnosis identifies with the chain), --forgetting needs rls.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_test_util.h"
#include "ident/ident_cases.h"
#include "uuvplan/io/virtual_campaign.h"

namespace uuvplan::cli_test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(ReportTool, MethodRlsAddsTheConvergenceFigure) {
  TempDir tmp;
  const auto designs = ident::testing::UrisDesigns();
  model::VirtualCampaignOptions vo;
  vo.seed = 4;
  io::SimulateCampaign(ident::testing::CaseTruth("uris"), {designs[2], designs[3]}, tmp / "c", vo);
  ToolRun r = RunTool("report '" + (tmp / "c") + "' -o '" + (tmp / "r1") + "' --method rls", tmp);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("--no-diagnosis"));
  r = RunTool("report '" + (tmp / "c") + "' -o '" + (tmp / "r2") +
                  "' --no-diagnosis --method one-step --forgetting 0.98",
              tmp);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("--forgetting"));
  EXPECT_FALSE(fs::exists(tmp / "r1"));  // nothing written on bad input
  r = RunTool("report '" + (tmp / "c") + "' -o '" + (tmp / "r3") +
                  "' --no-diagnosis --method rls --forgetting 0.98",
              tmp);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(tmp / "r3/figures/identification-yaw-rls.png"));
  EXPECT_TRUE(fs::exists(tmp / "r3/figures/identification-yaw-rls.svg"));
  EXPECT_THAT(ReadText(tmp / "r3/report.html"), HasSubstr("id=\"fig-identification-yaw-rls\""));
}

}  // namespace
}  // namespace uuvplan::cli_test
