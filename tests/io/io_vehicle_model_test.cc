// A vehicle file with a model (`diagnose --write-vehicle`, docs/formats.md): written and read
// back, by the vehicle reader (every command) and the truth reader (`score`), with its faults
// reported by file, line and key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "io_test_util.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/number_text.h"

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
  Vehicle written = truth.vehicle;
  written.models[Dof::kSurge] = m;
  io::WriteVehicleYaml(path, written, "a model\nof surge");
  EXPECT_THAT(ReadText(path), HasSubstr("# a model\n# of surge\n"));
  const Vehicle v = io::ReadVehicle(path);  // every command reads it as a vehicle
  EXPECT_EQ(v.name, truth.vehicle.name);
  EXPECT_EQ(v.priors.count(Dof::kSurge), truth.vehicle.priors.count(Dof::kSurge));
  ASSERT_EQ(v.models.size(), 1u);
  EXPECT_TRUE(v.models.at(Dof::kSurge).identified());
  const Truth read = io::ReadTruth(path);
  ASSERT_EQ(read.dofs.count(Dof::kSurge), 1u);
  const DofTruth& back = read.dofs.at(Dof::kSurge);
  EXPECT_EQ(back.params.at("bias_step"), 0.0);  // the truth reader's default (one ballast level)
  for (const auto& [name, value] : m.params) {
    // An estimate is rounded one digit past its σ's second: at most 0.5% of σ away.
    EXPECT_NEAR(back.params.at(name), value, 0.005 * m.sigma.at(name)) << name;
    // σ to 2 significant digits: at most 5% of itself away.
    EXPECT_NEAR(back.sigma.at(name), m.sigma.at(name), 0.05 * m.sigma.at(name)) << name;
    EXPECT_EQ(v.models.at(Dof::kSurge).params.at(name), back.params.at(name)) << name;
  }
  EXPECT_EQ(back.settings, m.settings);
}

// A file people read: an estimate with the digits its σ carries, σ with two, the user's a
// priori values as they wrote them, and no number longer than 10 significant digits.
TEST(VehicleModelIo, WrittenNumbersAreRoundedFromSigmaAndShort) {
  ScratchDir dir;
  Vehicle v = io::ReadTruth(dir.Path("truth.yaml")).vehicle;
  v.mass = 6.6210000000000004;  // 6.621 as a double prints 17 digits at %.17g
  DofParameters m;
  m.params = {{"m", 0.575123456}, {"k", 4.2912345678}, {"kq", 1.0 / 3.0}};
  m.sigma = {{"m", 0.0731234}, {"k", 0.1}};  // kq held (no σ): written exactly, 10 digits
  v.models[Dof::kSurge] = m;
  const std::string path = dir.Path("readable.yaml");
  io::WriteVehicleYaml(path, v, "readable");
  const std::string text = ReadText(path);
  EXPECT_THAT(text, HasSubstr("mass: 6.621\n"));
  EXPECT_THAT(text, HasSubstr("m: 0.5751\n"));  // σ 0.073: the ten-thousandths
  EXPECT_THAT(text, HasSubstr("k: 4.291\n"));   // σ 0.10: the thousandths
  EXPECT_THAT(text, HasSubstr("m: 0.073\n"));   // σ, two digits
  EXPECT_THAT(text, HasSubstr("kq: 0.3333333333\n"));
  EXPECT_THAT(text, HasSubstr("# identified"));  // the identified part is labelled
  EXPECT_THAT(text, HasSubstr("# a priori"));
  const Vehicle back = io::ReadVehicle(path);
  EXPECT_EQ(back.mass, 6.621);
  EXPECT_EQ(back.models.at(Dof::kSurge).params.at("m"), 0.5751);
}

// `identify --write-vehicle` updates the user's file: ROMEO's vehicle file (comments, key order,
// its own numbers) comes back line for line outside the model keys, its a priori drag with the
// comments beside it; the estimates read back as the whole-file writer's do; a second update
// replaces the first one's header and model rather than adding to them.
TEST(VehicleModelIo, AnUpdatedFileKeepsWhatItsUserWrote) {
  ScratchDir dir;
  const std::string source = SourcePath("cases/romeo/vehicle.yaml");
  Vehicle v = io::ReadVehicle(source);
  DofParameters m;
  m.params = {{"m", 891.23}, {"k", 47.1}, {"kq", 301.7}, {"bias", -1.2}};
  m.sigma = {{"m", 3.7}, {"k", 2.1}, {"kq", 11.9}, {"bias", 0.4}};
  v.models[Dof::kSurge] = m;
  const std::string updated = dir.Path("updated.yaml"), whole = dir.Path("whole.yaml");
  io::WriteVehicleYamlOver(updated, source, v, std::string(io::kWrittenByPrefix) + "x`\nof ROMEO");
  io::WriteVehicleYaml(whole, v, "whole");
  const std::string text = ReadText(updated);
  EXPECT_EQ(text.rfind("# written by `uuvplan x`\n# of ROMEO\n", 0), 0u) << text;
  std::size_t at = 0;  // every line of the user's file, in order
  std::istringstream lines(ReadText(source));
  for (std::string line; std::getline(lines, line);) {
    at = text.find(line + "\n", at);
    ASSERT_NE(at, std::string::npos) << "lost: " << line;
  }
  const Vehicle back = io::ReadVehicle(updated), reference = io::ReadVehicle(whole);
  EXPECT_EQ(back.models.at(Dof::kSurge).params, reference.models.at(Dof::kSurge).params);
  EXPECT_EQ(back.models.at(Dof::kSurge).sigma, reference.models.at(Dof::kSurge).sigma);
  EXPECT_EQ(back.priors.at(Dof::kSway).drag->kq, 442.3);
  EXPECT_EQ(back.mass, v.mass);
  // Again over the updated file, with another estimate and a model of heave it did not have.
  v.models[Dof::kSurge].params["m"] = 885.0;
  v.models[Dof::kHeave] = m;
  v.models[Dof::kHeave].params["m"] = 700.5;
  const std::string again = dir.Path("again.yaml");
  io::WriteVehicleYamlOver(again, updated, v, std::string(io::kWrittenByPrefix) + "y`");
  const std::string twice = ReadText(again);
  EXPECT_EQ(twice.find("uuvplan x`"), std::string::npos) << twice;
  EXPECT_THAT(twice, HasSubstr("\n\n" + ReadText(source).substr(0, 200)));  // the user's header
  EXPECT_EQ(twice.find("m: 891.2"), std::string::npos) << twice;
  const Vehicle back2 = io::ReadVehicle(again);
  EXPECT_EQ(back2.models.at(Dof::kSurge).params.at("m"), 885.0);
  EXPECT_EQ(back2.models.at(Dof::kHeave).params.at("m"), 700.5);
  EXPECT_EQ(back2.priors.at(Dof::kHeave).drag->k, 44.7);
}

