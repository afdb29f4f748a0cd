// Trial-log CSV reader and writer and the atomic file writer (docs/formats.md §Trial log).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <future>
#include <limits>
#include <stdexcept>

#include "io_test_util.h"
#include "support/real_data.h"
#include "uuvplan/io/io.h"

namespace uuvplan::model {
namespace {

using io::ReadTrialLog;
using io::WriteFileAtomically;
using io::WriteTrialLog;

using ::testing::AllOf;
using testing::At;
using ::testing::ElementsAre;
using testing::ErrorOf;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::IsNan;
using testing::ScratchDir;
using uuvplan::testing::RealDataPath;

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Comparison of columns with missing samples: NaN matches NaN.
void ExpectSameColumn(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    if (std::isnan(expected[i])) {
      EXPECT_TRUE(std::isnan(actual[i])) << "row " << i;
    } else {
      EXPECT_EQ(actual[i], expected[i]) << "row " << i;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Reading good files.

TEST(ReadTrialLogTest, ReadsKnownColumnsAndNotesUnknownOnes) {
  const TrialLog log = ReadTrialLog(testing::SourcePath("tests/data/io/trials/surge_0.csv"));
  EXPECT_THAT(log.t, ElementsAre(0, 0.1, 0.2, 0.3, 0.4));
  EXPECT_THAT(log.force[Index(Dof::kSurge)], ElementsAre(100, 100, 100, 100, 100));
  ExpectSameColumn(log.position[Index(Dof::kSurge)], {0, kNaN, 0.003, kNaN, 0.012});
  ExpectSameColumn(log.velocity[Index(Dof::kSurge)], {kNaN, 0.02, kNaN, 0.05, kNaN});
  EXPECT_THAT(log.velocity[Index(Dof::kYaw)], ElementsAre(0.01, 0.01, 0.01, -0.01, 0.02));
  EXPECT_TRUE(log.HasForce(Dof::kSurge));
  EXPECT_FALSE(log.HasForce(Dof::kYaw));
  EXPECT_FALSE(log.HasPosition(Dof::kYaw));
  EXPECT_THAT(log.mapping, IsEmpty());
  EXPECT_THAT(log.notes, ElementsAre("ignored column 'pwm_HFL'"));
}

TEST(ReadTrialLogTest, MappingColumnEmptyCellIsMinusOne) {
  const TrialLog log = ReadTrialLog(testing::SourcePath("tests/data/io/trials/heave_0.csv"));
  EXPECT_THAT(log.mapping_names, ElementsAre("vertical-all", "vertical-front"));
  EXPECT_THAT(log.mapping, ElementsAre(0, -1, 1, 1));
  EXPECT_THAT(log.notes, IsEmpty());
}

TEST(ReadTrialLogTest, UnwrapsHeadingAcrossEmptyCells) {
  const TrialLog log = ReadTrialLog(testing::SourcePath("tests/data/io/trials/yaw_0.csv"));
  // -3.1 follows 3.1: a step of -6.2 rad, so 2·pi is added from there on.
  ExpectSameColumn(log.position[Index(Dof::kYaw)],
                   {3.0, 3.1, -3.1 + 2 * kPi, kNaN, -2.9 + 2 * kPi});
  EXPECT_THAT(log.notes, ElementsAre(HasSubstr("unwrapped pos_yaw: 1 jump(s)")));
}

TEST(ReadTrialLogTest, UnwrapsSeveralTurnsBothWays) {
  ScratchDir dir;
  const std::string path = dir.Write("turns.csv",
                                     "t,pos_roll,pos_surge\n"
                                     "0,3.0,3.0\n1,-3.0,-3.0\n2,-1.0,-1.0\n3,1.5,1.5\n"
                                     "4,3.1,3.1\n5,-3.1,-3.1\n6,3.1,3.1\n");
  const TrialLog log = ReadTrialLog(path);
  const double w = 2 * kPi;  // up two turns, then back one
  const std::vector<double> expected = {3.0,     -3.0 + w,     -1.0 + w, 1.5 + w,
                                        3.1 + w, -3.1 + 2 * w, 3.1 + w};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(log.position[Index(Dof::kRoll)][i], expected[i], 1e-12) << i;
  }
  EXPECT_EQ(log.position[Index(Dof::kSurge)][1], -3.0);  // translations are never unwrapped
  EXPECT_THAT(log.notes, ElementsAre("unwrapped pos_roll: 3 jump(s) of more than pi rad"));
}

TEST(ReadTrialLogTest, AHeadingInDegreesIsNotUnwrappedByTwoPi) {
  // A heading in degrees spans more than 2·pi, so it is no angle wrapped to (-pi, pi]: its
  // noise alone steps by more than pi (0 → 4 → 1.5 → 8), which unwrapping by 2·pi would turn
  // into turns. Left as logged; wrapped at ±180 (179 → -178), it is unwrapped by 360 and said
  // so (input_sanity then names degrees).
  ScratchDir dir;
  const TrialLog noisy =
      ReadTrialLog(dir.Write("noisy.csv", "t,pos_yaw\n0,0\n1,4\n2,1.5\n3,8\n4,12\n"));
  ExpectSameColumn(noisy.position[Index(Dof::kYaw)], {0, 4, 1.5, 8, 12});
  EXPECT_THAT(noisy.notes, IsEmpty());
  const TrialLog wrapped =
      ReadTrialLog(dir.Write("wrapped.csv", "t,pos_yaw\n0,170\n1,174\n2,179\n3,-178\n4,-175\n"));
  ExpectSameColumn(wrapped.position[Index(Dof::kYaw)], {170, 174, 179, 182, 185});
  EXPECT_THAT(wrapped.notes, ElementsAre(HasSubstr("unwrapped pos_yaw as degrees")));
  // A compass heading in degrees, 0–360, the same.
  const TrialLog compass =
      ReadTrialLog(dir.Write("compass.csv", "t,pos_yaw\n0,350\n1,355\n2,359\n3,2\n4,6\n"));
  ExpectSameColumn(compass.position[Index(Dof::kYaw)], {350, 355, 359, 362, 366});
  EXPECT_THAT(compass.notes, ElementsAre(HasSubstr("unwrapped pos_yaw as degrees")));
}

TEST(ReadTrialLogTest, ARadianHeadingPrintedWithFourDecimalsIsStillUnwrapped) {
  // Wrapped to (-pi, pi] and printed to 4 decimals, a heading near south reads ±3.1416, just
  // past pi: it is still a wrapped angle in rad.
  ScratchDir dir;
  const TrialLog log =
      ReadTrialLog(dir.Write("south.csv", "t,pos_yaw\n0,3.1416\n1,-3.1416\n2,3.1415\n"));
  ExpectSameColumn(log.position[Index(Dof::kYaw)], {3.1416, -3.1416 + 2 * kPi, 3.1415});
  EXPECT_THAT(log.notes, ElementsAre(HasSubstr("unwrapped pos_yaw: 2 jump(s)")));
}

TEST(ReadTrialLogTest, ToleratesCrLfSpacesBlankLinesCommentsAnywhereAndNoFinalNewline) {
  ScratchDir dir;
  const std::string path = dir.Write("loose.csv",
                                     "# first\r\n\r\n t , force_sway ,vel_sway\r\n"
                                     "0, 1.5 ,+2\r\n# a comment between rows\r\n\r\n"
                                     "1e-1,-1,\t\r\n0.2,,3");
  const TrialLog log = ReadTrialLog(path);
  EXPECT_THAT(log.t, ElementsAre(0, 0.1, 0.2));
  ExpectSameColumn(log.force[Index(Dof::kSway)], {1.5, -1, kNaN});
  ExpectSameColumn(log.velocity[Index(Dof::kSway)], {2, kNaN, 3});
}

TEST(ReadTrialLogTest, ReadsALineLongerThanTheReadBuffer) {
  ScratchDir dir;
  const std::string long_cell(3 << 20, 'x');
  const std::string path =
      dir.Write("long.csv", "t,note,vel_heave\n0," + long_cell + ",1\n1,short,2\n");
  const TrialLog log = ReadTrialLog(path);
  EXPECT_THAT(log.velocity[Index(Dof::kHeave)], ElementsAre(1, 2));
}

TEST(ReadTrialLogTest, ReadsTheSharedRealLogs) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016", "tartan-pool-2022");
  const TrialLog bluerov = ReadTrialLog(RealDataPath("bluerov-yaw-2016/trials/yaw_1.csv"));
  EXPECT_EQ(bluerov.size(), 2926u);
  EXPECT_TRUE(bluerov.HasForce(Dof::kYaw));
  EXPECT_TRUE(bluerov.HasVelocity(Dof::kPitch));
  EXPECT_THAT(bluerov.notes, ElementsAre("ignored column 'thrust_T3'", "ignored column 'thrust_T4'",
                                         "ignored column 'pwm_T3'", "ignored column 'pwm_T4'",
                                         "ignored column 'ekf_yaw'"));
  const TrialLog tartan = ReadTrialLog(RealDataPath("tartan-pool-2022/trials/chunk_00.csv"));
  EXPECT_EQ(tartan.size(), 4085u - 11u);
  EXPECT_TRUE(tartan.HasPosition(Dof::kYaw));
  EXPECT_THAT(tartan.notes, IsEmpty());
}

// ---------------------------------------------------------------------------------------------
// Malformed files.

TEST(ReadTrialLogTest, MissingFile) {
  ScratchDir dir;
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(dir.Path("none.csv")); }),
              HasSubstr("none.csv: cannot open file: No such file or directory"));
}

