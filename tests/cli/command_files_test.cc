// `schedule --commands DIR`: the command files replayed through the
// simulator at the corners of the a priori box (the DOF's ParameterBox) as the pool
// would run them — each thruster's command held until the next row, turned into thrust by the
// thruster's model and into the DOF's force through the mapping the working thrusters form —
// find no propeller reversal, no thruster beyond its command range or under min_thrust, and no
// wall reached from the run sheet's start, on the ROMEO, VSOR and URIS schedules and on ROMEO
// driven by PWM (commands about a neutral of 1500 µs).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::cli_test {
namespace {

struct CommandRows {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

CommandRows ReadCommandCsv(const std::string& path) {
  CommandRows c;
  std::istringstream in(ReadText(path));
  std::string line, cell;
  std::getline(in, line);
  for (std::istringstream h(line); std::getline(h, cell, ',');) c.header.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (std::istringstream r(line); std::getline(r, cell, ',');) row.push_back(std::stod(cell));
    c.rows.push_back(row);
  }
  return c;
}

// The run sheet's start of each trial: its coordinate along the trial's axis (m from the wall
// behind, or the depth) or, for a rotation, the tether's start twist (rad).
std::map<std::string, double> StartsFromRunSheet(const std::string& text) {
  std::map<std::string, double> starts;
  const std::regex row(
      R"(\| \d+ \| (\S+) \| (\w+) \|[^|]*\|[^|]*\| x (\S+) m, y (\S+) m, z (\S+) m \| 0°(, tether twisted ([-+0-9.e]+)°)?)");
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    const std::string dof = m[2];
    if (m[7].matched) {
      starts[m[1]] = std::stod(m[7]) * M_PI / 180.0;
    } else {
      starts[m[1]] = std::stod(dof == "surge" ? m[3] : dof == "sway" ? m[4] : m[5]);
    }
  }
  return starts;
}

// Every translation's start and abort lines on the run sheet are marked to the centimetre
// ("1.60 m", command_sheet.h) and the abort lines are the margin lines seen from that start,
// each within the 5 mm of its rounding. Returns the number of translation rows checked.
int ExpectMarkedToTheCentimetre(const std::string& sheet, const model::Pool& pool) {
  const std::regex row(
      R"(^\| \d+ \| (\S+) \| (surge|sway|heave) \|[^|]*\|[^|]*\| x (\S+) m, y (\S+) m, z (\S+) m \|[^|]*\|[^|]*\|[^|]*\| (\S+) m / (\S+) m \|)");
  const std::regex centimetres(R"([-+]?\d+\.\d\d)");
  std::istringstream in(sheet);
  int rows = 0;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    ++rows;
    for (int i : {3, 4, 5, 6, 7}) {
      EXPECT_TRUE(std::regex_match(m[i].str(), centimetres)) << m[1] << ": " << m[i];
    }
    const model::Dof dof = *model::ParseDof(m[2].str());
    const double start = std::stod(m[dof == model::Dof::kSurge  ? 3
                                     : dof == model::Dof::kSway ? 4
                                                                : 5]);
    // 5 mm of rounding, 1e-9 for the decimal text.
    EXPECT_NEAR(start + std::stod(m[6]), pool.margin, 0.005 + 1e-9) << m[1];
    EXPECT_NEAR(start + std::stod(m[7]), pool.WallToWall(dof) - pool.margin, 0.005 + 1e-9) << m[1];
  }
  return rows;
}

// φ_n and the mapping the non-idle thrusters of a row form: the mapping of `dof` whose thrusters
// are exactly those, φ_n = Σ share_i·τ_i / Σ share_i² (τ_i = share_i·φ_n, ref 000 Table I).
void ForceOfRow(const model::Vehicle& v, model::Dof dof, const std::vector<double>& row,
                double* phi, int* mapping) {
  *phi = 0.0;
  *mapping = -1;
  std::vector<bool> working(v.thrusters.size());
  for (std::size_t i = 0; i < v.thrusters.size(); ++i) {
    working[i] = row[1 + i] != v.thrusters[i].neutral;
  }
  for (int m = 0; m < static_cast<int>(v.mappings.size()); ++m) {
    if (v.mappings[m].dof != dof) continue;
    std::vector<bool> uses(v.thrusters.size());
    double num = 0, den = 0;
    for (const auto& [i, share] : v.mappings[m].shares) {
      uses[i] = share != 0.0;
      num += share * v.thrusters[i].Thrust(row[1 + i]);
      den += share * share;
    }
    if (uses == working && den > 0) *phi = num / den, *mapping = m;
  }
}

