// The schedule as JSON (contract §schedule, §next).
//
// Reading is strict about the keys the contract names (a missing or ill-typed key is an
// InputError naming the file, the trial index and the key) and ignores keys it does not know
// (the contract welcomes more keys). A trial id names its log file (trials/<id>.csv), so it is
// limited to letters, digits and `_ . - +`, not starting with a dot.
#include "uuvplan/io/schedule_json.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

#include "uuvplan/io/information_json.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/io/plausibility.h"
#include "uuvplan/io/pool_verdict_json.h"

namespace uuvplan::io {

using nlohmann::json;
using planner::PlannedTrial;
using planner::PredictedPrecision;
using planner::Schedule;

namespace {

// ---------------------------------------------------------------------------------------------
// Writing.

json SegmentsToJson(const model::TrialDesign& d) {
  json segments = json::array();
  for (const auto& s : d.segments) {
    segments.push_back({{"force", s.force},
                        {"duration", s.duration},
                        {"mapping", s.mapping.empty() ? d.mapping : s.mapping}});
  }
  return segments;
}

// The fields of the trial's kind (contract §schedule).
void KindFieldsToJson(const model::TrialDesign& d, json* j) {
  switch (d.kind) {
    case model::TrialKind::kSteady:
      (*j)["force"] = d.force;
      break;
    case model::TrialKind::kSine:
      (*j)["offset"] = d.offset;
      (*j)["amplitude"] = d.amplitude;
      (*j)["omega"] = d.omega;
      break;
    case model::TrialKind::kSegments:
      (*j)["segments"] = SegmentsToJson(d);
      break;
    case model::TrialKind::kSwitched: {
      (*j)["offset"] = d.offset;
      json components = json::array();
      for (const auto& c : d.components) {
        components.push_back({{"amplitude", c.amplitude}, {"omega", c.omega}, {"phase", c.phase}});
      }
      (*j)["components"] = components;
      (*j)["mapping_neg"] = d.mapping_neg;
      (*j)["floor"] = {d.floor_pos, d.floor_neg};
      break;
    }
  }
}

// The sampled nominal profile (any tool can replay it) and the start position.
void ProfileToJson(const PlannedTrial& trial, json* j) {
  if (!trial.profile.t.empty()) {
    (*j)["profile"] = {
        {"t", trial.profile.t}, {"force", trial.profile.force}, {"mapping", trial.profile.mapping}};
  }
  if (!trial.start.from.empty()) {
    (*j)["start"] = {
        {"value", trial.start.value}, {"unit", trial.start.unit}, {"from", trial.start.from}};
  }
}

// ---------------------------------------------------------------------------------------------
// Reading.

bool IsIdChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' ||
         c == '+';
}

std::string TrialId(const JsonValue& v) {
  const std::string expectation =
      "a trial id of letters, digits and _ . - + not starting with '.' (it names the trial's "
      "log file)";
  const std::string id = String(v, expectation);
  bool ok = id.front() != '.';
  for (char c : id) ok = ok && IsIdChar(c);
  if (!ok) v.Expected(expectation);
  return id;
}

model::Dof DofOf(const JsonValue& v) {
  if (v.json().is_string()) {
    if (auto dof = model::ParseDof(v.json().get<std::string>())) return *dof;
  }
  v.Expected("a DOF (surge, sway, heave, roll, pitch, yaw)");
}

model::TrialKind KindOf(const JsonValue& v) {
  if (v.json().is_string()) {
    if (const auto kind = model::kTrialKindNames.Parse(v.json().get<std::string>())) return *kind;
  }
  v.Expected("a trial kind (" + model::kTrialKindNames.List() + ")");
}

// A trial's or leg's duration: positive, and plausible for a pool trial (parameter.h).
double PlausibleDuration(const JsonValue& v) {
  const double duration = PositiveNumber(v, "s");
  CheckPlausible(v, duration, plausible::kDuration);
  return duration;
}

std::vector<model::SegmentDesign> SegmentsOf(const JsonValue& v, const std::string& trial_mapping) {
  if (!v.json().is_array() || v.json().empty()) {
    v.Expected("a non-empty array of {force, duration, mapping}");
  }
  std::vector<model::SegmentDesign> segments;
  for (std::size_t i = 0; i < v.json().size(); ++i) {
    const JsonValue s = v.Item(i);
    if (!s.json().is_object()) s.Expected("an object {force, duration, mapping}");
    model::SegmentDesign seg;
    seg.force = Number(s.Required("force", "N or N·m"));
    seg.duration = PlausibleDuration(s.Required("duration", "s"));
    // The contract writes a mapping per segment; a hand-written plan may leave it to the trial.
    if (const auto m = s.Optional("mapping")) seg.mapping = String(*m, "a mapping name");
    if (seg.mapping == trial_mapping) seg.mapping.clear();
    segments.push_back(seg);
  }
  return segments;
}

// The legs make the trial: their durations must add up to it (to 1 µs per second, far below
// any log's resolution, and above the rounding of durations written as decimals).
void CheckSegmentsDuration(const JsonValue& trial, const model::TrialDesign& d) {
  double total = 0.0;
  for (const auto& s : d.segments) total += s.duration;
  if (std::abs(total - d.duration) > 1e-6 * std::max(1.0, d.duration)) {
    std::ostringstream what;
    what.precision(12);
    what << "expected the segments' durations to add up to the trial's, got " << total
         << " s for duration " << d.duration << " s";
    trial.Required("duration").Fail(what.str());
  }
}

// A switched trial's wave: offset, components [{amplitude, omega, phase}], mapping_neg and the
// floors [pos, neg] (>= 0).
void SwitchedFieldsOf(const JsonValue& j, model::TrialDesign* d) {
  d->offset = Number(j.Required("offset", "a switched trial's mean force"), "a number (N or N·m)");
  const JsonValue list = j.Required("components", "a switched trial's sinusoids");
  if (!list.json().is_array()) list.Expected("an array of {amplitude, omega, phase}");
  for (std::size_t i = 0; i < list.json().size(); ++i) {
    const JsonValue c = list.Item(i);
    if (!c.json().is_object()) c.Expected("an object {amplitude, omega, phase}");
    model::SineComponent s;
    s.amplitude = Number(c.Required("amplitude", "N or N·m"));
    s.omega = NonNegativeNumber(c.Required("omega", "rad/s"), "a number >= 0 (rad/s)");
    s.phase = Number(c.Required("phase", "rad"));
    d->components.push_back(s);
  }
  d->mapping_neg =
      String(j.Required("mapping_neg", "the mapping of the negative half"), "a mapping name");
  const JsonValue floor = j.Required("floor", "[pos, neg] smallest |force| of each mapping");
  const json& f = floor.json();
  if (!f.is_array() || f.size() != 2 || !f[0].is_number() || !f[1].is_number() ||
      !(f[0].get<double>() >= 0) || !(f[1].get<double>() >= 0)) {
    floor.Expected("[pos, neg], two numbers >= 0 (N or N·m)");
  }
  d->floor_pos = f[0].get<double>();
  d->floor_neg = f[1].get<double>();
}

// The fields of the trial's kind.
void KindFieldsOf(const JsonValue& j, model::TrialDesign* d) {
  switch (d->kind) {
    case model::TrialKind::kSteady:
      d->force =
          Number(j.Required("force", "a steady trial's constant force"), "a number (N or N·m)");
      break;
    case model::TrialKind::kSine:
      d->offset = Number(j.Required("offset", "a sine trial's mean force"), "a number (N or N·m)");
      d->amplitude =
          Number(j.Required("amplitude", "a sine trial's force amplitude"), "a number (N or N·m)");
      d->omega = NonNegativeNumber(j.Required("omega", "a sine trial's frequency"),
                                   "a number >= 0 (rad/s)");
      break;
    case model::TrialKind::kSegments:
      d->segments = SegmentsOf(j.Required("segments", "a segments trial's legs"), d->mapping);
      CheckSegmentsDuration(j, *d);
      break;
    case model::TrialKind::kSwitched:
      SwitchedFieldsOf(j, d);
      break;
  }
}

// start: {value, unit, from} (the profile is written for other tools; the design replays).
planner::StartPosition StartOf(const JsonValue& v) {
  if (!v.json().is_object()) v.Expected("an object {value, unit, from}");
  planner::StartPosition s;
  s.value = Number(v.Required("value", "m or deg"));
  s.unit = String(v.Required("unit", "m or deg"), "a unit (m or deg)");
  s.from = String(v.Required("from", "what the value is measured from"), "a named wall or heading");
  return s;
}

// travel: [min, max] with min <= max (m or rad).
std::array<double, 2> TravelOf(const JsonValue& v) {
  const std::string expectation = "[min, max] with min <= max (m or rad)";
  const json& j = v.json();
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) {
    v.Expected(expectation);
  }
  const std::array<double, 2> t = {j[0].get<double>(), j[1].get<double>()};
  if (!std::isfinite(t[0]) || !std::isfinite(t[1]) || t[0] > t[1]) v.Expected(expectation);
  return t;
}

}  // namespace

