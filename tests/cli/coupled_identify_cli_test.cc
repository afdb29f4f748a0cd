// `uuvplan identify CAMPAIGN --model coupled`: a virtual combined-mode campaign of
// cases/asv written to disk, identified from the command line, its JSON within 3σ of the truth.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "support/coupled_campaign.h"
#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/coupled_model.h"

namespace uuvplan::cli_test {
namespace {

TEST(CoupledIdentifyCli, IdentifiesACombinedModeCampaign) {
  const model::Truth truth =
      io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/cases/asv/truth.yaml");
  const auto designs = testing::CombinedModeDesigns(120.0);
  auto logs = testing::RunCoupledCampaign(truth, designs, 21);
  model::Campaign campaign;
  campaign.vehicle_file = "vehicle.yaml";
  campaign.vehicle = truth.vehicle;
  double clock = 0.0;
  for (std::size_t i = 0; i < logs.size(); ++i) {
    model::TrialEntry e;
    e.file = "trials/" + designs[i].id + ".csv";
    e.dof = designs[i].inputs.front().dof;  // a combined trial is listed under one of its DOFs
    e.mapping = designs[i].inputs.front().mapping;
    e.start = clock;
    e.has_start = true;
    e.log = std::move(logs[i]);
    campaign.trials.push_back(std::move(e));
    clock += designs[i].duration + 60.0;
  }
  TempDir scratch;
  io::WriteCampaign(scratch / "campaign", campaign, truth.vehicle);
  const ToolRun run = RunTool("identify '" + (scratch / "campaign") + "' --model coupled --json '" +
                                  (scratch / "id.json") + "'",
                              scratch);
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("coupled horizontal model"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("kg·m²"), std::string::npos) << run.out;  // units on every number
  const nlohmann::json j = nlohmann::json::parse(ReadText(scratch / "id.json"));
  ASSERT_EQ(j.at("status"), "ok");
  const model::MultiDofModel coupled = model::CoupledHorizontalModel(truth.vehicle);
  const Eigen::VectorXd want = model::CoupledThetaOfTruth(coupled, truth);
  const std::vector<std::string>& names = coupled.parameter_names();
  ASSERT_EQ(names.size(), 12u);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& p = j.at("params").at(names[k]);
    EXPECT_LT(std::abs(p.at("value").get<double>() - want[k]), 3 * p.at("sigma").get<double>())
        << names[k];
  }
}

TEST(CoupledIdentifyCli, OptionsOfThePerDofChainAreRefusedNotIgnored) {
  // Before, `--model coupled --method rls` ran the coupled estimator and ignored --method.
  // Refused before any file is read (exit 2, naming every option given).
  TempDir scratch;
  const ToolRun run = RunTool("identify '" + (scratch / "none.yaml") +
                                  "' --model coupled --method rls --dof surge --no-prune",
                              scratch);
  EXPECT_EQ(run.status, 2) << run.out << run.err;
  const std::string text = run.out + run.err;
  EXPECT_NE(text.find("--model coupled"), std::string::npos) << text;
  EXPECT_NE(text.find("no --dof, --no-prune, --method"), std::string::npos) << text;
}

}  // namespace
}  // namespace uuvplan::cli_test
