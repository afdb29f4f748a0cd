// `uuvplan schedule VEHICLE --pool POOL --model coupled`: the per-DOF planner's
// options are refused, not ignored; a coupled plan runs through `simulate` and `identify --model
// coupled`. The planner itself is tested in tests/planner/coupled_design_test.cc (5–16 s a
// plan; the plan below is written by hand, in the schedule JSON's form).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/coupled_model.h"

namespace uuvplan::cli_test {
namespace {

TEST(CoupledScheduleCli, OptionsOfThePerDofPlannerAreRefusedNotIgnored) {
  // Refused before any file is read (exit 2, naming every option given).
  TempDir scratch;
  const ToolRun run =
      RunTool("schedule '" + (scratch / "none.yaml") + "' --pool '" + (scratch / "none.yaml") +
                  "' --model coupled --dof surge --no-steady",
              scratch);
  EXPECT_EQ(run.status, 2) << run.out << run.err;
  const std::string text = run.out + run.err;
  EXPECT_NE(text.find("--model coupled"), std::string::npos) << text;
  EXPECT_NE(text.find("no --dof, --no-steady"), std::string::npos) << text;
}

// A surge+sway+yaw plan as `schedule --model coupled --json` writes it (the ASV design of
// planning.md §5, rounded), its first `inputs` inputs kept.
std::string CoupledPlan(const std::string& mode, int inputs) {
  nlohmann::json in = nlohmann::json::array({{{"dof", "surge"},
                                              {"mapping", "horizontal-all-surge"},
                                              {"kind", "sine"},
                                              {"offset", 3.4},
                                              {"amplitude", 41.7},
                                              {"omega", 0.175}},
                                             {{"dof", "sway"},
                                              {"mapping", "horizontal-all-sway"},
                                              {"kind", "sine"},
                                              {"offset", 41.7},
                                              {"amplitude", 57.9},
                                              {"omega", 0.365}},
                                             {{"dof", "yaw"},
                                              {"mapping", "horizontal-all-yaw"},
                                              {"kind", "sine"},
                                              {"offset", 201.4},
                                              {"amplitude", 20.2},
                                              {"omega", 0.774}}});
  in.erase(in.begin() + inputs, in.end());
  const nlohmann::json plan = {
      {"model", "coupled-horizontal"},
      {"trial", {{"id", "combined"}, {"mode", mode}, {"duration", 120}, {"inputs", in}}}};
  return plan.dump();
}

// schedule → simulate → identify for the coupled model from the command line: the campaign the
// plan makes identifies the inertias within 3σ of the truth (a 0.3% chance each to miss).
TEST(CoupledScheduleCli, ACoupledPlanIsSimulatedAndIdentified) {
  TempDir scratch;
  { std::ofstream(scratch / "plan.json") << CoupledPlan("surge+sway+yaw", 3); }
  const std::string truth = std::string(UUVPLAN_SOURCE_DIR) + "/cases/asv/truth.yaml";
  const ToolRun sim =
      RunTool("simulate --truth '" + truth + "' --plan '" + (scratch / "plan.json") + "' --out '" +
                  (scratch / "run") + "' --seed 4",
              scratch);
  ASSERT_EQ(sim.status, 0) << sim.out << sim.err;
  EXPECT_NE(sim.out.find("--model coupled"), std::string::npos) << sim.out;
  const ToolRun id = RunTool(
      "identify '" + (scratch / "run") + "' --model coupled --json '" + (scratch / "id.json") + "'",
      scratch);
  ASSERT_EQ(id.status, 0) << id.out << id.err;
  const nlohmann::json j = nlohmann::json::parse(ReadText(scratch / "id.json"));
  const model::Truth t = io::ReadTruth(truth);
  const model::MultiDofModel coupled = model::CoupledHorizontalModel(t.vehicle);
  const Eigen::VectorXd want = model::CoupledThetaOfTruth(coupled, t);
  for (model::Dof dof : model::kHorizontalDofs) {
    const std::string name = std::string(model::DofName(dof)) + ".m";
    const auto& p = j.at("params").at(name);
    EXPECT_LT(std::abs(p.at("value").get<double>() - want[coupled.ParameterIndex(name)]),
              3 * p.at("sigma").get<double>())
        << name;
  }
}

// A coupled plan whose inputs do not match its mode is refused with the file and key (exit 2),
// before anything is written.
TEST(CoupledScheduleCli, ACoupledPlanThatDoesNotMatchItsModeIsRefused) {
  TempDir scratch;
  { std::ofstream(scratch / "plan.json") << CoupledPlan("surge+sway+yaw", 2); }
  const ToolRun sim = RunTool("simulate --truth '" + std::string(UUVPLAN_SOURCE_DIR) +
                                  "/cases/asv/truth.yaml' --plan '" + (scratch / "plan.json") +
                                  "' --out '" + (scratch / "run") + "'",
                              scratch);
  EXPECT_EQ(sim.status, 2) << sim.out << sim.err;
  const std::string text = sim.out + sim.err;
  EXPECT_NE(text.find("plan.json"), std::string::npos) << text;
  EXPECT_NE(text.find("trial.inputs"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(scratch / "run") / "campaign.yaml"));
}

}  // namespace
}  // namespace uuvplan::cli_test