std::string PredictedAssumptionOf(const JsonValue& predicted) {
  const auto a = predicted.Optional("assumption");
  if (!a) return kUnrecordedSigmaAssumption;
  return String(*a, "the sentence saying what the predicted σ rest on");
}

namespace {

PredictedPrecision PredictedOf(const JsonValue& v) {
  if (!v.json().is_object()) v.Expected("an object {sigma, criterion, value}");
  PredictedPrecision p;
  const JsonValue sigma = v.Required("sigma", "predicted 1σ per parameter");
  if (!sigma.json().is_object()) sigma.Expected("an object {<parameter>: sigma}");
  for (const auto& item : sigma.json().items()) {
    const JsonValue s = *sigma.Optional(item.key());
    const double x = NumberOrNaN(s, "a number >= 0, or null");
    if (x < 0) s.Expected("a number >= 0, or null");
    p.sigma[item.key()] = x;
  }
  p.criterion = String(v.Required("criterion", "D, Ds, A or E"), "a criterion name (D, Ds, A, E)");
  p.criterion_value = NumberOrNaN(v.Required("value", "the criterion value"));
  p.assumption = PredictedAssumptionOf(v);
  return p;
}

std::map<model::Dof, PredictedPrecision> PredictedMapOf(const JsonValue& v) {
  if (!v.json().is_object()) v.Expected("an object {<dof>: {sigma, criterion, value}}");
  std::map<model::Dof, PredictedPrecision> out;
  for (const auto& [name, p] : v.json().items()) {
    const auto dof = model::ParseDof(name);
    if (!dof) v.Fail("key '" + name + "': expected a DOF (surge, sway, heave, roll, pitch, yaw)");
    out[*dof] = PredictedOf(*v.Optional(name));
  }
  return out;
}

// The trials of a schedule ("trials") or of a `next` result ("trial").
std::vector<PlannedTrial> TrialsOf(const JsonValue& root) {
  std::vector<PlannedTrial> trials;
  if (const auto list = root.Optional("trials")) {
    if (!list->json().is_array()) list->Expected("an array of trials");
    for (std::size_t i = 0; i < list->json().size(); ++i) {
      trials.push_back(TrialFromJson(list->Item(i)));
    }
    if (trials.empty()) list->Fail("expected at least one trial, got an empty array");
  } else if (const auto trial = root.Optional("trial")) {
    trials.push_back(TrialFromJson(*trial));
  } else {
    root.Fail("missing required key 'trials' (a schedule) or 'trial' (a `next` result)");
  }
  return trials;
}

// Each trial's log is trials/<id>.csv: ids must differ.
void CheckDistinctIds(const JsonValue& root, const std::vector<PlannedTrial>& trials) {
  std::set<std::string> ids;
  for (std::size_t i = 0; i < trials.size(); ++i) {
    if (!ids.insert(trials[i].design.id).second) {
      Place(root.file(), 0, "trials[" + std::to_string(i) + "].id")
          .Fail("trial id '" + trials[i].design.id +
                "' appears twice (each trial's log is trials/<id>.csv)");
    }
  }
}

}  // namespace

