// Campaign reader and writer (docs/formats.md §Campaign): the fixture, the shared real
// campaigns, and one test per malformed campaign.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io_test_util.h"
#include "support/real_data.h"
#include "uuvplan/io/io.h"

namespace uuvplan::model {
namespace {

using io::ReadCampaign;
using io::WriteCampaign;
using io::WriteCampaignYaml;

using ::testing::AllOf;
using testing::At;
using ::testing::ElementsAre;
using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::ScratchDir;
using uuvplan::testing::RealDataPath;

TEST(ReadCampaignTest, ReadsTheFixture) {
  const std::string path = testing::SourcePath("tests/data/io/campaign.yaml");
  const Campaign c = ReadCampaign(path);
  EXPECT_EQ(c.path, path);
  EXPECT_EQ(c.vehicle_file, "vehicle.yaml");
  EXPECT_EQ(c.vehicle.name, "romeo");
  ASSERT_TRUE(c.pool_file);
  EXPECT_EQ(*c.pool_file, "pool.yaml");
  EXPECT_EQ(c.pool->name, "genoa-pool");
  ASSERT_EQ(c.trials.size(), 3u);

  const TrialEntry& surge = c.trials[0];
  EXPECT_EQ(surge.file, "trials/surge_0.csv");
  EXPECT_EQ(surge.path, testing::SourcePath("tests/data/io/trials/surge_0.csv"));
  EXPECT_EQ(surge.dof, Dof::kSurge);
  EXPECT_EQ(surge.mapping, "surge-front");  // the vehicle's only surge mapping
  EXPECT_EQ(surge.ballast_steps, 0);
  EXPECT_EQ(surge.use, TrialUse::kFit);
  EXPECT_TRUE(surge.has_start);
  EXPECT_EQ(surge.start, 0.0);
  EXPECT_EQ(surge.log.size(), 5u);

  const TrialEntry& heave = c.trials[1];
  EXPECT_EQ(heave.mapping, "vertical-all");
  EXPECT_EQ(heave.ballast_steps, 2);
  EXPECT_EQ(heave.use, TrialUse::kValidate);
  EXPECT_EQ(heave.start, 120.5);
  EXPECT_THAT(heave.log.mapping, ElementsAre(0, -1, 1, 1));

  const TrialEntry& yaw = c.trials[2];
  EXPECT_FALSE(yaw.has_start);
  EXPECT_EQ(yaw.use, TrialUse::kFit);
  EXPECT_EQ(yaw.log.notes.size(), 1u);  // the heading was unwrapped
}

// Every command that takes a campaign accepts its directory too.
TEST(ReadCampaignTest, ADirectoryStandsForItsCampaignYaml) {
  const Campaign by_file = ReadCampaign(testing::SourcePath("tests/data/io/campaign.yaml"));
  const Campaign by_dir = ReadCampaign(testing::SourcePath("tests/data/io"));
  EXPECT_EQ(by_dir.path, by_file.path);
  ASSERT_EQ(by_dir.trials.size(), by_file.trials.size());
  EXPECT_EQ(by_dir.trials[0].path, by_file.trials[0].path);
  EXPECT_EQ(by_dir.trials[0].log.t, by_file.trials[0].log.t);
}

// A log copied under another name (`uuvplan log` twice with new ids) is the same data counted
// twice, however it is named: refused as the same path is (exit 2 in the tool), a warning
// with --accept-implausible.
TEST(ReadCampaignTest, ACopyOfALogIsRefusedAsTheSameLog) {
  ScratchDir dir;
  std::filesystem::copy_file(dir.Path("trials/surge_0.csv"), dir.Path("trials/surge_copy.csv"));
  const std::string path =
      dir.Write("copies.yaml",
                "vehicle: vehicle.yaml\ntrials:\n  - file: trials/surge_0.csv\n    dof: surge\n"
                "  - file: trials/surge_copy.csv\n    dof: surge\n");
  try {
    ReadCampaign(path);
    ADD_FAILURE() << "a copied log was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("copies.yaml:5: trials[1].file: implausible: a copy of the "
                                    "log of trials[0] ('trials/surge_0.csv')"));
  }
  // One changed digit is another log.
  dir.Edit("trials/surge_copy.csv", "\n0,", "\n0.0,");
  EXPECT_EQ(ReadCampaign(path).trials.size(), 2u);
}

