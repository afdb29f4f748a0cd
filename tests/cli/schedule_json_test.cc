// The schedule JSON of the contract (§schedule, §next): keys written exactly as the contract
// names them, a schedule read back to the same trials, and malformed plans refused with the
// file, the trial index and the key in the message.
#include "uuvplan/io/schedule_json.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "cli_test_util.h"
#include "uuvplan/io/loop_json.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::planner {
namespace {

using io::ReadScheduleJson;
using io::ScheduleToJson;
using io::TrialFromJson;
using io::TrialToJson;

using nlohmann::json;
using ::testing::HasSubstr;

PlannedTrial SteadyTrial() {
  PlannedTrial t;
  t.design.id = "surge_steady_1";
  t.design.dof = model::Dof::kSurge;
  t.design.kind = model::TrialKind::kSteady;
  t.design.mapping = "surge-front";
  t.design.duration = 40.0;
  t.design.force = 35.0;
  t.travel = {0.0, 11.5};
  t.thrust_min = 24.7;
  return t;
}

PlannedTrial SineTrial() {
  PlannedTrial t;
  t.design.id = "yaw_sine";
  t.design.dof = model::Dof::kYaw;
  t.design.kind = model::TrialKind::kSine;
  t.design.mapping = "yaw-fr-rl";
  t.design.duration = 120.0;
  t.design.offset = -5.0;  // ref 000 §IV-D: offset -5 N·m, amplitude 4 N·m
  t.design.amplitude = 4.0;
  t.design.omega = 2 * 3.141592653589793 / 24.0;
  t.travel = {-9.0, 0.0};
  t.thrust_min = 0.64;
  return t;
}

PlannedTrial SegmentsTrial() {
  PlannedTrial t;
  t.design.id = "heave_ballast_3";
  t.design.dof = model::Dof::kHeave;
  t.design.kind = model::TrialKind::kSegments;
  t.design.mapping = "vertical-all";
  t.design.segments = {{60, 20, ""}, {-60, 20, ""}, {120, 15.5, "vertical-front"}};
  t.design.duration = 55.5;
  t.design.ballast_steps = 3;
  t.travel = {-1.25, 3.5};
  t.thrust_min = 15.0;
  return t;
}

// Plan files of these tests live in one directory removed when the test program ends.
std::string TempFile(const std::string& name, const std::string& text) {
  static const cli_test::TempDir dir;
  static int count = 0;
  return dir.Write(std::to_string(++count) + "-" + name, text);
}

// The message of the InputError that `f` throws ("" if none).
template <typename F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const model::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScheduleJson, SteadyTrialHasExactlyTheContractKeys) {
  const json j = TrialToJson(SteadyTrial());
  // contract §schedule: id, dof, kind, duration, mapping, the kind's fields, travel, thrust_min;
  // ballast_steps only when non-zero.
  std::set<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.insert(k);
  EXPECT_EQ(keys, (std::set<std::string>{"id", "dof", "kind", "duration", "mapping", "force",
                                         "travel", "thrust_min"}));
  EXPECT_EQ(j["dof"], "surge");
  EXPECT_EQ(j["kind"], "steady");
  EXPECT_EQ(j["force"], 35.0);
  EXPECT_EQ(j["travel"], json({0.0, 11.5}));
}

TEST(ScheduleJson, SineAndSegmentsFields) {
  const json sine = TrialToJson(SineTrial());
  EXPECT_EQ(sine["kind"], "sine");
  EXPECT_EQ(sine["offset"], -5.0);
  EXPECT_EQ(sine["amplitude"], 4.0);
  EXPECT_DOUBLE_EQ(sine["omega"].get<double>(), 2 * 3.141592653589793 / 24.0);
  EXPECT_FALSE(sine.contains("force"));
  EXPECT_FALSE(sine.contains("segments"));

  const json seg = TrialToJson(SegmentsTrial());
  EXPECT_EQ(seg["kind"], "segments");
  EXPECT_EQ(seg["ballast_steps"], 3);
  ASSERT_EQ(seg["segments"].size(), 3u);
  // Every segment carries its mapping (contract): the trial's when the design leaves it empty.
  EXPECT_EQ(seg["segments"][0],
            json({{"force", 60.0}, {"duration", 20.0}, {"mapping", "vertical-all"}}));
  EXPECT_EQ(seg["segments"][2]["mapping"], "vertical-front");
}

