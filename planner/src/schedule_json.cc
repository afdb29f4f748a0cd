// The schedule as JSON (contract §schedule, §next): writing a schedule and reading one back, or
// reading the single trial of a `next` result, for `uuvplan simulate` and the pool team.
//
// Reading is strict about the keys the contract names (a missing or ill-typed key is an
// InputError naming the file, the trial index and the key) and ignores keys it does not know
// (the contract welcomes more keys). A trial id names its log file (trials/<id>.csv), so it is
// limited to letters, digits and `_ . - +`, not starting with a dot.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "uuvplan/model/input_error.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::planner {
namespace {

using model::InputError;
using nlohmann::json;

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

// ---------------------------------------------------------------------------------------------
// Reading: `where` is "<file>: trials[i]" (or "<file>: trial"); a key's place is where.key.

std::string TypeName(const json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number()) return "the number " + v.dump();
  if (v.is_string()) {
    std::string s = v.get<std::string>();
    if (s.size() > 40) s = s.substr(0, 40) + "...";
    return "the string \"" + s + "\"";
  }
  if (v.is_array()) return "an array";
  return "an object";
}

// The place of `key` inside `where`: "f.json: trials[2]" + "force" -> "f.json: trials[2].force";
// a top-level key of a file is passed as where = "f.json: " -> "f.json: pool_time".
std::string Place(const std::string& where, const std::string& key) {
  return !where.empty() && where.back() == ' ' ? where + key : where + "." + key;
}

[[noreturn]] void Expected(const std::string& where, const std::string& key,
                           const std::string& expectation, const json& got) {
  throw InputError(Place(where, key), "expected " + expectation + ", got " + TypeName(got));
}

const json& Required(const json& obj, const std::string& where, const std::string& key,
                     const std::string& why) {
  const auto it = obj.find(key);
  if (it == obj.end()) {
    throw InputError(where,
                     "missing required key '" + key + "'" + (why.empty() ? "" : " (" + why + ")"));
  }
  return *it;
}

double Number(const json& v, const std::string& where, const std::string& key,
              const std::string& expectation = "a number") {
  if (!v.is_number() || !std::isfinite(v.get<double>())) Expected(where, key, expectation, v);
  return v.get<double>();
}

double PositiveNumber(const json& v, const std::string& where, const std::string& key,
                      const std::string& unit) {
  const std::string expectation = "a positive number (" + unit + ")";
  const double x = Number(v, where, key, expectation);
  if (!(x > 0)) Expected(where, key, expectation, v);
  return x;
}

std::string String(const json& v, const std::string& where, const std::string& key,
                   const std::string& expectation) {
  if (!v.is_string() || v.get<std::string>().empty()) Expected(where, key, expectation, v);
  return v.get<std::string>();
}

int WholeNonNegative(const json& v, const std::string& where, const std::string& key) {
  const std::string expectation = "a whole number >= 0";
  const double x = Number(v, where, key, expectation);
  if (x < 0 || x != std::floor(x) || x > 1e6) Expected(where, key, expectation, v);
  return static_cast<int>(x);
}

bool IsIdChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' ||
         c == '+';
}

std::string TrialId(const json& v, const std::string& where) {
  const std::string expectation =
      "a trial id of letters, digits and _ . - + not starting with '.' (it names the trial's "
      "log file)";
  const std::string id = String(v, where, "id", expectation);
  bool ok = id.front() != '.';
  for (char c : id) ok = ok && IsIdChar(c);
  if (!ok) Expected(where, "id", expectation, v);
  return id;
}

model::Dof DofOf(const json& v, const std::string& where) {
  const std::string expectation = "a DOF (surge, sway, heave, roll, pitch, yaw)";
  if (v.is_string()) {
    if (auto dof = model::ParseDof(v.get<std::string>())) return *dof;
  }
  Expected(where, "dof", expectation, v);
}

model::TrialKind KindOf(const json& v, const std::string& where) {
  if (v.is_string()) {
    const std::string k = v.get<std::string>();
    if (k == "steady") return model::TrialKind::kSteady;
    if (k == "sine") return model::TrialKind::kSine;
    if (k == "segments") return model::TrialKind::kSegments;
  }
  Expected(where, "kind", "a trial kind (steady, sine, segments)", v);
}