TEST(ReadCampaignTest, PoolIsOptionalAndTrialsMayBeNone) {
  ScratchDir dir;
  const std::string path = dir.Write("empty_campaign.yaml", "vehicle: vehicle.yaml\ntrials: []\n");
  const Campaign c = ReadCampaign(path);
  EXPECT_FALSE(c.pool_file);
  EXPECT_FALSE(c.pool);
  EXPECT_TRUE(c.trials.empty());
}

// Data rows of a trial CSV: every line but comments and the header (as `wc -l` would count
// them less those).
std::size_t DataRows(const std::string& path) {
  const std::string text = testing::ReadText(path);
  std::size_t lines = 0, comments = 0;
  for (std::size_t at = 0; at < text.size(); at = text.find('\n', at) + 1) {
    ++lines;
    comments += text[at] == '#';
    if (text.find('\n', at) == std::string::npos) break;
  }
  return lines - comments - 1;
}

void ExpectEveryTrialLoaded(const std::string& campaign_path, std::size_t trials) {
  const Campaign c = ReadCampaign(campaign_path);
  ASSERT_EQ(c.trials.size(), trials);
  for (const TrialEntry& t : c.trials) {
    EXPECT_EQ(t.log.size(), DataRows(t.path)) << t.file;
    EXPECT_TRUE(t.log.HasForce(t.dof)) << t.file;
  }
}

TEST(ReadCampaignTest, LoadsTheBluerovCampaign) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016");
  ExpectEveryTrialLoaded(RealDataPath("bluerov-yaw-2016/campaign.yaml"), 5);
}

TEST(ReadCampaignTest, LoadsTheBluerovCampaignOfAllRuns) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016");
  const std::string path = RealDataPath("bluerov-yaw-2016/campaign_all.yaml");
  ExpectEveryTrialLoaded(path, 13);
  const Campaign c = ReadCampaign(path);
  EXPECT_EQ(c.trials[0].log.size(), 1763u);  // act34_1: 1771 lines, 7 comments, 1 header
  EXPECT_EQ(c.trials.back().start, 2411618.7);
  EXPECT_EQ(c.trials[2].use, TrialUse::kValidate);
}

TEST(ReadCampaignTest, LoadsTheTartanCampaign) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("tartan-pool-2022");
  const std::string path = RealDataPath("tartan-pool-2022/campaign.yaml");
  ExpectEveryTrialLoaded(path, 16);
  EXPECT_EQ(ReadCampaign(path).trials[2].mapping, "tam-heave");
}

// ---------------------------------------------------------------------------------------------
// Malformed campaigns.

TEST(ReadCampaignTest, MissingTrialFileNamesTheCampaignLine) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "trials/yaw_0.csv", "trials/yaw_9.csv");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              AllOf(HasSubstr(At("campaign.yaml", line) + " trials[2].file: cannot open '"),
                    HasSubstr("trials/yaw_9.csv': No such file or directory")));
}

TEST(ReadCampaignTest, MissingVehicleFile) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "vehicle: vehicle.yaml", "vehicle: romeo.yaml");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              AllOf(HasSubstr(At("campaign.yaml", line) + " vehicle: cannot open '"),
                    HasSubstr("romeo.yaml': No such file or directory")));
}

TEST(ReadCampaignTest, VehicleErrorsNameTheVehicleFile) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "mass: 450", "mass: heavy");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) + " mass: expected a positive number"));
}

TEST(ReadCampaignTest, MissingTrials) {
  ScratchDir dir;
  const std::string path = dir.Write("c.yaml", "vehicle: vehicle.yaml\n");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(path); }),
              HasSubstr("c.yaml: missing required key 'trials'"));
}

TEST(ReadCampaignTest, UnknownTrialKey) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "ballast_steps: 2", "ballast: 2");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr(At("campaign.yaml", line) +
                        " trials[1]: unknown key 'ballast' (allowed: file, dof, mapping, "
                        "ballast_steps, use, start)"));
}

TEST(ReadCampaignTest, UnknownDof) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "dof: yaw", "dof: heading");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr(At("campaign.yaml", line) +
                        " trials[2].dof: expected a DOF (surge, sway, heave, roll, pitch, yaw), "
                        "got 'heading'"));
}

TEST(ReadCampaignTest, UnknownMapping) {
  EXPECT_THAT(ErrorOf([] {
                ReadCampaign(testing::SourcePath("tests/data/bad/campaign_unknown_mapping.yaml"));
              }),
              HasSubstr("campaign_unknown_mapping.yaml:10: trials[1].mapping: expected a heave "
                        "mapping of the vehicle (vertical-all, vertical-front), got "
                        "'vertical-rear'"));
}

