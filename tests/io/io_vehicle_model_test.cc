// A vehicle file with a model (`diagnose --write-vehicle`, docs/formats.md): written and read
// back, by the vehicle reader (every command) and the truth reader (`score`), with its faults
// reported by file, line and key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "io_test_util.h"
#include "uuvplan/io/io.h"

namespace uuvplan::model::testing {
namespace {

using ::testing::HasSubstr;

TEST(VehicleModelIo, WrittenModelReadsBackWithSigmaEffectsAndSettings) {
  ScratchDir dir;
  const Truth truth = io::ReadTruth(dir.Path("truth.yaml"));
  DofTruth m;
  m.params = {{"m", 890.5},
              {"k", 46.9},
              {"kq", 306.2},
              {"bias", -1.25},
              {"eta.surge-front.neg", 0.81},
              {"lag", 0.0823},
              {"thrust_exponent", -0.48},
              {"coupling.ur", -3.5},
              {"k_neg", 57.9},
              {"kq_neg", 0.0}};
  m.settings = {{"thrust_reference", 120.0}};
  for (const auto& [name, value] : m.params) m.sigma[name] = 0.01 * std::abs(value);
  const std::string path = dir.Path("model.yaml");
  io::WriteVehicleYaml(path, truth.vehicle, {{Dof::kSurge, m}}, "a model\nof surge");
  EXPECT_THAT(ReadText(path), HasSubstr("# a model\n# of surge\n"));
  const Vehicle v = io::ReadVehicle(path);  // every command reads it as a vehicle
  EXPECT_EQ(v.name, truth.vehicle.name);
  EXPECT_EQ(v.priors.count(Dof::kSurge), truth.vehicle.priors.count(Dof::kSurge));
  // identification notes that it does not start from the written model
  EXPECT_EQ(v.dofs_with_parameters, std::vector<Dof>{Dof::kSurge});
  const Truth read = io::ReadTruth(path);
  ASSERT_EQ(read.dofs.count(Dof::kSurge), 1u);
  std::map<std::string, double> expected = m.params;
  expected["bias_step"] = 0.0;  // the truth reader's default (one ballast level)
  EXPECT_EQ(read.dofs.at(Dof::kSurge).params, expected);  // 17 digits: exact
  EXPECT_EQ(read.dofs.at(Dof::kSurge).sigma, m.sigma);
  EXPECT_EQ(read.dofs.at(Dof::kSurge).settings, m.settings);
}

TEST(VehicleModelIo, ModelFaultsInAVehicleFileNameFileLineAndKey) {
  // A model's keys are checked by the vehicle reader too (every command reports them).
  ScratchDir dir;
  const Truth truth = io::ReadTruth(dir.Path("truth.yaml"));
  DofTruth m;
  m.params = {{"m", 10.0}, {"k", 1.0}};
  m.sigma = {{"m", 0.1}};
  io::WriteVehicleYaml(dir.Path("model.yaml"), truth.vehicle, {{Dof::kSurge, m}}, "test");
  dir.Edit("model.yaml", "      m: 0.10000000000000001", "      nope: 0.1");
  const std::string e1 = ErrorOf([&] { io::ReadVehicle(dir.Path("model.yaml")); });
  EXPECT_THAT(e1, HasSubstr("model.yaml:"));
  EXPECT_THAT(e1, HasSubstr("dofs.surge.sigma"));
  EXPECT_THAT(e1, HasSubstr("got 'nope'"));
  EXPECT_THAT(e1, HasSubstr("a parameter given by this DOF's params or effects"));
  dir.Edit("model.yaml", "      k: 1\n", "      k: -1\n");
  const std::string e2 = ErrorOf([&] { io::ReadVehicle(dir.Path("model.yaml")); });
  EXPECT_THAT(e2, HasSubstr("params.k"));
}

}  // namespace
}  // namespace uuvplan::model::testing
