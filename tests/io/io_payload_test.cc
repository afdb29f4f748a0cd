// A vehicle file that is a payload on a known vehicle (docs/formats.md): read with its base, and
// its faults — a missing or circular base, a volume in litres, a jet the base does not have —
// reported by file, line and key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.h"
#include "uuvplan/io/io.h"

namespace uuvplan::model::testing {
namespace {

using ::testing::HasSubstr;

std::string PayloadFile(const std::string& base, const std::string& payload) {
  return "name: carried\nbase: " + base + "\npayload:\n" + payload;
}

const char* kSkid = "  mass: 40\n  volume: 0.038\n  size: [0.9, 0.7, 0.25]\n  cg: [0, 0, 0.3]\n";

TEST(PayloadIo, OnFrameCaseReadsAsTheFrameWithItsSkid) {
  const Vehicle frame = io::ReadVehicle(SourcePath("cases/payload60/frame/identified.yaml"));
  const Vehicle v = io::ReadVehicle(SourcePath("cases/payload60/on-frame.yaml"));
  EXPECT_EQ(v.name, "payload60");
  EXPECT_DOUBLE_EQ(v.mass, frame.mass + 40);
  EXPECT_NEAR(v.size[2], 0.6, 1e-12);
  EXPECT_EQ(v.thrusters.size(), frame.thrusters.size());
  ASSERT_EQ(v.models.size(), frame.models.size());
  for (const auto& [dof, model] : v.models) {
    EXPECT_THAT(model.origin, HasSubstr("payload60-frame")) << DofName(dof);
    EXPECT_GT(model.params.at("m"), frame.models.at(dof).params.at("m")) << DofName(dof);
  }
  EXPECT_EQ(v.mappings.at(v.MappingIndex("sway-all")).open_water, OpenWater::kPositive);
  // The truth file with the same keys reads to the same vehicle.
  const Truth truth = io::ReadTruth(SourcePath("cases/payload60/on-frame-truth.yaml"));
  EXPECT_EQ(truth.vehicle.models.at(Dof::kHeave).params, v.models.at(Dof::kHeave).params);
  EXPECT_EQ(truth.dofs.at(Dof::kHeave).params.at("m"), 120.0);
}

// Written (as `simulate` writes a campaign's vehicle, `identify --write-vehicle` the DOFs it did
// not identify) and read back: still a priori, with its origin, not an identified model.
TEST(PayloadIo, DerivedModelKeepsItsOriginWhenWritten) {
  ScratchDir dir;
  const Vehicle v = io::ReadVehicle(SourcePath("cases/payload60/on-frame.yaml"));
  const std::string path = dir.Path("written.yaml");
  io::WriteVehicleYaml(path, v, "test");
  EXPECT_THAT(ReadText(path), HasSubstr("a priori (origin below)"));
  const Vehicle back = io::ReadVehicle(path);
  for (const auto& [dof, model] : v.models) {
    EXPECT_EQ(back.models.at(dof).origin, model.origin) << DofName(dof);
    EXPECT_EQ(back.models.at(dof).sigma.size(), model.sigma.size()) << DofName(dof);
  }
}

TEST(PayloadIo, FaultsNameTheFileLineAndKey) {
  ScratchDir dir;
  const std::string base = SourcePath("cases/payload60/frame/identified.yaml");
  const auto error = [&](const std::string& text) {
    const std::string path = dir.Write("carried.yaml", text);
    return ErrorOf([&] { io::ReadVehicle(path); });
  };
  EXPECT_THAT(error(PayloadFile("missing.yaml", kSkid)),
              HasSubstr("carried.yaml:2: base: cannot open"));
  EXPECT_THAT(error(PayloadFile("carried.yaml", kSkid)),
              HasSubstr("the bases return to a file already read"));
  // 38 litres written where m³ are asked: a payload 1000× lighter than water.
  EXPECT_THAT(error(PayloadFile(base, "  mass: 40\n  volume: 38\n  size: [0.9, 0.7, 0.25]\n")),
              HasSubstr("payload.volume: implausible"));
  EXPECT_THAT(error(PayloadFile(base, std::string(kSkid) + "  blocks: [sway-all.up]\n")),
              HasSubstr("payload.blocks"));
  EXPECT_THAT(error(PayloadFile(base, std::string(kSkid) + "  colour: red\n")),
              HasSubstr("colour"));
  EXPECT_THAT(error(PayloadFile(base, kSkid) + "thrusters: []\n"), HasSubstr("thrusters"));
  // A fault in the base is reported through the key that names it.
  const std::string bad_base = dir.Write("bad-base.yaml", "name: frame\nmass: -1\n");
  EXPECT_THAT(error(PayloadFile(bad_base, kSkid)),
              HasSubstr("base: the base vehicle is not valid: "));
}

}  // namespace
}  // namespace uuvplan::model::testing