std::vector<model::SegmentDesign> SegmentsOf(const json& v, const std::string& where,
                                             const std::string& trial_mapping) {
  const std::string expectation = "a non-empty array of {force, duration, mapping}";
  if (!v.is_array() || v.empty()) Expected(where, "segments", expectation, v);
  std::vector<model::SegmentDesign> segments;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string at = where + ".segments[" + std::to_string(i) + "]";
    const json& s = v[i];
    if (!s.is_object()) {
      throw InputError(at, "expected an object {force, duration, mapping}, got " + TypeName(s));
    }
    model::SegmentDesign seg;
    seg.force = Number(Required(s, at, "force", "N or N·m"), at, "force");
    seg.duration = PositiveNumber(Required(s, at, "duration", "s"), at, "duration", "s");
    // The contract writes a mapping per segment; a hand-written plan may leave it to the trial.
    if (const auto m = s.find("mapping"); m != s.end()) {
      seg.mapping = String(*m, at, "mapping", "a mapping name");
    }
    if (seg.mapping == trial_mapping) seg.mapping.clear();
    segments.push_back(seg);
  }
  return segments;
}

// travel: [min, max] with min <= max (m or rad).
std::array<double, 2> TravelOf(const json& v, const std::string& where) {
  const std::string expectation = "[min, max] with min <= max (m or rad)";
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
    Expected(where, "travel", expectation, v);
  }
  const std::array<double, 2> t = {v[0].get<double>(), v[1].get<double>()};
  if (!std::isfinite(t[0]) || !std::isfinite(t[1]) || t[0] > t[1]) {
    Expected(where, "travel", expectation, v);
  }
  return t;
}

PredictedPrecision PredictedOf(const json& v, const std::string& where) {
  if (!v.is_object()) {
    throw InputError(where, "expected an object {sigma, criterion, value}, got " + TypeName(v));
  }
  PredictedPrecision p;
  const json& sigma = Required(v, where, "sigma", "predicted 1σ per parameter");
  if (!sigma.is_object()) Expected(where, "sigma", "an object {<parameter>: sigma}", sigma);
  for (const auto& [name, s] : sigma.items()) {
    const double x = Number(s, where + ".sigma", name, "a number >= 0");
    if (x < 0) Expected(where + ".sigma", name, "a number >= 0", s);
    p.sigma[name] = x;
  }
  p.criterion = String(Required(v, where, "criterion", "D, Ds, A or E"), where, "criterion",
                       "a criterion name (D, Ds, A, E)");
  p.criterion_value = Number(Required(v, where, "value", "the criterion value"), where, "value");
  return p;
}

std::map<model::Dof, PredictedPrecision> PredictedMapOf(const json& v, const std::string& where) {
  if (!v.is_object()) {
    throw InputError(where,
                     "expected an object {<dof>: {sigma, criterion, value}}, got " + TypeName(v));
  }
  std::map<model::Dof, PredictedPrecision> out;
  for (const auto& [name, p] : v.items()) {
    const auto dof = model::ParseDof(name);
    if (!dof) {
      throw InputError(where, "key '" + name +
                                  "': expected a DOF (surge, sway, heave, roll, "
                                  "pitch, yaw)");
    }
    out[*dof] = PredictedOf(p, where + "." + name);
  }
  return out;
}

// Line and column of byte offset `pos` in `text` (1-based), for parse errors.
std::string LineColumn(const std::string& text, std::size_t pos) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < pos && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
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
  switch (d.kind) {
    case model::TrialKind::kSteady:
      j["force"] = d.force;
      break;
    case model::TrialKind::kSine:
      j["offset"] = d.offset;
      j["amplitude"] = d.amplitude;
      j["omega"] = d.omega;
      break;
    case model::TrialKind::kSegments:
      j["segments"] = SegmentsToJson(d);
      break;
  }
  j["travel"] = {trial.travel[0], trial.travel[1]};
  j["thrust_min"] = trial.thrust_min;
  if (d.ballast_steps != 0) j["ballast_steps"] = d.ballast_steps;
  return j;
}

json ScheduleToJson(const Schedule& schedule) {
  json trials = json::array();
  for (const auto& t : schedule.trials) trials.push_back(TrialToJson(t));
  json predicted = json::object();
  for (const auto& [dof, p] : schedule.predicted) {
    json sigma = json::object();
    for (const auto& [name, s] : p.sigma) sigma[name] = s;
    predicted[std::string(model::DofName(dof))] = {
        {"sigma", sigma}, {"criterion", p.criterion}, {"value", p.criterion_value}};
  }
  return {{"trials", trials}, {"predicted", predicted}, {"pool_time", schedule.pool_time}};
}