TEST(ReadCampaignTest, MappingOfAnotherDof) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "mapping: vertical-all", "mapping: surge-front");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr(At("campaign.yaml", line) +
                        " trials[1].mapping: expected a heave mapping of the vehicle "
                        "(vertical-all, vertical-front), got 'surge-front'"));
}

TEST(ReadCampaignTest, MappingRequiredWhenTheDofHasSeveral) {
  ScratchDir dir;
  dir.Edit("campaign.yaml", "    mapping: vertical-all\n", "");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr("trials[1]: missing required key 'mapping' (the vehicle has 2 heave "
                        "mappings: vertical-all, vertical-front)"));
}

TEST(ReadCampaignTest, BadUse) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "use: validate", "use: test");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr(At("campaign.yaml", line) +
                        " trials[1].use: expected a use (fit, validate), got 'test'"));
}

TEST(ReadCampaignTest, NegativeBallastSteps) {
  ScratchDir dir;
  dir.Edit("campaign.yaml", "ballast_steps: 2", "ballast_steps: -1");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr("trials[1].ballast_steps: expected a whole number >= 0, got '-1'"));
}

TEST(ReadCampaignTest, FractionalBallastSteps) {
  ScratchDir dir;
  dir.Edit("campaign.yaml", "ballast_steps: 2", "ballast_steps: 1.5");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr("trials[1].ballast_steps: expected a whole number >= 0, got '1.5'"));
}

TEST(ReadCampaignTest, StartBeforeThePreviousTrial) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "start: 0\n", "start: 200\n");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr(At("campaign.yaml", line + 6) +
                        " trials[1].start: expected a start >= the previous trial's 200 s "
                        "(trials are listed in the order they were run), got '120.5'"));
}

TEST(ReadCampaignTest, TrialWithoutForceOfItsDof) {
  ScratchDir dir;
  const int line = dir.Edit("campaign.yaml", "dof: yaw", "dof: sway");
  dir.Edit("vehicle.yaml",
           "  vertical-all:", "  sway-only:\n    dof: sway\n    shares: {VR: 1}\n  vertical-all:");
  dir.Edit("campaign.yaml", "mapping: yaw-diff", "mapping: sway-only");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr(At("campaign.yaml", line - 1) +
                        " trials[2]: trials/yaw_0.csv has no 'force_sway' column (a sway trial "
                        "needs force_sway or every thruster's cmd_<thruster>, and pos_sway or "
                        "vel_sway)"));
}

TEST(ReadCampaignTest, TrialWithoutPositionOrVelocityOfItsDof) {
  ScratchDir dir;
  dir.Write("trials/yaw_0.csv", "t,force_yaw,vel_surge\n0,1,2\n");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr("trials[2]: trials/yaw_0.csv has no 'pos_yaw' or 'vel_yaw' column (a yaw "
                        "trial needs force_yaw or every thruster's cmd_<thruster>, and pos_yaw or "
                        "vel_yaw)"));
}

TEST(ReadCampaignTest, TrialForceColumnWithoutValues) {
  ScratchDir dir;
  dir.Write("trials/yaw_0.csv", "t,force_yaw,vel_yaw\n0,,2\n1,,3\n");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr("trials[2]: trials/yaw_0.csv: column 'force_yaw' has no value"));
}

TEST(ReadCampaignTest, CsvMappingOfAnotherDofNamesTheCsvLine) {
  ScratchDir dir;
  dir.Edit("trials/heave_0.csv", "1.0,50,0.98,vertical-front", "1.0,50,0.98,surge-front");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr("heave_0.csv:5: column 'mapping': expected a mapping of the vehicle on "
                        "the trial's DOF (vertical-all, vertical-front), got 'surge-front'"));
}

TEST(ReadCampaignTest, CsvErrorsNameTheCsvFile) {
  ScratchDir dir;
  dir.Edit("trials/surge_0.csv", "0.2,100,0.003", "0.2,100,0.0x3");
  EXPECT_THAT(ErrorOf([&] { ReadCampaign(dir.Path("campaign.yaml")); }),
              HasSubstr("surge_0.csv:6: column 'pos_surge': expected a number or an empty cell, "
                        "got '0.0x3'"));
}

// ---------------------------------------------------------------------------------------------
// Writing.