void CheckThrusters(const model::Vehicle& v, const std::string& id, const CommandRows& c) {
  for (std::size_t i = 0; i < v.thrusters.size(); ++i) {
    const model::Thruster& th = v.thrusters[i];
    ASSERT_EQ(c.header[1 + i], th.name);
    int sign = 0;
    for (const auto& row : c.rows) {
      const double u = row[1 + i];
      EXPECT_GE(u, th.command_min) << id << " " << th.name << " below its command range";
      EXPECT_LE(u, th.command_max) << id << " " << th.name << " beyond its command range";
      if (u == th.neutral) continue;
      // 1e-6 relative: the file's 8 significant digits of the command, squared by the model.
      EXPECT_GE(std::abs(th.Thrust(u)), v.min_thrust * (1 - 1e-6)) << id << " " << th.name;
      const int s = u > th.neutral ? 1 : -1;
      EXPECT_TRUE(sign == 0 || s == sign) << id << " " << th.name << " reverses";
      sign = s;
    }
  }
}

// Position extremes over the box of the replayed commands, from the start (m or rad).
std::array<double, 2> ReplayOverBox(const model::Vehicle& v, const model::Pool& pool,
                                    model::Dof dof, const CommandRows& c) {
  std::vector<double> t, phi;
  std::vector<int> mapping;
  for (const auto& row : c.rows) {
    double f;
    int m;
    ForceOfRow(v, dof, row, &f, &m);
    t.push_back(row[0]);
    phi.push_back(f);
    mapping.push_back(m);
  }
  const double duration = t.back();
  const auto input = model::MakeHeldExcitation(t, phi, mapping, duration);
  std::vector<std::string> notes;
  const auto ctx = planner::DofPlanningProblem::APriori(v, pool, dof,
                                                        planner::ScheduleOptions{}.planner, &notes);
  // Output at every row (the held commands change only there). An extreme of the position falls
  // where the velocity crosses zero, so rows 50 ms apart miss at most ½·a·(25 ms)², under 1 mm
  // at these vehicles' accelerations (< 1 m/s²).
  std::vector<double> times;
  for (const auto& row : c.rows) times.push_back(row[0]);
  model::TrialConditions conditions;
  conditions.input = input.get();
  model::SimulationOptions so;
  so.step_s = 0.02;
  std::array<double, 2> travel = {0, 0};
  for (const planner::ParameterValues& corner : ctx->box().CheckPoints(2)) {  // the corners
    const Eigen::VectorXd theta = ctx->model().Theta(corner);
    const model::Trajectory x = model::Simulate(ctx->model(), theta, conditions, times, so);
    travel[0] = std::min(travel[0], x.x.col(0).minCoeff());
    travel[1] = std::max(travel[1], x.x.col(0).maxCoeff());
  }
  return travel;
}

// Plans `vehicle_file` in `pool_file` (`schedule` with `args`), replays every trial's command
// file and returns them by trial id.
std::map<std::string, CommandRows> ReplaySchedule(const std::string& vehicle_file,
                                                  const std::string& pool_file,
                                                  const std::string& args) {
  const TempDir scratch;
  const ToolRun run =
      RunTool("schedule '" + vehicle_file + "' --pool '" + pool_file + "' " + args + " --json '" +
                  (scratch / "plan.json") + "' --commands '" + (scratch / "commands") + "'",
              scratch);
  std::map<std::string, CommandRows> files;
  EXPECT_TRUE(run.status == 0 || run.status == 1) << run.err;
  if (run.status != 0 && run.status != 1) return files;
  const model::Vehicle v = io::ReadVehicle(vehicle_file);
  const model::Pool pool = io::ReadPool(pool_file);
  const planner::Schedule plan = io::ReadScheduleJson(scratch / "plan.json");
  const auto starts = StartsFromRunSheet(ReadText(scratch / "commands/run_sheet.md"));
  EXPECT_FALSE(plan.trials.empty());
  const auto translations =
      std::count_if(plan.trials.begin(), plan.trials.end(),
                    [](const auto& t) { return !model::IsRotational(t.design.dof); });
  EXPECT_EQ(ExpectMarkedToTheCentimetre(ReadText(scratch / "commands/run_sheet.md"), pool),
            translations);
  for (const planner::PlannedTrial& trial : plan.trials) {
    const std::string& id = trial.design.id;
    const model::Dof dof = trial.design.dof;
    const CommandRows c = ReadCommandCsv(scratch / ("commands/" + id + ".csv"));
    files[id] = c;
    EXPECT_EQ(c.header.size(), v.thrusters.size() + 2) << id;
    if (c.header.size() != v.thrusters.size() + 2) continue;
    CheckThrusters(v, id, c);
    EXPECT_EQ(starts.count(id), 1u) << id << " not on the run sheet";
    if (starts.count(id) != 1) continue;
    const std::array<double, 2> travel = ReplayOverBox(v, pool, dof, c);
    const double start = starts.at(id);
    // Margin lines from the run sheet's start; 1 cm (or 0.1°) of tolerance: the start is marked
    // to the centimetre (5 mm) and the held commands move the vehicle by millimetres from the
    // planned continuous sine.
    const bool rotation = model::IsRotational(dof);
    const double tolerance = rotation ? 0.1 * M_PI / 180 : 0.01;
    const double low = rotation ? -pool.FreeTravel(dof) / 2 : pool.margin;
    const double high = rotation ? pool.FreeTravel(dof) / 2 : pool.WallToWall(dof) - pool.margin;
    EXPECT_GE(start + travel[0], low - tolerance)
        << vehicle_file << " " << id << " crosses the margin";
    EXPECT_LE(start + travel[1], high + tolerance)
        << vehicle_file << " " << id << " crosses the margin";
  }
  return files;
}