TEST(ReadTrialLogTest, EmptyFile) {
  ScratchDir dir;
  const std::string path = dir.Write("empty.csv", "");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr("empty.csv: empty file: expected a header line such as "
                        "'t,force_surge,vel_surge' followed by data rows"));
}

TEST(ReadTrialLogTest, CommentsOnlyFileIsEmpty) {
  ScratchDir dir;
  const std::string path = dir.Write("comments.csv", "# nothing\n# logged\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }), HasSubstr("comments.csv: empty file"));
}

TEST(ReadTrialLogTest, HeaderOnly) {
  ScratchDir dir;
  const std::string path = dir.Write("header.csv", "# c\nt,force_surge,vel_surge\n\n");
  EXPECT_THAT(
      ErrorOf([&] { ReadTrialLog(path); }),
      HasSubstr(At("header.csv", 2) + " no data rows after the header: expected at least one row"));
}

TEST(ReadTrialLogTest, MissingTimeColumn) {
  ScratchDir dir;
  const std::string path = dir.Write("no_t.csv", "# c\ntime,force_surge\n0,1\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("no_t.csv", 2) + " header: expected a 't' column (time, s), got "
                                            "columns 'time', 'force_surge'"));
}

TEST(ReadTrialLogTest, ColumnTwice) {
  ScratchDir dir;
  const std::string path = dir.Write("twice.csv", "t,vel_surge,vel_surge\n0,1,2\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("twice.csv", 1) + " header: column 'vel_surge' appears twice"));
}

TEST(ReadTrialLogTest, RepeatedTime) {
  ScratchDir dir;
  const std::string path = dir.Write("t.csv", "t,vel_surge\n0,1\n0.5,1\n# c\n0.5,2\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("t.csv", 5) + " column 't': expected a time after the previous row's "
                                         "0.5 (times must strictly increase), got '0.5'"));
}