TEST(WriteCampaignYamlTest, RoundTrips) {
  ScratchDir dir;
  const Campaign original = ReadCampaign(dir.Path("campaign.yaml"));
  WriteCampaignYaml(dir.Path("copy.yaml"), original);
  const Campaign copy = ReadCampaign(dir.Path("copy.yaml"));
  EXPECT_EQ(copy.vehicle_file, original.vehicle_file);
  EXPECT_EQ(copy.pool_file, original.pool_file);
  ASSERT_EQ(copy.trials.size(), original.trials.size());
  for (std::size_t i = 0; i < copy.trials.size(); ++i) {
    const TrialEntry& a = copy.trials[i];
    const TrialEntry& b = original.trials[i];
    EXPECT_EQ(a.file, b.file);
    EXPECT_EQ(a.path, b.path);
    EXPECT_EQ(a.dof, b.dof);
    EXPECT_EQ(a.mapping, b.mapping);
    EXPECT_EQ(a.ballast_steps, b.ballast_steps);
    EXPECT_EQ(a.use, b.use);
    EXPECT_EQ(a.has_start, b.has_start);
    EXPECT_EQ(a.start, b.start);
    EXPECT_EQ(a.log.size(), b.log.size());
  }
}

TEST(WriteCampaignYamlTest, WritesTheContractKeys) {
  ScratchDir dir;
  Campaign c;
  c.vehicle_file = "vehicle.yaml";
  TrialEntry t;
  t.file = "trials/t 1.csv";
  t.dof = Dof::kHeave;
  t.mapping = "vertical-all";
  t.ballast_steps = 1;
  t.use = TrialUse::kValidate;
  t.start = 0.1 + 0.2;
  t.has_start = true;
  c.trials.push_back(t);
  WriteCampaignYaml(dir.Path("c.yaml"), c);
  EXPECT_EQ(testing::ReadText(dir.Path("c.yaml")),
            "vehicle: vehicle.yaml\n"
            "trials:\n"
            "  - file: trials/t 1.csv\n"
            "    dof: heave\n"
            "    mapping: vertical-all\n"
            "    ballast_steps: 1\n"
            "    use: validate\n"
            "    start: 0.30000000000000004\n");
}

// A whole campaign directory (what `simulate` writes): vehicle, campaign and trial logs, read
// back to the same campaign; a directory with content is refused and left untouched.
TEST(WriteCampaignTest, WritesADirectoryThatReadsBack) {
  ScratchDir dir;
  Campaign original = ReadCampaign(dir.Path("campaign.yaml"));
  original.pool_file.reset();  // written as given: a pool file would have to be beside it
  const std::vector<std::string> comments(original.trials.size(), "written by a test");
  const Campaign written = WriteCampaign(dir.Path("out/"), original, original.vehicle, comments);
  EXPECT_EQ(written.path, dir.Path("out/campaign.yaml"));
  EXPECT_EQ(written.vehicle_file, "vehicle.yaml");
  const Campaign back = ReadCampaign(dir.Path("out/campaign.yaml"));
  EXPECT_EQ(back.vehicle.name, original.vehicle.name);
  ASSERT_EQ(back.trials.size(), original.trials.size());
  for (std::size_t i = 0; i < back.trials.size(); ++i) {
    EXPECT_EQ(back.trials[i].file, original.trials[i].file);
    EXPECT_EQ(back.trials[i].path, written.trials[i].path);
    EXPECT_EQ(back.trials[i].log.t, original.trials[i].log.t);
    EXPECT_EQ(testing::ReadText(written.trials[i].path).rfind("# written by a test\n", 0), 0u);
  }
  EXPECT_THAT(ErrorOf([&] { WriteCampaign(dir.Path("out"), original, original.vehicle); }),
              HasSubstr("out: output directory exists and is not empty"));
  EXPECT_EQ(ReadCampaign(dir.Path("out/campaign.yaml")).trials.size(), back.trials.size());
}

// The temporary directory is unique to the run, so a user's directory of the old
// temporary name is never touched, and nothing of the run is left behind.
TEST(WriteCampaignTest, LeavesOtherDirectoriesAlone) {
  ScratchDir dir;
  const Campaign original = ReadCampaign(dir.Path("campaign.yaml"));
  std::filesystem::create_directories(dir.Path("mine.tmp-uuvplan"));
  std::ofstream(dir.Path("mine.tmp-uuvplan/keep.txt")) << "user data\n";
  Campaign c = original;
  c.pool_file.reset();
  WriteCampaign(dir.Path("mine"), c, c.vehicle);
  EXPECT_EQ(testing::ReadText(dir.Path("mine.tmp-uuvplan/keep.txt")), "user data\n");
  int leftovers = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.Path(""))) {
    leftovers += e.path().filename().string().rfind("mine.tmp-uuvplan-", 0) == 0;
  }
  EXPECT_EQ(leftovers, 0);
}

}  // namespace
}  // namespace uuvplan::model