json TrialToJson(const PlannedTrial& trial) {
  const model::TrialDesign& d = trial.design;
  json j;
  j["id"] = d.id;
  j["dof"] = std::string(model::DofName(d.dof));
  j["kind"] = std::string(model::TrialKindName(d.kind));
  j["duration"] = d.duration;
  j["mapping"] = d.mapping;
  KindFieldsToJson(d, &j);
  if (d.family != model::InputFamily::kPlain)
    j["family"] = std::string(model::InputFamilyName(d.family));
  j["travel"] = {trial.travel[0], trial.travel[1]};
  j["thrust_min"] = trial.thrust_min;
  if (d.ballast_steps != 0) j["ballast_steps"] = d.ballast_steps;
  ProfileToJson(trial, &j);
  return j;
}

json PredictedToJson(const PredictedPrecision& p) {
  json sigma = json::object();
  for (const auto& [name, s] : p.sigma) sigma[name] = JsonNumber(s);
  return {{"sigma", sigma},
          {"criterion", p.criterion},
          {"value", JsonNumber(p.criterion_value)},
          {"assumption", p.assumption}};
}

json ScheduleToJson(const Schedule& schedule) {
  json trials = json::array();
  for (const auto& t : schedule.trials) trials.push_back(TrialToJson(t));
  json predicted = json::object();
  for (const auto& [dof, p] : schedule.predicted) {
    predicted[std::string(model::DofName(dof))] = PredictedToJson(p);
  }
  return {{"trials", trials}, {"predicted", predicted}, {"pool_time", schedule.pool_time}};
}

json ScheduleResultJson(const planner::ScheduleResult& r,
                        const planner::ScheduleInformation& information,
                        const planner::PoolVerdict& verdict, const model::Pool& pool) {
  json j = ScheduleToJson(r.schedule);
  j["status"] = std::string(planner::PlanStatusName(r.status));
  json notes = json::array();
  json missing = json::object();
  for (const auto& d : r.dofs) {
    for (const auto& n : d.notes) notes.push_back(n);
    if (!d.complete) missing[std::string(model::DofName(d.dof))] = {{"message", d.message}};
  }
  j["notes"] = notes;
  if (!missing.empty()) j["not_planned"] = missing;
  j["verdict"] = PoolVerdictJson(verdict, pool);
  AddInformationJson(information, &j);
  return j;
}