TEST(ReadTrialLogTest, DecreasingTime) {
  ScratchDir dir;
  const std::string path = dir.Write("t.csv", "t,vel_surge\n0,1\n0.5,1\n0.4,2\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("t.csv", 4) + " column 't': expected a time after the previous row's "
                                         "0.5"));
}

TEST(ReadTrialLogTest, EmptyTime) {
  ScratchDir dir;
  const std::string path = dir.Write("t.csv", "t,vel_surge\n0,1\n,1\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("t.csv", 3) + " column 't': expected a time (s), got an empty cell"));
}

TEST(ReadTrialLogTest, NonNumericCellNamesLineAndColumn) {
  ScratchDir dir;
  const std::string path =
      dir.Write("bad.csv", "# c\nt,force_surge,vel_surge\n0,1,2\n0.1,1,fast\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("bad.csv", 4) +
                        " column 'vel_surge': expected a number or an empty cell, got 'fast'"));
}

TEST(ReadTrialLogTest, NumberWithTrailingText) {
  ScratchDir dir;
  const std::string path = dir.Write("bad.csv", "t,force_surge\n0,12N\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr("column 'force_surge': expected a number or an empty cell, got '12N'"));
}

TEST(ReadTrialLogTest, LiteralNanCell) {
  EXPECT_THAT(ErrorOf([] { ReadTrialLog(testing::SourcePath("tests/data/bad/trial_nan.csv")); }),
              HasSubstr("trial_nan.csv:5: column 'vel_surge': expected a number or an empty "
                        "cell, got 'NaN'"));
}

TEST(ReadTrialLogTest, LiteralInfCell) {
  ScratchDir dir;
  const std::string path = dir.Write("inf.csv", "t,pos_heave\n0,-inf\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("inf.csv", 2) +
                        " column 'pos_heave': expected a number or an empty cell, got '-inf'"));
}