void ReplayCase(const std::string& name) {
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + name;
  ReplaySchedule(dir + "/vehicle.yaml", dir + "/pool.yaml", "");
}

TEST(CommandFiles, RomeoReplayStaysWithinLimitsAndWalls) { ReplayCase("romeo"); }
TEST(CommandFiles, VsorReplayStaysWithinLimitsAndWalls) { ReplayCase("vsor"); }
TEST(CommandFiles, UrisReplayStaysWithinLimitsAndWalls) { ReplayCase("uris"); }

// ROMEO's thrusters driven by PWM: an ESC takes 1100–1900 µs and stops at 1500, and
// V = (u − 1500 µs)/40 maps that onto ROMEO's ±10 V, so c = c_V/40² per µs². Every command
// file stays in [1100, 1900], idles and stops every thruster at exactly 1500, and replays like
// ROMEO's (yaw: the DOF whose mappings use all four horizontal thrusters).
TEST(CommandFiles, PwmDrivenRomeoStaysInItsRangeAndStopsAtNeutral) {
  const std::string romeo = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";
  std::string text = ReadText(romeo + "vehicle.yaml");
  const std::string volts = "thrust: {model: square, c_pos: 1.02, c_neg: 1.09}, command: [-10, 10]";
  const std::string pwm =
      "thrust: {model: square, c_pos: 0.0006375, c_neg: 0.00068125}, command: [1100, 1900], "
      "neutral: 1500";
  int replaced = 0;
  for (std::size_t at; (at = text.find(volts)) != std::string::npos; ++replaced) {
    text.replace(at, volts.size(), pwm);
  }
  ASSERT_EQ(replaced, 8);  // every thruster of ROMEO
  const TempDir scratch;
  scratch.Write("vehicle.yaml", text);
  const auto files = ReplaySchedule(scratch / "vehicle.yaml", romeo + "pool.yaml", "--dof yaw");
  ASSERT_FALSE(files.empty());
  for (const auto& [id, c] : files) {
    ASSERT_FALSE(c.rows.empty()) << id;
    int driven = 0;
    for (const auto& row : c.rows) {
      for (std::size_t i = 1; i + 1 < row.size(); ++i) driven += row[i] != 1500.0;
    }
    EXPECT_GT(driven, 0) << id << ": no thruster driven";
    const auto& last = c.rows.back();
    for (std::size_t i = 1; i + 1 < last.size(); ++i) {
      EXPECT_EQ(last[i], 1500.0) << id << " " << c.header[i] << " does not stop at neutral";
    }
  }
}

TEST(CommandFiles, AnExistingDirectoryIsNeverOverwritten) {
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo";
  const TempDir scratch;
  std::filesystem::create_directories(scratch / "commands");
  scratch.Write("commands/keep.txt", "mine");
  const ToolRun run = RunTool("schedule '" + dir + "/vehicle.yaml' --pool '" + dir +
                                  "/pool.yaml' --commands '" + (scratch / "commands") + "'",
                              scratch);
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_EQ(run.err.rfind("uuvplan:", 0), 0u) << run.err;
  EXPECT_EQ(ReadText(scratch / "commands/keep.txt"), "mine");
  EXPECT_FALSE(std::filesystem::exists(scratch / "commands/run_sheet.md"));
}

}  // namespace
}  // namespace uuvplan::cli_test