PlannedTrial TrialFromJson(const json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where, "expected a trial object, got " + TypeName(j));
  PlannedTrial trial;
  model::TrialDesign& d = trial.design;
  d.id = TrialId(Required(j, where, "id", "the trial's name"), where);
  d.dof = DofOf(Required(j, where, "dof", "surge, sway, heave, roll, pitch or yaw"), where);
  d.kind = KindOf(Required(j, where, "kind", "steady, sine or segments"), where);
  d.duration = PositiveNumber(Required(j, where, "duration", "s"), where, "duration", "s");
  d.mapping = String(Required(j, where, "mapping", "the thrust mapping of the trial"), where,
                     "mapping", "a mapping name");
  switch (d.kind) {
    case model::TrialKind::kSteady:
      d.force = Number(Required(j, where, "force", "a steady trial's constant force"), where,
                       "force", "a number (N or N·m)");
      break;
    case model::TrialKind::kSine:
      d.offset = Number(Required(j, where, "offset", "a sine trial's mean force"), where, "offset",
                        "a number (N or N·m)");
      d.amplitude = Number(Required(j, where, "amplitude", "a sine trial's force amplitude"), where,
                           "amplitude", "a number (N or N·m)");
      d.omega = Number(Required(j, where, "omega", "a sine trial's frequency"), where, "omega",
                       "a number >= 0 (rad/s)");
      if (d.omega < 0) Expected(where, "omega", "a number >= 0 (rad/s)", j.at("omega"));
      break;
    case model::TrialKind::kSegments: {
      d.segments =
          SegmentsOf(Required(j, where, "segments", "a segments trial's legs"), where, d.mapping);
      double total = 0.0;
      for (const auto& s : d.segments) total += s.duration;
      // The legs make the trial: their durations must add up to it (to 1 µs per second, far
      // below any log's resolution, and above the rounding of durations written as decimals).
      if (std::abs(total - d.duration) > 1e-6 * std::max(1.0, d.duration)) {
        std::ostringstream what;
        what.precision(12);
        what << "expected the segments' durations to add up to the trial's, got " << total
             << " s for duration " << d.duration << " s";
        throw InputError(where + ".duration", what.str());
      }
      break;
    }
  }
  if (const auto t = j.find("travel"); t != j.end()) trial.travel = TravelOf(*t, where);
  if (const auto t = j.find("thrust_min"); t != j.end()) {
    trial.thrust_min = Number(*t, where, "thrust_min", "a number >= 0 (N)");
    if (trial.thrust_min < 0) Expected(where, "thrust_min", "a number >= 0 (N)", *t);
  }
  if (const auto b = j.find("ballast_steps"); b != j.end()) {
    d.ballast_steps = WholeNonNegative(*b, where, "ballast_steps");
  }
  return trial;
}

Schedule ReadScheduleJson(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path, "cannot open file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open file: ") + std::strerror(errno));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: ...";
    // keep what follows the position and put the position in our own "file:line:col" form.
    std::string why = e.what();
    if (const auto colon = why.find(": ", why.find("parse error")); colon != std::string::npos) {
      why = why.substr(colon + 2);
    }
    const std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
    throw InputError(path + ":" + LineColumn(text, at), "not valid JSON: " + why);
  }
  if (!root.is_object()) {
    throw InputError(path,
                     "expected a schedule {\"trials\": [...]} or a `next` result "
                     "{\"trial\": {...}}, got " +
                         TypeName(root));
  }
  Schedule schedule;
  if (const auto trials = root.find("trials"); trials != root.end()) {
    if (!trials->is_array()) Expected(path + ": ", "trials", "an array of trials", *trials);
    for (std::size_t i = 0; i < trials->size(); ++i) {
      schedule.trials.push_back(
          TrialFromJson((*trials)[i], path + ": trials[" + std::to_string(i) + "]"));
    }
  } else if (const auto trial = root.find("trial"); trial != root.end()) {
    schedule.trials.push_back(TrialFromJson(*trial, path + ": trial"));
  } else {
    throw InputError(path,
                     "missing required key 'trials' (a schedule) or 'trial' (a `next` "
                     "result)");
  }
  if (schedule.trials.empty()) {
    throw InputError(path + ": trials", "expected at least one trial, got an empty array");
  }
  std::set<std::string> ids;
  for (std::size_t i = 0; i < schedule.trials.size(); ++i) {
    if (!ids.insert(schedule.trials[i].design.id).second) {
      throw InputError(path + ": trials[" + std::to_string(i) + "].id",
                       "trial id '" + schedule.trials[i].design.id +
                           "' appears twice (each trial's log is trials/<id>.csv)");
    }
  }
  // A schedule's predicted precision (a `next` result's "predicted" is its own business).
  if (const auto p = root.find("predicted"); p != root.end() && root.contains("trials")) {
    schedule.predicted = PredictedMapOf(*p, path + ": predicted");
  }
  if (const auto t = root.find("pool_time"); t != root.end()) {
    schedule.pool_time = Number(*t, path + ": ", "pool_time", "a number >= 0 (s)");
    if (schedule.pool_time < 0) Expected(path + ": ", "pool_time", "a number >= 0 (s)", *t);
  }
  return schedule;
}

}  // namespace uuvplan::planner
