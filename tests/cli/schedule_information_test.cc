// The schedule JSON's information table (docs/cli.md "The schedule JSON"):
// per trial and per DOF the Fisher information with parameter names, the D/A/E criteria, the
// predicted σ and the condition number — recomputed here from the matrix written, the DOF's
// matrix the sum of its trials', and its nominal σ never above the planner's worst-case σ.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::cli_test {
namespace {

using nlohmann::json;

Eigen::MatrixXd Matrix(const json& rows) {
  const int n = static_cast<int>(rows.size());
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) M(i, j) = rows[i][j].get<double>();
  }
  return M;
}

// The DOF's block: every number recomputed from its matrix and nominal values.
void CheckBlock(const std::string& dof, const json& b, const json& worst_sigma) {
  const Eigen::MatrixXd M = Matrix(b["fisher"]);
  const int n = static_cast<int>(b["parameters"].size());
  ASSERT_EQ(M.rows(), n) << dof;
  EXPECT_EQ(b["units"].size(), b["parameters"].size()) << dof;
  // Symmetric to round-off (the JSON keeps 17 digits).
  EXPECT_LE((M - M.transpose()).norm(), 1e-12 * M.norm()) << dof;
  Eigen::VectorXd d(n);
  // criteria.h: D = diag(|θ_i|), a unit scale where θ_i = 0 (a bias's nominal value).
  for (int i = 0; i < n; ++i) {
    const double theta = std::abs(b["theta"][i].get<double>());
    d[i] = theta > 0 ? theta : 1.0;
  }
  const Eigen::MatrixXd R = d.asDiagonal() * M * d.asDiagonal();
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(R).eigenvalues();
  ASSERT_FALSE(b["criteria"]["singular"].get<bool>()) << dof << ": the schedule determines it";
  // 1e-8: the same sums in another order (log det from eigenvalues, not Cholesky).
  EXPECT_NEAR(b["criteria"]["D"].get<double>(), lambda.array().log().sum(), 1e-8) << dof;
  EXPECT_NEAR(b["criteria"]["E"].get<double>(), std::log(lambda.minCoeff()), 1e-8) << dof;
  EXPECT_NEAR(b["criteria"]["A"].get<double>(), -std::log(R.inverse().trace()), 1e-8) << dof;
  EXPECT_NEAR(b["condition_number"].get<double>() / (lambda.maxCoeff() / lambda.minCoeff()), 1.0,
              1e-8)
      << dof;
  const Eigen::MatrixXd C = M.inverse();
  for (int i = 0; i < n; ++i) {
    const std::string name = b["parameters"][i];
    const double sigma = b["sigma"][name].get<double>();
    EXPECT_NEAR(sigma / std::sqrt(C(i, i)), 1.0, 1e-8) << dof << " " << name;
    // The planner's σ is the worst over the box, whose centre is this point (1e-9: round-off).
    ASSERT_TRUE(worst_sigma.contains(name)) << dof << " " << name;
    EXPECT_LE(sigma, worst_sigma[name].get<double>() * (1 + 1e-9)) << dof << " " << name;
  }
}

// ... and say what they rest on: an answer that depends on an assumption says so where it is
// printed. Every predicted σ rests on the model as given, white sensor noise and each trial's
// start estimated (docs/planning.md, "Initial state"): `schedule` prints that sentence beside
// its σ and the JSON carries it beside `predicted` and `information` (`next`, `loop` and `demo`
// print it from the same constant; Cli.DemoTellsTheRomeoStory).
TEST(ScheduleInformation, RomeoTablesAgreeWithTheirMatrices) {
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";
  const TempDir scratch;
  const ToolRun run = RunTool("schedule " + dir + "vehicle.yaml --pool " + dir +
                                  "pool.yaml --json " + (scratch / "plan.json"),
                              scratch);
  ASSERT_TRUE(run.status == 0 || run.status == 1) << run.err;
  EXPECT_NE(run.out.find(std::string("assumption: ") + planner::kPredictedSigmaAssumption),
            std::string::npos)
      << run.out;
  const json j = json::parse(ReadText(scratch / "plan.json"));
  ASSERT_TRUE(j.contains("information"));
  EXPECT_EQ(j["information"]["assumption"], planner::kPredictedSigmaAssumption);
  EXPECT_FALSE(j["predicted"].empty());
  for (const auto& [dof, p] : j["predicted"].items()) {
    EXPECT_EQ(p["assumption"], planner::kPredictedSigmaAssumption) << dof;
  }
  const json& dofs = j["information"]["dofs"];
  ASSERT_EQ(dofs.size(), j["predicted"].size());
  for (const auto& [dof, block] : dofs.items()) {
    CheckBlock(dof, block, j["predicted"][dof]["sigma"]);
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(static_cast<int>(block["parameters"].size()),
                                                static_cast<int>(block["parameters"].size()));
    for (const json& t : j["trials"]) {
      if (t["dof"] != dof) continue;
      ASSERT_TRUE(t.contains("information")) << t["id"];
      EXPECT_EQ(t["information"]["parameters"], block["parameters"]) << t["id"];
      sum += Matrix(t["information"]["fisher"]);
    }
    const Eigen::MatrixXd total = Matrix(block["fisher"]);
    EXPECT_LE((sum - total).norm(), 1e-12 * total.norm()) << dof;  // round-off of the sum
  }
}

}  // namespace
}  // namespace uuvplan::cli_test