TEST(ReadTrialLogTest, OutOfRangeNumber) {
  ScratchDir dir;
  const std::string path = dir.Write("big.csv", "t,pos_heave\n0,1e999\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr("expected a number or an empty cell, got '1e999'"));
}

TEST(ReadTrialLogTest, TooManyCells) {
  ScratchDir dir;
  const std::string path = dir.Write("cells.csv", "t,force_surge,vel_surge\n0,1,2\n0.1,1,2,3,4\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("cells.csv", 3) + " expected 3 cells as in the header, got 5"));
}

TEST(ReadTrialLogTest, TooFewCells) {
  ScratchDir dir;
  const std::string path = dir.Write("cells.csv", "t,force_surge,vel_surge\n0,1\n");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path); }),
              HasSubstr(At("cells.csv", 2) + " expected 3 cells as in the header, got 2"));
}

TEST(ReadTrialLogTest, CellsOfIgnoredColumnsAreNotChecked) {
  ScratchDir dir;
  const std::string path = dir.Write("ok.csv", "t,comment,vel_surge\n0,hello,1\n1,nan,2\n");
  EXPECT_THAT(ReadTrialLog(path).velocity[Index(Dof::kSurge)], ElementsAre(1, 2));
}

TEST(ReadTrialLogTest, MappingNotAllowedNamesTheLine) {
  const std::string path = testing::SourcePath("tests/data/io/trials/heave_0.csv");
  EXPECT_THAT(ErrorOf([&] { ReadTrialLog(path, {"vertical-all"}); }),
              HasSubstr("heave_0.csv:5: column 'mapping': expected a mapping of the vehicle on "
                        "the trial's DOF (vertical-all), got 'vertical-front'"));
}

// ---------------------------------------------------------------------------------------------
// Writing.

TrialLog SampleLog() {
  TrialLog log;
  log.t = {0, 0.1, 0.2, 0.30000000000000004, 1e-7 + 0.3};
  log.force[Index(Dof::kHeave)] = {-50, -50, 50.125, 50, 1.0 / 3.0};
  log.position[Index(Dof::kHeave)] = {1.0, kNaN, 0.98, kNaN, 0.97};
  log.velocity[Index(Dof::kYaw)] = {kNaN, 0.01, -2.5e-9, 1e12, 0};
  log.mapping_names = {"vertical-all", "vertical-front"};
  log.mapping = {0, -1, 1, 1, 0};
  return log;
}

TEST(WriteTrialLogTest, WritesHeaderCommentsAndEmptyCells) {
  ScratchDir dir;
  const std::string path = dir.Path("out.csv");
  WriteTrialLog(path, SampleLog(), "simulated\nseed 3");
  const std::string text = testing::ReadText(path);
  EXPECT_THAT(text, HasSubstr("# simulated\n# seed 3\nt,force_heave,pos_heave,vel_yaw,mapping\n"
                              "0,-50,1,,vertical-all\n0.1,-50,,0.01,\n"));
}

TEST(WriteTrialLogTest, RoundTrips) {
  ScratchDir dir;
  const std::string path = dir.Path("out.csv");
  const TrialLog written = SampleLog();
  WriteTrialLog(path, written);
  const TrialLog read = ReadTrialLog(path);
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t i = 0; i < read.size(); ++i) EXPECT_NEAR(read.t[i], written.t[i], 1e-12);
  ExpectSameColumn(read.position[Index(Dof::kHeave)], written.position[Index(Dof::kHeave)]);
  ExpectSameColumn(read.velocity[Index(Dof::kYaw)], written.velocity[Index(Dof::kYaw)]);
  const auto& force = read.force[Index(Dof::kHeave)];
  EXPECT_EQ(force[2], 50.125);
  EXPECT_NEAR(force[4], 1.0 / 3.0, 1e-10);  // 10 significant digits
  EXPECT_EQ(read.mapping, written.mapping);
  EXPECT_EQ(read.mapping_names, written.mapping_names);
  EXPECT_FALSE(read.HasForce(Dof::kYaw));
}

