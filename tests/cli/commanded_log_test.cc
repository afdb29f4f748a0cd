// A trial logged as thruster commands (cmd_<thruster> columns, docs/formats.md "Trial log")
// identifies to the same estimates as the same trials with the nominal force worked out by
// hand from those commands: on cases/bluerov2 (geometry-derived mappings, the T200's dead band).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/trial_log_csv.h"
#include "uuvplan/io/virtual_campaign.h"

namespace uuvplan::cli {
namespace {

namespace fs = std::filesystem;
using cli_test::ReadText;
using cli_test::RunTool;
using cli_test::TempDir;
using cli_test::ToolRun;
using ::testing::HasSubstr;

// The T200 of cases/bluerov2 written out here (its file's numbers, checked below): thrust
// c·V|V| (seed 000 eq. 6), c = 51.5 N forward and 40 N reverse, none within 0.0625 of neutral.
double T200Thrust(double v) {
  if (std::abs(v) < 0.0625) return 0.0;
  return (v >= 0 ? 51.5 : 40.0) * v * std::abs(v);
}

// A setpoint as a 1e-4 step controller sends it: not the exact inverse of the force.
double Quantised(double v) { return std::round(v * 1e4) / 1e4; }

std::vector<model::TrialDesign> SurgeDesigns(const std::string& mapping) {
  model::TrialDesign legs;
  legs.id = "legs";
  legs.dof = model::Dof::kSurge;
  legs.kind = model::TrialKind::kSegments;
  legs.mapping = mapping;
  for (double f : {6.0, 12.0, 18.0, 24.0}) {
    legs.segments.push_back({f, 15.0, ""});
    legs.duration += 15.0;
  }
  model::TrialDesign sine = legs;
  sine.id = "sine";
  sine.kind = model::TrialKind::kSine;
  sine.segments.clear();
  sine.offset = 12.0;  // 12 ± 7 N: every thruster clear of its dead band (0.2 N)
  sine.amplitude = 7.0;
  sine.omega = 2 * M_PI / 8.0;
  sine.duration = 64.0;
  return {legs, sine};
}

// Writes the trial `id` of the simulated campaign twice: as commands (cmd_<thruster>) into
// `commanded`, and as the force computed by hand from the same commands into `by_hand`.
void WriteBothLogs(const model::Vehicle& v, const model::TrialDesign& d, const fs::path& sim,
                   const fs::path& commanded, const fs::path& by_hand) {
  const std::string file = "trials/" + d.id + ".csv";
  const model::TrialLog simulated = io::ReadTrialLog((sim / file).string());
  const auto& phi = simulated.force[model::Index(d.dof)];
  const model::ThrustMapping& m = v.mappings[v.MappingIndex(d.mapping)];
  model::TrialLog cmd = simulated, hand = simulated;
  cmd.force = {};
  std::vector<double> fit(phi.size(), 0.0);
  double norm = 0.0;
  for (std::size_t i = 0; i < v.thrusters.size(); ++i) {
    double share = 0.0;
    for (const auto& [ti, s] : m.shares) share = ti == static_cast<int>(i) ? s : share;
    norm += share * share;
    std::vector<double>& column = cmd.commands[v.thrusters[i].name];
    for (std::size_t r = 0; r < phi.size(); ++r) {
      column.push_back(Quantised(v.thrusters[i].Command(share * phi[r])));
      fit[r] += share * T200Thrust(column.back());  // tau_i = share_i·phi, least squares
    }
  }
  for (double& f : fit) f /= norm;
  hand.force = {};
  hand.force[model::Index(d.dof)] = fit;
  io::WriteTrialLog((commanded / file).string(), cmd);
  io::WriteTrialLog((by_hand / file).string(), hand);
}

std::map<std::string, std::pair<double, double>> Estimates(const std::string& json) {
  std::map<std::string, std::pair<double, double>> out;
  const auto j = nlohmann::json::parse(ReadText(json));
  for (const auto& [name, p] : j["dofs"]["surge"]["params"].items()) {
    out[name] = {p["value"].get<double>(), p["sigma"].get<double>()};
  }
  return out;
}

TEST(CommandedLog, IdentifiesAsTheForceComputedByHand) {
  const TempDir dir;
  const std::string cases = std::string(UUVPLAN_SOURCE_DIR) + "/cases/bluerov2/";
  const model::Truth truth = io::ReadTruth(cases + "truth.yaml");
  const model::Vehicle& v = truth.vehicle;
  for (const model::Thruster& t : v.thrusters) {  // T200Thrust is this file's thrust model
    ASSERT_EQ(t.model.kind, model::ThrustModel::Kind::kSquare);
    ASSERT_EQ(t.model.c_pos, 51.5);
    ASSERT_EQ(t.model.c_neg, 40.0);
    ASSERT_EQ(t.model.dead_band, 0.0625);
    ASSERT_EQ(t.neutral, 0.0);
  }
  const std::string mapping = v.mappings[v.MappingsOf(model::Dof::kSurge).front()].name;
  const std::vector<model::TrialDesign> designs = SurgeDesigns(mapping);
  model::VirtualCampaignOptions options;
  options.seed = 11;
  const fs::path sim = dir / "sim", commanded = dir / "cmd", by_hand = dir / "hand";
  io::SimulateCampaign(truth, designs, sim.string(), options);
  for (const fs::path& to : {commanded, by_hand}) {
    fs::create_directories(to / "trials");
    fs::copy_file(sim / "campaign.yaml", to / "campaign.yaml");
    fs::copy_file(sim / "vehicle.yaml", to / "vehicle.yaml");
  }
  for (const model::TrialDesign& d : designs) WriteBothLogs(v, d, sim, commanded, by_hand);
  EXPECT_THAT(ReadText((commanded / "trials/sine.csv").string()), HasSubstr(",cmd_FR,"));
  for (const fs::path& c : {commanded, by_hand}) {
    const ToolRun run = RunTool(
        "identify '" + c.string() + "' --dof surge --json '" + (c / "id.json").string() + "'", dir);
    ASSERT_EQ(run.status, 0) << run.out << run.err;
  }
  const auto a = Estimates((commanded / "id.json").string());
  const auto b = Estimates((by_hand / "id.json").string());
  ASSERT_TRUE(a.count("m") && a.count("k") && a.count("kq"))
      << ReadText((commanded / "id.json").string());
  ASSERT_EQ(a.size(), b.size());
  // The by-hand force is written with 10 significant digits; the commands are exact (1e-4
  // steps): the two forces differ by ~1e-10 relative, and so do the estimates, far below 1e-6.
  for (const auto& [name, value] : a) {
    ASSERT_TRUE(b.count(name)) << name;
    EXPECT_NEAR(value.first, b.at(name).first, 1e-6 * std::abs(b.at(name).first)) << name;
    EXPECT_NEAR(value.second, b.at(name).second, 1e-6 * b.at(name).second) << name;
  }
  // `log` takes a log of commands as the campaign does (the log is read through the vehicle).
  const ToolRun logged =
      RunTool("log '" + by_hand.string() + "' '" + (commanded / "trials/sine.csv").string() +
                  "' --trial sine_cmd --dof surge --mapping " + mapping,
              dir);
  EXPECT_EQ(logged.status, 0) << logged.out << logged.err;
}

}  // namespace
}  // namespace uuvplan::cli
