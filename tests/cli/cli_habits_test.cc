// The command line's habits (docs/cli.md "Common rules"): --version from
// CMake's project(), an unknown command or option named with the closest known name by edit
// distance, every error — CLI11's own parse errors included — starting with "uuvplan:", and
// the same exit status (2) for every usage error of every command.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// The commands `uuvplan --help` lists (CLI11 prints them under "Subcommands:").
std::vector<std::string> Commands(const TempDir& scratch) {
  std::vector<std::string> names;
  std::istringstream in(RunTool("--help", scratch).out);
  bool listed = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("Subcommands:", 0) == 0) listed = true;
    std::istringstream words(line);
    std::string name;
    if (listed && line.size() > 2 && line[0] == ' ' && words >> name) names.push_back(name);
  }
  return names;
}

TEST(CliHabits, VersionIsTheProjectVersion) {
  const TempDir scratch;
  const std::string cmake = ReadText(std::string(UUVPLAN_SOURCE_DIR) + "/CMakeLists.txt");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(cmake, m, std::regex(R"(project\(uuvplan VERSION ([0-9.]+))")));
  const ToolRun run = RunTool("--version", scratch);
  EXPECT_EQ(run.status, 0);
  EXPECT_EQ(run.out, "uuvplan " + m[1].str() + "\n");
}

TEST(CliHabits, UnknownCommandNamesTheClosestOne) {
  const TempDir scratch;
  const ToolRun foo = RunTool("foo", scratch);
  EXPECT_EQ(foo.status, 2);
  EXPECT_THAT(foo.err, StartsWith("uuvplan: unknown command 'foo' (did you mean 'loop'?)\n"));
  const ToolRun typo = RunTool("scedule x --pool y", scratch);
  EXPECT_EQ(typo.status, 2);
  EXPECT_THAT(typo.err,
              StartsWith("uuvplan: unknown command 'scedule' (did you mean 'schedule'?)"));
  const ToolRun far = RunTool("xyzzyplugh", scratch);
  EXPECT_EQ(far.status, 2);
  EXPECT_THAT(far.err, StartsWith("uuvplan: unknown command 'xyzzyplugh'\n"));  // no guess
}

TEST(CliHabits, UnknownOptionOfEveryCommandIsAUsageError) {
  const TempDir scratch;
  const std::vector<std::string> commands = Commands(scratch);
  ASSERT_GE(commands.size(), 9u);
  for (const std::string& c : commands) {
    const ToolRun run = RunTool(c + " --no-such-option", scratch);
    EXPECT_EQ(run.status, 2) << c;
    EXPECT_THAT(run.err, StartsWith("uuvplan: unknown option '--no-such-option' for '" + c + "'"))
        << c;
  }
  const ToolRun typo = RunTool("schedule v.yaml --pool p.yaml --jsn x", scratch);
  EXPECT_EQ(typo.status, 2);
  EXPECT_THAT(
      typo.err,
      StartsWith("uuvplan: unknown option '--jsn' for 'schedule' (did you mean '--json'?)"));
  const ToolRun top = RunTool("--verison", scratch);
  EXPECT_EQ(top.status, 2);
  EXPECT_THAT(top.err,
              StartsWith("uuvplan: unknown option '--verison' (did you mean '--version'?)"));
}

TEST(CliHabits, ParserErrorsStartWithTheProgramName) {
  const TempDir scratch;
  for (const std::string& args :
       {std::string(""), std::string("schedule"), std::string("schedule v.yaml"),
        std::string("schedule v.yaml --pool p.yaml --max-duration -3"),
        std::string("simulate --truth t.yaml --plan p.json --out d --seed abc"),
        std::string("log c.yaml")}) {
    const ToolRun run = RunTool(args, scratch);
    EXPECT_EQ(run.status, 2) << args;
    EXPECT_THAT(run.err, StartsWith("uuvplan: ")) << args;
  }
}

TEST(CliHabits, ATrialLongerThanAnHourIsRefusedNamingTheOption) {
  // --max-duration 1e9 (a unit slip) once ran into the simulation's work limit, whose message
  // ("position trace samples … a shorter trial") named no option.
  const TempDir scratch;
  const std::string romeo = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";
  for (const char* command : {"schedule", "check-pool"}) {
    const ToolRun run = RunTool(std::string(command) + " '" + romeo + "vehicle.yaml' --pool '" +
                                    romeo + "pool.yaml' --max-duration 1e9",
                                scratch);
    EXPECT_EQ(run.status, 2) << command;
    EXPECT_THAT(run.err, HasSubstr("--max-duration")) << command << run.err;
    EXPECT_THAT(run.err, HasSubstr("(0, 3600] s")) << command << run.err;
  }
}

TEST(CliHabits, BadInputOfEveryFileCommandStartsWithTheProgramName) {
  const TempDir scratch;
  const std::string missing = scratch / "missing.yaml";
  for (const std::string& args :
       {"schedule " + missing + " --pool " + missing,
        "check-pool " + missing + " --pool " + missing, "identify " + missing,
        "next " + missing + " --pool " + missing, "diagnose " + missing,
        "score " + missing + " " + missing, "loop --truth " + missing + " --pool " + missing,
        "simulate --truth " + missing + " --plan " + missing + " --out " + (scratch / "out"),
        "log " + missing + " " + missing + " --trial a --dof surge"}) {
    const ToolRun run = RunTool(args, scratch);
    EXPECT_EQ(run.status, 2) << args;
    EXPECT_THAT(run.err, StartsWith("uuvplan: error: ")) << args;
    EXPECT_THAT(run.err, HasSubstr("missing.yaml")) << args;
  }
}

}  // namespace
}  // namespace uuvplan::cli_test