TEST(WriteTrialLogTest, KeepsTimesStrictlyIncreasingBeyondTenDigits) {
  ScratchDir dir;
  TrialLog log;
  for (int i = 0; i < 100; ++i) log.t.push_back(1000.0 + i * 1e-9);
  log.velocity[Index(Dof::kSurge)].assign(100, 1.0);
  WriteTrialLog(dir.Path("fine.csv"), log);
  EXPECT_EQ(ReadTrialLog(dir.Path("fine.csv")).t, log.t);
}

TEST(WriteTrialLogTest, LargeLogRoundTripsThroughManyReadChunks) {
  ScratchDir dir;
  TrialLog log;
  const int n = 200000;  // about 5 MB: lines straddle the 1 MiB read chunks
  for (int i = 0; i < n; ++i) {
    log.t.push_back(i * 0.01);
    log.force[Index(Dof::kSurge)].push_back(std::sin(i * 0.001) * 100);
    log.velocity[Index(Dof::kSurge)].push_back(i % 3 == 0 ? kNaN : i * 1e-6);
  }
  WriteTrialLog(dir.Path("big.csv"), log);
  const TrialLog read = ReadTrialLog(dir.Path("big.csv"));
  ASSERT_EQ(read.size(), log.size());
  for (int i = 0; i < n; i += 997) {
    EXPECT_NEAR(read.t[i], log.t[i], 1e-9);
    EXPECT_NEAR(read.force[Index(Dof::kSurge)][i], log.force[Index(Dof::kSurge)][i], 1e-7);
  }
  EXPECT_THAT(read.velocity[Index(Dof::kSurge)][3], IsNan());
  EXPECT_EQ(read.velocity[Index(Dof::kSurge)][4], 4e-6);
}

TEST(WriteTrialLogTest, RefusesWhatTheReaderWouldReject) {
  ScratchDir dir;
  TrialLog log = SampleLog();
  log.velocity[Index(Dof::kYaw)][1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(WriteTrialLog(dir.Path("x.csv"), log), std::invalid_argument);
  log = SampleLog();
  log.t[2] = log.t[1];
  EXPECT_THROW(WriteTrialLog(dir.Path("x.csv"), log), std::invalid_argument);
  log = SampleLog();
  log.force[Index(Dof::kHeave)].pop_back();
  EXPECT_THROW(WriteTrialLog(dir.Path("x.csv"), log), std::invalid_argument);
  log = SampleLog();
  log.mapping_names[0] = "a,b";
  EXPECT_THROW(WriteTrialLog(dir.Path("x.csv"), log), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir.Path("x.csv")));
}

// ---------------------------------------------------------------------------------------------
// Atomic writes.

TEST(WriteFileAtomicallyTest, ReplacesTheFileWhole) {
  ScratchDir dir;
  const std::string path = dir.Path("a.txt");
  WriteFileAtomically(path, "first");
  WriteFileAtomically(path, "second");
  EXPECT_EQ(testing::ReadText(path), "second");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.Path(""))) {
    files += entry.path().filename() == "a.txt" || entry.path().filename().string()[0] == '.';
  }
  EXPECT_EQ(files, 1);  // no temporary left beside it
}

TEST(WriteFileAtomicallyTest, MissingDirectoryNamesThePath) {
  ScratchDir dir;
  const std::string path = dir.Path("no/such/dir/a.txt");
  EXPECT_THAT(ErrorOf([&] { WriteFileAtomically(path, "x"); }),
              AllOf(HasSubstr(path + ": cannot create a temporary file beside it"),
                    HasSubstr("No such file or directory")));
}

