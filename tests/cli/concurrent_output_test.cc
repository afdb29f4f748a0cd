// Outputs that never lose data: concurrent runs on one --out, a user's directory with the name
// of an old temporary directory, and outputs onto special files (devices, FIFOs, symlinks).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

namespace fs = std::filesystem;

const std::string kTruth = std::string(UUVPLAN_SOURCE_DIR) + "/tests/data/io/truth.yaml";
const std::string kGoodPlanPath =
    std::string(UUVPLAN_SOURCE_DIR) + "/tests/data/bad/cases/plan_good.json";

// Four `simulate --out X` at once: one writes X; every other one either fails naming the
// other run (it started while the winner held X) or, had it won, wrote the same campaign. A
// directory of the user's called X.tmp-uuvplan is left as it was, and no temporary remains.
TEST(ConcurrentOutput, FourSimulateRunsOnOneOutAllButOneRefused) {
  const TempDir dir;
  const std::string out = dir / "X";
  fs::create_directories(out + ".tmp-uuvplan");
  dir.Write("X.tmp-uuvplan/mine.txt", "user data\n");
  std::string script;
  for (int i = 0; i < 4; ++i) {
    const std::string n = std::to_string(i);
    script += "('" + std::string(UUVPLAN_BINARY) + "' simulate --truth '" + kTruth + "' --plan '" +
              kGoodPlanPath + "' --out '" + out + "' >/dev/null 2>'" + (dir / ("err" + n)) +
              "'; echo $? >'" + (dir / ("rc" + n)) + "') & ";
  }
  ASSERT_EQ(std::system((script + "wait").c_str()), 0);  // std::system runs /bin/sh
  int succeeded = 0;
  for (int i = 0; i < 4; ++i) {
    const std::string n = std::to_string(i);
    const std::string rc = ReadText(dir / ("rc" + n)), err = ReadText(dir / ("err" + n));
    if (rc == "0\n") {
      ++succeeded;
      continue;
    }
    EXPECT_EQ(rc, "2\n") << err;
    const bool named = err.find("another run is writing " + out) != std::string::npos ||
                       err.find("another run wrote a campaign there") != std::string::npos ||
                       err.find("exists and is not empty") != std::string::npos;
    EXPECT_TRUE(named) << err;
  }
  EXPECT_EQ(succeeded, 1);
  EXPECT_TRUE(fs::exists(out + "/campaign.yaml"));
  EXPECT_EQ(ReadText(dir / "X.tmp-uuvplan/mine.txt"), "user data\n");
  for (const auto& e : fs::directory_iterator(dir.path())) {
    EXPECT_EQ(e.path().filename().string().rfind("X.tmp-uuvplan-", 0), std::string::npos)
        << e.path();
  }
}

// `simulate --json` onto private nodes (mknod needs CAP_MKNOD; skipped otherwise, never the
// machine's /dev/null or /dev/full), into a FIFO and through a symlink; stdout onto a full device.
class SpecialOutputs : public ::testing::Test {
 protected:
  int Simulate(const std::string& json, const std::string& out = "X",
               const std::string& stdout_to = "") {
    const std::string command =
        "'" + std::string(UUVPLAN_BINARY) + "' simulate --truth '" + kTruth + "' --plan '" +
        kGoodPlanPath + "' --out '" + dir / out + "' --json '" + json + "' >'" +
        (stdout_to.empty() ? dir / "stdout" : stdout_to) + "' 2>'" + dir / "stderr" + "'";
    const int raw = std::system(command.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  }
  std::string Stderr() const { return ReadText(dir / "stderr"); }
  // "" when made, else why not.
  std::string MakeDevice(const std::string& name, unsigned minor) const {
    if (::mknod((dir / name).c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0) return "";
    return std::string("cannot make a private device node: ") + std::strerror(errno);
  }
  bool IsCharDevice(const std::string& name) const {
    struct stat st {};
    return ::lstat((dir / name).c_str(), &st) == 0 && S_ISCHR(st.st_mode);
  }
  const TempDir dir;
};

TEST_F(SpecialOutputs, JsonOntoDeviceNodesWritesInPlaceAndAFullOneFails) {
  if (const std::string why = MakeDevice("null", 3); !why.empty()) GTEST_SKIP() << why;
  if (const std::string why = MakeDevice("full", 7); !why.empty()) GTEST_SKIP() << why;
  EXPECT_EQ(Simulate(dir / "null", "A"), 0) << Stderr();
  EXPECT_TRUE(IsCharDevice("null"));
  EXPECT_EQ(Simulate(dir / "full", "B"), 2);
  EXPECT_NE(Stderr().find(dir / "full" + ": cannot write: No space left on device"),
            std::string::npos)
      << Stderr();
  EXPECT_TRUE(IsCharDevice("full"));
  EXPECT_EQ(Simulate(dir / "c.json", "C", dir / "full"), 2);  // stdout on a full device
  EXPECT_NE(Stderr().find("the standard output cannot be written: No space left on device"),
            std::string::npos)
      << Stderr();
}

TEST_F(SpecialOutputs, JsonIntoAFifoAndThroughASymlink) {
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0) << std::strerror(errno);
  const std::string reader = "cat '" + dir / "pipe" + "' >'" + dir / "piped.json" + "' &";
  ASSERT_EQ(std::system(reader.c_str()), 0);
  EXPECT_EQ(Simulate(dir / "pipe", "A"), 0) << Stderr();
  fs::create_directory(dir / "results");
  fs::create_symlink("results/sim.json", dir / "latest.json");
  EXPECT_EQ(Simulate(dir / "latest.json", "B"), 0) << Stderr();

  EXPECT_TRUE(fs::is_fifo(dir / "pipe"));
  EXPECT_TRUE(fs::is_symlink(dir / "latest.json"));
  std::string linked = ReadText(dir / "results/sim.json");
  EXPECT_NE(linked.find("\"trials\""), std::string::npos) << linked;
  const std::size_t out = linked.find(dir / "B/campaign.yaml");
  ASSERT_NE(out, std::string::npos) << linked;
  linked.replace(out, (dir / "B").size(), dir / "A");  // the same campaign, written to A
  for (int wait = 0; wait < 100 && ReadText(dir / "piped.json").size() < linked.size(); ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the reader's last write
  }
  EXPECT_EQ(ReadText(dir / "piped.json"), linked);
}

}  // namespace
}  // namespace uuvplan::cli_test