TEST(ScheduleJson, ScheduleRoundTripsThroughAFile) {
  Schedule s;
  s.trials = {SteadyTrial(), SineTrial(), SegmentsTrial()};
  s.predicted[model::Dof::kSurge] = {{{"m", 56.0}, {"k", 4.9}}, "D", -12.25};
  s.pool_time = 395.5;
  const json j = ScheduleToJson(s);
  EXPECT_TRUE(j.contains("trials"));
  EXPECT_EQ(j["predicted"]["surge"]["criterion"], "D");
  EXPECT_EQ(j["predicted"]["surge"]["value"], -12.25);
  EXPECT_EQ(j["predicted"]["surge"]["sigma"]["m"], 56.0);
  EXPECT_EQ(j["pool_time"], 395.5);

  const Schedule r = ReadScheduleJson(TempFile("plan.json", j.dump(2)));
  ASSERT_EQ(r.trials.size(), 3u);
  // Exact equality: JSON numbers are written with round-trip precision.
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& a = s.trials[i];
    const auto& b = r.trials[i];
    EXPECT_EQ(a.design.id, b.design.id);
    EXPECT_EQ(a.design.dof, b.design.dof);
    EXPECT_EQ(a.design.kind, b.design.kind);
    EXPECT_EQ(a.design.mapping, b.design.mapping);
    EXPECT_EQ(a.design.duration, b.design.duration);
    EXPECT_EQ(a.design.force, b.design.force);
    EXPECT_EQ(a.design.offset, b.design.offset);
    EXPECT_EQ(a.design.amplitude, b.design.amplitude);
    EXPECT_EQ(a.design.omega, b.design.omega);
    EXPECT_EQ(a.design.ballast_steps, b.design.ballast_steps);
    ASSERT_EQ(a.design.segments.size(), b.design.segments.size());
    for (std::size_t k = 0; k < a.design.segments.size(); ++k) {
      EXPECT_EQ(a.design.segments[k].force, b.design.segments[k].force);
      EXPECT_EQ(a.design.segments[k].duration, b.design.segments[k].duration);
      EXPECT_EQ(a.design.segments[k].mapping, b.design.segments[k].mapping);
    }
    EXPECT_EQ(a.travel, b.travel);
    EXPECT_EQ(a.thrust_min, b.thrust_min);
  }
  ASSERT_EQ(r.predicted.count(model::Dof::kSurge), 1u);
  EXPECT_EQ(r.predicted.at(model::Dof::kSurge).sigma.at("k"), 4.9);
  EXPECT_EQ(r.pool_time, 395.5);
}

// Every predicted σ says what it rests on (planner::kPredictedSigmaAssumption), in the file
// and read back; a file written before that was recorded (no "assumption") is read as resting
// on the start counted known, which made σ several times too small (docs/planning.md,
// "Initial state"), so that `report` does not label it with today's assumption.
TEST(ScheduleJson, PredictedSigmaCarryWhatTheyRestOnAndOldFilesSaySo) {
  Schedule s;
  s.trials = {SteadyTrial()};
  s.predicted[model::Dof::kSurge] = {{{"m", 56.0}}, "D", -12.25};
  json j = ScheduleToJson(s);
  EXPECT_EQ(j["predicted"]["surge"]["assumption"], planner::kPredictedSigmaAssumption);
  EXPECT_EQ(
      ReadScheduleJson(TempFile("now.json", j.dump())).predicted.at(model::Dof::kSurge).assumption,
      planner::kPredictedSigmaAssumption);
  j["predicted"]["surge"].erase("assumption");
  EXPECT_EQ(
      ReadScheduleJson(TempFile("old.json", j.dump())).predicted.at(model::Dof::kSurge).assumption,
      io::kUnrecordedSigmaAssumption);
  j["predicted"]["surge"]["assumption"] = 3;
  EXPECT_THAT(ErrorOf([&] { ReadScheduleJson(TempFile("bad.json", j.dump())); }),
              HasSubstr("predicted.surge.assumption"));
}