TEST(WriteFileAtomicallyTest, FailedRenameLeavesNoTemporary) {
  ScratchDir dir;
  std::filesystem::create_directory(dir.Path("out"));
  std::filesystem::create_directory(dir.Path("out/target"));
  std::filesystem::create_directory(dir.Path("out/target/inside"));  // not an empty directory
  EXPECT_THAT(ErrorOf([&] { WriteFileAtomically(dir.Path("out/target"), "x"); }),
              HasSubstr("target: cannot replace it with the new file"));
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.Path("out"))) {
    ++entries;
    EXPECT_EQ(entry.path().filename(), "target");
  }
  EXPECT_EQ(entries, 1);
}

// Private device nodes made with mknod(2) (null 1:3, full 1:7 — the numbers of Linux's
// /dev/null and /dev/full), never the machine's own; "" with the reason when they cannot be made
// (mknod needs CAP_MKNOD).
std::string MakeCharDevice(const std::string& path, unsigned minor) {
  if (::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0) return "";
  return std::string("cannot make a private device node here: ") + std::strerror(errno);
}

bool IsCharDevice(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

TEST(WriteFileAtomicallyTest, ADeviceNodeIsWrittenInPlaceAndAFullOneIsAnError) {
  ScratchDir dir;
  const std::string null = dir.Path("null"), full = dir.Path("full");
  if (const std::string why = MakeCharDevice(null, 3); !why.empty()) GTEST_SKIP() << why;
  if (const std::string why = MakeCharDevice(full, 7); !why.empty()) GTEST_SKIP() << why;
  WriteFileAtomically(null, "{}\n");
  EXPECT_TRUE(IsCharDevice(null));  // not replaced by a regular file
  EXPECT_THAT(ErrorOf([&] { WriteFileAtomically(full, "{}\n"); }),
              AllOf(HasSubstr(full + ": cannot write"), HasSubstr("No space left on device")));
  EXPECT_TRUE(IsCharDevice(full));
}

TEST(WriteFileAtomicallyTest, AFifoIsWrittenInPlace) {
  ScratchDir dir;
  const std::string fifo = dir.Path("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  auto read = std::async(std::launch::async, [&] { return testing::ReadText(fifo); });
  WriteFileAtomically(fifo, "through the pipe\n");
  EXPECT_EQ(read.get(), "through the pipe\n");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(WriteFileAtomicallyTest, ASymlinkIsWrittenThroughAndStaysALink) {
  ScratchDir dir;
  std::filesystem::create_directory(dir.Path("results"));
  WriteFileAtomically(dir.Path("results/plan.json"), "old");
  ::chmod(dir.Path("results/plan.json").c_str(), 0640);
  std::filesystem::create_symlink("results/plan.json", dir.Path("latest.json"));  // relative
  std::filesystem::create_symlink("latest.json", dir.Path("again.json"));         // a chain
  std::filesystem::create_symlink("results/new.json", dir.Path("dangling.json"));

  WriteFileAtomically(dir.Path("again.json"), "new");
  WriteFileAtomically(dir.Path("dangling.json"), "created");

  EXPECT_TRUE(std::filesystem::is_symlink(dir.Path("again.json")));
  EXPECT_TRUE(std::filesystem::is_symlink(dir.Path("latest.json")));
  EXPECT_TRUE(std::filesystem::is_symlink(dir.Path("dangling.json")));
  EXPECT_EQ(testing::ReadText(dir.Path("results/plan.json")), "new");
  EXPECT_EQ(testing::ReadText(dir.Path("results/new.json")), "created");
  const auto perms = std::filesystem::status(dir.Path("results/plan.json")).permissions();
  EXPECT_EQ(perms & std::filesystem::perms::all, std::filesystem::perms(0640));  // kept
  for (const char* folder : {"", "results"}) {  // no temporary left beside either
    for (const auto& entry : std::filesystem::directory_iterator(dir.Path(folder))) {
      EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
    }
  }
}

TEST(WriteFileAtomicallyTest, ALinkLoopIsAnError) {
  ScratchDir dir;
  std::filesystem::create_symlink("b.json", dir.Path("a.json"));
  std::filesystem::create_symlink("a.json", dir.Path("b.json"));
  EXPECT_THAT(ErrorOf([&] { WriteFileAtomically(dir.Path("a.json"), "x"); }),
              HasSubstr("a.json: cannot write through it: too many levels of symbolic links"));
}

}  // namespace
}  // namespace uuvplan::model
