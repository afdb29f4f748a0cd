// The malformed-input suite: every case of tests/data/bad/cases/expectations.tsv
// (written by tests/data/bad/make_cases.py: mutations of every input format — vehicle, pool,
// truth, plan JSON, campaign, trial CSV — and command-line values) must exit with status 2, not
// crash or exit 3, with a message naming its file and line or key, and must not echo a file
// that is not of the expected format. Plus what must be accepted: a UTF-8 byte order mark,
// and an implausible value under --accept-implausible (as a warning).
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

const std::string kBadCases = std::string(UUVPLAN_SOURCE_DIR) + "/tests/data/bad/cases";
const std::string kData = std::string(UUVPLAN_SOURCE_DIR) + "/tests/data";

struct BadCase {
  std::string name, arguments;
  std::vector<std::string> must_contain;
  std::string must_not_contain;
};

// ctest and failures show the case's name, not its bytes.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

std::vector<std::string> Split(const std::string& text, const std::string& separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t at; (at = text.find(separator, start)) != std::string::npos;) {
    parts.push_back(text.substr(start, at - start));
    start = at + separator.size();
  }
  parts.push_back(text.substr(start));
  return parts;
}

std::vector<BadCase> ReadCases() {
  std::ifstream in(kBadCases + "/expectations.tsv");
  std::vector<BadCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = Split(line, "\t");
    if (cells.size() != 4) continue;  // counted by SuiteHasEveryFormat
    cases.push_back({cells[0], cells[1], Split(cells[2], " && "), cells[3]});
  }
  return cases;
}

std::string Substituted(std::string text, const std::string& out) {
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"{cases}", kBadCases},
                                   {"{data}", kData},
                                   {"{out}", out}}) {
    for (std::size_t at; (at = text.find(key)) != std::string::npos;)
      text.replace(at, key.size(), value);
  }
  return text;
}

class MalformedInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(MalformedInput, ExitsTwoNamingFileAndPlace) {
  const BadCase& c = GetParam();
  TempDir scratch;
  const ToolRun run = RunTool(Substituted(c.arguments, scratch / "out"), scratch);
  EXPECT_EQ(run.status, 2) << c.arguments << "\n" << run.err;
  for (const std::string& text : c.must_contain)
    EXPECT_NE(run.err.find(text), std::string::npos) << "expected '" << text << "' in:\n"
                                                     << run.err;
  if (!c.must_not_contain.empty())
    EXPECT_EQ(run.err.find(c.must_not_contain), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("internal error"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "out")) << "a refused run wrote its output";
}

std::string CaseName(const ::testing::TestParamInfo<BadCase>& info) {
  std::string name = info.param.name;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, MalformedInput, ::testing::ValuesIn(ReadCases()), CaseName);

// At least 60 cases, five or more per format.
TEST(MalformedInputSuite, HasSixtyCasesOverEveryFormat) {
  const std::vector<BadCase> cases = ReadCases();
  EXPECT_GE(cases.size(), 60u);
  for (const std::string prefix : {"vehicle_", "pool_", "truth_", "plan_", "campaign_", "csv_"}) {
    int n = 0;
    for (const BadCase& c : cases) n += c.name.rfind(prefix, 0) == 0;
    EXPECT_GE(n, 5) << prefix;
  }
}

// A spreadsheet's UTF-8 byte order mark before the header is not part of the column 't'.
TEST(WellFormedInput, CsvAndYamlWithByteOrderMarkAreRead) {
  TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  dir.Write("log.csv", bom + "t,force_surge,pos_surge\n0,100,0\n0.3,100,0.01\n0.6,100,0.04\n");
  std::ifstream vehicle(kData + "/io/vehicle.yaml");
  std::stringstream text;
  text << vehicle.rdbuf();
  dir.Write("vehicle.yaml", bom + text.str());
  dir.Write("campaign.yaml", bom +
                                 "vehicle: vehicle.yaml\ntrials:\n  - {file: log.csv, dof: surge, "
                                 "mapping: surge-front}\n");
  const ToolRun run = RunTool("identify '" + (dir / "campaign.yaml") + "' --dof surge", dir);
  EXPECT_EQ(run.err.find("error:"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("expected a 't' column"), std::string::npos) << run.err;
}

// --accept-implausible: the implausible value is read, with a warning naming file, line, key.
TEST(WellFormedInput, AcceptImplausibleWarnsInsteadOfRefusing) {
  TempDir dir;
  const std::string pool = dir.Write("lake.yaml", "name: lake\nlength: 2e5\nwidth: 12\ndepth: 4\n");
  const std::string args = "schedule " + kData + "/io/vehicle.yaml --dof surge --pool " + pool;
  const ToolRun refused = RunTool(args, dir);
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find(pool + ":2: length: implausible"), std::string::npos) << refused.err;
  const ToolRun accepted = RunTool(args + " --accept-implausible", dir);
  EXPECT_NE(accepted.status, 2) << accepted.err;
  EXPECT_NE(accepted.err.find("warning: " + pool + ":2: length: implausible"), std::string::npos)
      << accepted.err;
}

}  // namespace
}  // namespace uuvplan::cli_test