// The same update on ROMEO's file as people also write it: CRLF line ends (kept), quoted and
// spaced keys ('dofs', "surge" :), blank lines holding a tab; and a file in YAML documents
// (`...`), written whole. Each reads back with the model, no key twice.
TEST(VehicleModelIo, AnUpdatedFileKeepsItsLineEndsAndQuotedKeys) {
  ScratchDir dir;
  const std::string romeo = ReadText(SourcePath("cases/romeo/vehicle.yaml"));
  Vehicle v = io::ReadVehicle(SourcePath("cases/romeo/vehicle.yaml"));
  DofParameters m;
  m.params = {{"m", 891.23}, {"k", 47.1}, {"kq", 301.7}, {"bias", -1.2}};
  m.sigma = {{"m", 3.7}, {"k", 2.1}, {"kq", 11.9}, {"bias", 0.4}};
  v.models[Dof::kSurge] = m;
  const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
    }
    return text;
  };
  const std::string quoted =
      replaced(replaced(romeo, "\ndofs:", "\n'dofs':"), "\n  surge:\n", "\n  \"surge\" :\n\t\n");
  const std::map<std::string, std::string> sources = {{"crlf.yaml", replaced(romeo, "\n", "\r\n")},
                                                      {"quoted.yaml", quoted},
                                                      {"documents.yaml", romeo + "...\n"}};
  for (const auto& [name, text] : sources) {
    WriteText(dir.Path(name), text);
    const std::string out = dir.Path("updated-" + name);
    io::WriteVehicleYamlOver(out, dir.Path(name), v, "updated");
    const Vehicle back = io::ReadVehicle(out);
    EXPECT_EQ(back.models.at(Dof::kSurge).params.at("m"), 891.23) << name;  // σ 3.7: 0.01
    EXPECT_EQ(back.priors.at(Dof::kSurge).drag->kq, 306.2) << name;
    const std::string written = ReadText(out);
    if (name == "crlf.yaml") {
      EXPECT_EQ(std::count(written.begin(), written.end(), '\n'),
                std::count(written.begin(), written.end(), '\r'));
      EXPECT_THAT(written, HasSubstr("Table IV, forward surge, technological payload\r\n"));
    }
    if (name == "quoted.yaml") EXPECT_THAT(written, HasSubstr("  \"surge\" :\n"));
  }
}

TEST(FileNumbers, EstimateDigitsFollowSigma) {
  EXPECT_EQ(io::EstimateNumber(890.4321, 25.0), "890.4");
  EXPECT_EQ(io::EstimateNumber(0.57512, 0.073), "0.5751");
  EXPECT_EQ(io::EstimateNumber(-3.141592, 0.0012), "-3.14159");
  EXPECT_EQ(io::EstimateNumber(0.0003, 0.5), "0");       // below the rounding place: 0.000 ± 0.50
  EXPECT_EQ(io::EstimateNumber(12345.0, 0.0), "12345");  // held: exact
  EXPECT_EQ(io::SigmaNumber(0.0731234), "0.073");
  EXPECT_EQ(io::SigmaNumber(0.0), "0");
  EXPECT_EQ(io::FileNumber(0.1), "0.1");
  EXPECT_EQ(io::FileNumber(1.0 / 3.0), "0.3333333333");
  EXPECT_EQ(io::FileNumber(2.5e-7), "2.5e-07");
}

TEST(VehicleModelIo, ModelFaultsInAVehicleFileNameFileLineAndKey) {
  // A model's keys are checked by the vehicle reader too (every command reports them).
  ScratchDir dir;
  const Truth truth = io::ReadTruth(dir.Path("truth.yaml"));
  DofTruth m;
  m.params = {{"m", 10.0}, {"k", 1.0}};
  m.sigma = {{"m", 0.1}};
  Vehicle written = truth.vehicle;
  written.models[Dof::kSurge] = m;
  io::WriteVehicleYaml(dir.Path("model.yaml"), written, "test");
  dir.Edit("model.yaml", "      m: 0.1\n", "      nope: 0.1\n");
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
