// An estimate outside the vehicle file's a priori range is a finding in `identify`'s text and
// JSON (docs/identification.md "Outside the a priori range"): a virtual ROMEO campaign (true
// surge m 890 kg, ref 000 §IV-D) identified against vehicle files whose added_mass range puts
// that m above, below and inside the range.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

using ::testing::HasSubstr;

class OutsidePriorCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scratch_ = new TempDir();
    const std::string plan = scratch_->Write("plan.json", kRomeoFirstSurgeTrials);
    const ToolRun sim = RunTool("simulate --truth " + kRomeoCase + "truth.yaml --plan " + plan +
                                    " --out " + *scratch_ / "campaign" + " --seed 7",
                                *scratch_);
    ASSERT_EQ(sim.status, 0) << sim.err;
    scratch_->Write("campaign/vehicle.yaml.simulated",
                    ReadText(*scratch_ / "campaign/vehicle.yaml"));
  }
  static void TearDownTestSuite() { delete scratch_; }

  // identify with the campaign's vehicle file given `added_mass`; the JSON's surge entry.
  nlohmann::json IdentifyWithAddedMass(const std::string& added_mass) {
    std::string text = ReadText(*scratch_ / "campaign/vehicle.yaml.simulated");
    const std::string key = "added_mass: [0.1, 1]";  // as simulate writes ROMEO's
    const auto at = text.find(key);
    if (at == std::string::npos) {
      ADD_FAILURE() << "no '" << key << "' in the simulated vehicle file:\n" << text;
      return {};
    }
    scratch_->Write("campaign/vehicle.yaml",
                    text.replace(at, key.size(), "added_mass: " + added_mass));
    run_ = RunTool(
        "identify " + *scratch_ / "campaign" + " --dof surge --json " + *scratch_ / "id.json",
        *scratch_);
    EXPECT_EQ(run_.status, 0) << run_.err;  // a finding, not a failure
    return nlohmann::json::parse(ReadText(*scratch_ / "id.json"))["dofs"]["surge"];
  }

  static TempDir* scratch_;
  ToolRun run_;
};
TempDir* OutsidePriorCli::scratch_ = nullptr;

// The identified m (about 900 ± 15 kg) lies 15σ above 675 kg = 450 kg × 1.5.
TEST_F(OutsidePriorCli, AnEstimateAboveTheRangeIsAFindingWithItsCauses) {
  const nlohmann::json surge = IdentifyWithAddedMass("[0.1, 0.5]");
  ASSERT_EQ(surge["outside_prior"].size(), 1u) << surge["outside_prior"].dump();
  const nlohmann::json& o = surge["outside_prior"][0];
  EXPECT_EQ(o["parameter"], "m");
  EXPECT_EQ(o["side"], "above");
  EXPECT_DOUBLE_EQ(o["range"][1].get<double>(), 675.0);
  EXPECT_GT(o["value"].get<double>(), 675.0);
  EXPECT_GT(o["sigmas_beyond"].get<double>(), 3.0);
  EXPECT_THAT(o["finding"].get<std::string>(), HasSubstr("installation loss"));
  EXPECT_THAT(run_.out, HasSubstr("OUTSIDE THE A PRIORI RANGE: m = "));
  EXPECT_THAT(run_.out, HasSubstr("lies above the vehicle file's a priori range [495, 675] kg"));
}

// 990 kg = 450 kg × 2.2 lies above the estimate: below the range, with the causes of that side.
TEST_F(OutsidePriorCli, AnEstimateBelowTheRangeIsAFindingWithItsCauses) {
  const nlohmann::json surge = IdentifyWithAddedMass("[1.2, 1.5]");
  ASSERT_EQ(surge["outside_prior"].size(), 1u) << surge["outside_prior"].dump();
  EXPECT_EQ(surge["outside_prior"][0]["side"], "below");
  EXPECT_THAT(surge["outside_prior"][0]["finding"].get<std::string>(),
              HasSubstr("the logged force smaller"));
  EXPECT_THAT(run_.out, HasSubstr("lies below the vehicle file's a priori range [990, 1125] kg"));
}

TEST_F(OutsidePriorCli, AnEstimateInsideTheRangeIsNoFinding) {
  const nlohmann::json surge = IdentifyWithAddedMass("[0.1, 1.2]");
  EXPECT_TRUE(surge["outside_prior"].empty()) << surge["outside_prior"].dump();
  EXPECT_THAT(run_.out, ::testing::Not(HasSubstr("OUTSIDE THE A PRIORI RANGE")));
}

}  // namespace
}  // namespace uuvplan::cli_test