// A loop's history carries what its predicted σ rest on: the iteration's own sentence, or the
// unrecorded one for a loop written before it was (report labels its table with it); a null σ
// or criterion value (a non-finite one, as the writers put it) reads as NaN.
TEST(ScheduleJson, LoopHistoryCarriesWhatItsPredictedSigmaRestOn) {
  json iteration = json::parse(R"({"trial": {"id": "a", "dof": "surge", "kind": "steady",
    "duration": 10, "mapping": "surge-front", "force": 30}, "dof": "surge", "pool_time": 10,
    "params": {"surge": {"m": {"value": 900, "sigma": 9}}},
    "sigma": {"m": {"predicted": null}}})");
  planner::PredictedPrecision p;
  p.sigma = {{"m", std::numeric_limits<double>::quiet_NaN()}};
  p.criterion_value = std::numeric_limits<double>::infinity();
  iteration["predicted"] = {{"surge", io::PredictedToJson(p)}};
  EXPECT_TRUE(iteration["predicted"]["surge"]["sigma"]["m"].is_null());
  EXPECT_TRUE(iteration["predicted"]["surge"]["value"].is_null());
  json loop = {{"iterations", {iteration}}};
  const io::LoopHistory now = io::ReadLoopJson(TempFile("loop.json", loop.dump()));
  EXPECT_EQ(now.predicted_assumption, planner::kPredictedSigmaAssumption);
  EXPECT_TRUE(std::isnan(now.series.at(model::Dof::kSurge).at("m").front().predicted));
  loop["iterations"][0]["predicted"]["surge"].erase("assumption");
  EXPECT_EQ(io::ReadLoopJson(TempFile("old-loop.json", loop.dump())).predicted_assumption,
            io::kUnrecordedSigmaAssumption);
  // A schedule's predicted object with null σ and value reads back as NaN, not as an error.
  Schedule s;
  s.trials = {SteadyTrial()};
  s.predicted[model::Dof::kSurge] = p;
  const Schedule r = ReadScheduleJson(TempFile("nan.json", ScheduleToJson(s).dump()));
  EXPECT_TRUE(std::isnan(r.predicted.at(model::Dof::kSurge).sigma.at("m")));
  EXPECT_TRUE(std::isnan(r.predicted.at(model::Dof::kSurge).criterion_value));
}

TEST(ScheduleJson, ReadsTheTrialOfANextResult) {
  const json next = {{"estimates", {{"dofs", json::object()}}},
                     {"trial", TrialToJson(SineTrial())},
                     {"predicted", {{"anything", "the next command's own business"}}}};
  const Schedule r = ReadScheduleJson(TempFile("next.json", next.dump()));
  ASSERT_EQ(r.trials.size(), 1u);
  EXPECT_EQ(r.trials[0].design.id, "yaw_sine");
  EXPECT_EQ(r.trials[0].design.offset, -5.0);
}

TEST(ScheduleJson, HandWrittenPlanNeedsNoTravelNorSegmentMappings) {
  const std::string text = R"({"trials": [
    {"id": "a", "dof": "heave", "kind": "segments", "duration": 30, "mapping": "vertical-all",
     "segments": [{"force": 50, "duration": 10}, {"force": -50, "duration": 20}]}]})";
  const Schedule r = ReadScheduleJson(TempFile("plan.json", text));
  ASSERT_EQ(r.trials.size(), 1u);
  EXPECT_EQ(r.trials[0].design.segments[1].force, -50.0);
  EXPECT_EQ(r.trials[0].design.segments[1].mapping, "");  // the trial's
  EXPECT_EQ(r.trials[0].travel, (std::array<double, 2>{0.0, 0.0}));
}

TEST(ScheduleJson, MissingKeyNamesFileIndexAndKey) {
  json j = ScheduleToJson({{SteadyTrial(), SineTrial()}, {}, 0.0});
  j["trials"][1].erase("amplitude");
  const std::string path = TempFile("plan.json", j.dump());
  const std::string e = ErrorOf([&] { ReadScheduleJson(path); });
  EXPECT_THAT(e, HasSubstr(path + ": trials[1]"));
  EXPECT_THAT(e, HasSubstr("missing required key 'amplitude'"));
}