json UnplannedScheduleJson(const std::vector<PlannedTrial>& plan, const std::string& note) {
  json trials = json::array();
  for (const auto& t : plan) {
    json j = TrialToJson(t);
    j.erase("travel");
    j.erase("thrust_min");
    trials.push_back(j);
  }
  return {{"trials", trials}, {"note", note}};
}

PlannedTrial TrialFromJson(const JsonValue& j) {
  if (!j.json().is_object()) j.Expected("a trial object");
  PlannedTrial trial;
  model::TrialDesign& d = trial.design;
  d.id = TrialId(j.Required("id", "the trial's name"));
  d.dof = DofOf(j.Required("dof", "surge, sway, heave, roll, pitch or yaw"));
  d.kind = KindOf(j.Required("kind", "steady, sine, segments or switched"));
  d.duration = PlausibleDuration(j.Required("duration", "s"));
  d.mapping = String(j.Required("mapping", "the thrust mapping of the trial"), "a mapping name");
  KindFieldsOf(j, &d);
  if (const auto t = j.Optional("travel")) trial.travel = TravelOf(*t);
  if (const auto t = j.Optional("thrust_min")) {
    trial.thrust_min = NonNegativeNumber(*t, "a number >= 0 (N)");
  }
  if (const auto b = j.Optional("ballast_steps")) d.ballast_steps = WholeNonNegative(*b);
  if (const auto f = j.Optional("family")) {
    const auto family = f->json().is_string()
                            ? model::kInputFamilyNames.Parse(f->json().get<std::string>())
                            : std::nullopt;
    if (!family) f->Expected("an input family (" + model::kInputFamilyNames.List() + ")");
    d.family = *family;
  }
  if (const auto s = j.Optional("start")) trial.start = StartOf(*s);
  return trial;
}

Schedule ReadScheduleJson(const std::string& path) {
  const json root_json = LoadJson(path);
  const JsonValue root(root_json, path, "");
  if (!root_json.is_object()) {
    root.Expected("a schedule {\"trials\": [...]} or a `next` result {\"trial\": {...}}");
  }
  Schedule schedule;
  schedule.trials = TrialsOf(root);
  CheckDistinctIds(root, schedule.trials);
  // A schedule's predicted precision (a `next` result's "predicted" is its own business).
  if (const auto p = root.Optional("predicted"); p && root_json.contains("trials")) {
    schedule.predicted = PredictedMapOf(*p);
  }
  if (const auto t = root.Optional("pool_time")) {
    schedule.pool_time = NonNegativeNumber(*t, "a number >= 0 (s)");
  }
  return schedule;
}

std::optional<StoredVerdict> ReadScheduleVerdict(const std::string& path) {
  const json root_json = LoadJson(path);
  const JsonValue root(root_json, path, "");
  const auto v = root.Optional("verdict");
  if (!v) return std::nullopt;
  if (!v->json().is_object()) v->Expected("an object {hosted, sentence, lines}");
  StoredVerdict out;
  const auto hosted = v->Optional("hosted");
  const auto sentence = v->Optional("sentence");
  const auto lines = v->Optional("lines");
  if (!hosted || !hosted->json().is_boolean()) v->Expected("an object with \"hosted\": true|false");
  if (!sentence || !sentence->json().is_string()) v->Expected("an object with a \"sentence\"");
  if (!lines || !lines->json().is_array()) v->Expected("an object with \"lines\": [...]");
  out.hosted = hosted->json().get<bool>();
  out.sentence = sentence->json().get<std::string>();
  for (std::size_t i = 0; i < lines->json().size(); ++i) {
    const JsonValue line = lines->Item(i);
    if (!line.json().is_string()) line.Expected("a line of text");
    out.lines.push_back(line.json().get<std::string>());
  }
  return out;
}

std::vector<model::Dof> ScheduleDofs(const std::string& path) {
  std::set<model::Dof> dofs;
  for (const PlannedTrial& t : ReadScheduleJson(path).trials) dofs.insert(t.design.dof);
  const json root_json = LoadJson(path);
  const JsonValue root(root_json, path, "");
  if (const auto np = root.Optional("not_planned")) {
    if (!np->json().is_object()) np->Expected("an object {<dof>: {message}}");
    for (const auto& [name, why] : np->json().items()) {
      const auto dof = model::ParseDof(name);
      if (!dof)
        np->Fail("key '" + name + "': expected a DOF (surge, sway, heave, roll, pitch, yaw)");
      dofs.insert(*dof);
    }
  }
  return {dofs.begin(), dofs.end()};
}

}  // namespace uuvplan::io