TEST(ScheduleJson, WrongTypeNamesFileIndexKeyAndValue) {
  json j = ScheduleToJson({{SteadyTrial(), SineTrial()}, {}, 0.0});
  j["trials"][0]["force"] = "35 N";
  const std::string path = TempFile("plan.json", j.dump());
  const std::string e = ErrorOf([&] { ReadScheduleJson(path); });
  EXPECT_THAT(e, HasSubstr(path + ": trials[0].force: expected a number"));
  EXPECT_THAT(e, HasSubstr("\"35 N\""));
}

TEST(ScheduleJson, EachMalformedFieldIsRefused) {
  struct Case {
    const char* key;
    json value;
    const char* expected;
  };
  const Case cases[] = {
      {"dof", "surf", "trials[0].dof: expected a DOF"},
      {"kind", "ramp", "trials[0].kind: expected a trial kind"},
      {"duration", 0, "trials[0].duration: expected a positive number"},
      {"duration", true, "trials[0].duration: expected a positive number"},
      {"mapping", 3, "trials[0].mapping: expected a mapping name"},
      {"id", "../escape", "trials[0].id: expected a trial id"},
      {"id", "", "trials[0].id: expected a trial id"},
      {"travel", json({1.0}), "trials[0].travel: expected [min, max]"},
      {"travel", json({2.0, 1.0}), "trials[0].travel: expected [min, max]"},
      {"thrust_min", -1, "trials[0].thrust_min: expected a number >= 0"},
      {"ballast_steps", 1.5, "trials[0].ballast_steps: expected a whole number >= 0"},
  };
  for (const Case& c : cases) {
    json t = TrialToJson(SteadyTrial());
    t[c.key] = c.value;
    const std::string e = ErrorOf([&] { TrialFromJson(io::JsonValue(t, "p.json", "trials[0]")); });
    EXPECT_THAT(e, HasSubstr(std::string("p.json: ") + c.expected)) << c.key << " = " << c.value;
  }
}

TEST(ScheduleJson, SegmentsMustAddUpToTheDuration) {
  json t = TrialToJson(SegmentsTrial());
  t["duration"] = 60.0;  // legs add up to 55.5 s
  const std::string e = ErrorOf([&] { TrialFromJson(io::JsonValue(t, "p.json", "trials[4]")); });
  EXPECT_THAT(e, HasSubstr("p.json: trials[4].duration"));
  EXPECT_THAT(e, HasSubstr("55.5 s for duration 60 s"));

  t = TrialToJson(SegmentsTrial());
  t["segments"][1].erase("force");
  EXPECT_THAT(ErrorOf([&] { TrialFromJson(io::JsonValue(t, "p.json", "trials[4]")); }),
              HasSubstr("p.json: trials[4].segments[1]: missing required key 'force'"));
}

TEST(ScheduleJson, FileLevelFaults) {
  EXPECT_THAT(ErrorOf([] { ReadScheduleJson("/nonexistent/plan.json"); }),
              HasSubstr("/nonexistent/plan.json: cannot open file"));
  const std::string bad = TempFile("bad.json", "{\"trials\": [\n  {\"id\": \"a\",,}\n]}");
  EXPECT_THAT(ErrorOf([&] { ReadScheduleJson(bad); }), HasSubstr(bad + ":2:"));
  EXPECT_THAT(ErrorOf([&] { ReadScheduleJson(bad); }), HasSubstr("not valid JSON"));
  EXPECT_THAT(ErrorOf([] { ReadScheduleJson(TempFile("e.json", "{\"trials\": []}")); }),
              HasSubstr("expected at least one trial"));
  EXPECT_THAT(ErrorOf([] { ReadScheduleJson(TempFile("e.json", "{\"plan\": []}")); }),
              HasSubstr("missing required key 'trials'"));
  json twice = ScheduleToJson({{SteadyTrial(), SteadyTrial()}, {}, 0.0});
  EXPECT_THAT(ErrorOf([&] { ReadScheduleJson(TempFile("t.json", twice.dump())); }),
              HasSubstr("trials[1].id: trial id 'surge_steady_1' appears twice"));
}

}  // namespace
}  // namespace uuvplan::planner
