#include "import/import_map.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>

#include "uuvplan/io/files.h"
#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io::import {
namespace {

namespace fs = std::filesystem;
using model::InputError;

std::string SourcePath(const Value& v, const std::string& source_dir) {
  const fs::path written(Name(v, "a path relative to the recordings' directory"));
  const std::string path =
      (written.is_absolute() ? written : fs::path(source_dir) / written).string();
  const std::string why = UnreadableReason(path);
  if (!why.empty())
    v.Expected("a readable file (relative to " + source_dir + ")", path + ": " + why);
  return path;
}

// Two numbers per line: the table as (command, N), sorted by command.
std::vector<std::array<double, 2>> ReadThrustTable(const std::string& path, bool thrust_first) {
  std::istringstream in(ReadFileText(path));
  std::vector<std::array<double, 2>> table;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    std::istringstream words(line);
    double a = NAN, b = NAN;
    std::string rest;
    const bool numbers = bool(words >> a >> b) && !(words >> rest);
    if (!numbers && table.empty()) continue;  // a heading
    if (!numbers || !std::isfinite(a) || !std::isfinite(b)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      throw InputError(path + ":" + std::to_string(line_number),
                       "expected two numbers (command and thrust), got '" + line + "'");
    }
    table.push_back(thrust_first ? std::array<double, 2>{b, a} : std::array<double, 2>{a, b});
  }
  std::sort(table.begin(), table.end());
  for (std::size_t i = 1; i < table.size(); ++i) {
    if (table[i][0] == table[i - 1][0]) {
      throw InputError(
          path, "expected one thrust per command, got two at " + std::to_string(table[i][0]));
    }
  }
  if (table.size() < 2) throw InputError(path, "expected a table of at least two rows");
  return table;
}

void ReadThrustTableKey(const Value& v, const std::string& source_dir, ImportMap* m) {
  const MapValue map(v, "a map {file, columns}");
  map.AllowOnly({"file", "columns"});
  const std::string path = SourcePath(map.Required("file"), source_dir);
  bool thrust_first = false;
  if (map.Has("columns")) {
    const Value columns = map.Optional("columns");
    const std::vector<Value> names = List(columns, "[command, thrust] or [thrust, command]");
    if (names.size() != 2) columns.Expected("[command, thrust] or [thrust, command]");
    thrust_first = Choice(names[0], {"command", "thrust"}, "a column") == 1;
    if (Choice(names[1], {"command", "thrust"}, "a column") == int(thrust_first)) {
      columns.Expected("[command, thrust] or [thrust, command]");
    }
  }
  m->thrust_table_file = map.Required("file").node().Scalar();
  m->thrust_table = ReadThrustTable(path, thrust_first);
}

void ReadCommands(const Value& v, ImportMap* m) {
  const MapValue map(v, "a map {topic, unit, thrusters}");
  map.AllowOnly({"topic", "unit", "neutral", "full_scale", "thrusters"});
  m->command_topic = Name(map.Required("topic"), "a topic");
  m->unit = CommandUnit(Choice(map.Required("unit"), {"pwm_us", "normalised", "N"}, "a unit"));
  if (map.Has("neutral")) m->neutral = AnyNumber(map.Optional("neutral"));
  if (map.Has("full_scale")) m->full_scale = Positive(map.Optional("full_scale"));
  const MapValue thrusters(map.Required("thrusters"), "a map thruster: field");
  for (const MapValue::Entry& e : thrusters.entries()) {
    m->thrusters.emplace_back(e.key, Name(e.value, "a field of the command message"));
  }
  if (m->thrusters.empty()) map.Required("thrusters").Expected("at least one thruster");
}

void ReadForces(const Value& v, ImportMap* m) {
  const MapValue map(v, "a map dof: {thruster: arm}");
  for (const MapValue::Entry& e : map.entries()) {
    const model::Dof dof = DofKey(e);
    const MapValue arms(e.value, "a map thruster: arm (m; 1 or -1 for a force)");
    for (const MapValue::Entry& a : arms.entries()) {
      const bool known = std::any_of(m->thrusters.begin(), m->thrusters.end(),
                                     [&](const auto& t) { return t.first == a.key; });
      if (!known) a.key_value.Expected("a thruster named under commands.thrusters", a.key);
      m->forces[dof][a.key] = AnyNumber(a.value);
    }
  }
}

// The sign and turn that take a value in `frame` to uuvplan's NED/FRD axes (Fossen 2011 §2.1;
// ROS REP 103). Body FLU→FRD flips y and z: sway, heave, pitch and yaw rates. World ENU→NED
// swaps x and y and flips z: the field named is the one along the DOF's axis (north for surge,
// east for sway, unchanged), up becomes down (heave), and the attitude: roll about north
// unchanged, pitch flipped, heading ψ (from east, counter-clockwise) becomes π/2 − ψ.
void ReadFrame(const Value& v, MeasuredSignal* s) {
  const int frame = s->position ? Choice(v, {"ned", "enu"}, "a world frame")
                                : Choice(v, {"frd", "flu"}, "a body frame");
  s->frame = v.node().Scalar();
  if (frame == 0) return;
  const model::Dof d = s->dof;
  const bool flipped = d == model::Dof::kHeave || d == model::Dof::kPitch ||
                       d == model::Dof::kYaw || (!s->position && d == model::Dof::kSway);
  s->sign = flipped ? -1.0 : 1.0;
  if (s->position && d == model::Dof::kYaw) s->turn = M_PI / 2;
}

MeasuredSignal ReadSignal(const MapValue::Entry& e) {
  MeasuredSignal s;
  s.column = e.key;
  const std::string kind = e.key.substr(0, e.key.find('_') + 1);
  const auto dof = model::ParseDof(e.key.substr(kind.size()));
  if ((kind != "pos_" && kind != "vel_") || !dof) {
    e.key_value.Expected("a column pos_<dof> or vel_<dof>", e.key);
  }
  s.dof = *dof;
  s.position = kind == "pos_";
  const MapValue map(e.value, "a map {topic, field, scale, offset, frame}");
  map.AllowOnly({"topic", "field", "scale", "offset", "frame"});
  s.topic = Name(map.Required("topic"), "a topic");
  s.field = Name(map.Required("field"), "a field of the message");
  if (map.Has("scale")) s.scale = AnyNumber(map.Optional("scale"));
  if (map.Has("offset")) s.offset = AnyNumber(map.Optional("offset"));
  s.frame = s.position ? "ned" : "frd";
  if (map.Has("frame")) ReadFrame(map.Optional("frame"), &s);
  return s;
}

void ReadClocks(const Value& v, ImportMap* m) {
  const MapValue map(v, "a map topic: {field, scale, align}");
  for (const MapValue::Entry& e : map.entries()) {
    const MapValue clock(e.value, "a map {field, scale, align}");
    clock.AllowOnly({"field", "scale", "align"});
    DeviceClock& c = m->clocks[e.key];
    c.field = Name(clock.Required("field"), "a field of the message");
    if (clock.Has("scale")) c.scale = Positive(clock.Optional("scale"));
    if (clock.Has("align"))
      c.align = Choice(clock.Optional("align"), {"arrival", "none"}, "an alignment") == 0;
  }
}

// `ranges: {trial: [[start, end], ...]}`: s after the recording's first command message.
void ReadRanges(const Value& v, ImportMap* m) {
  const MapValue map(v, "a map trial: [[start, end], ...] (s after the first command)");
  for (const MapValue::Entry& e : map.entries()) {
    for (const Value& item : List(e.value, "a list of [start, end] in s")) {
      const std::array<double, 2> range = Pair(item, "[start, end] in s, 0 <= start < end");
      if (!(range[0] >= 0 && range[0] < range[1])) {
        item.Expected("[start, end] in s, 0 <= start < end");
      }
      m->ranges[e.key].push_back(range);
    }
  }
}

void ReadTrialKeys(const MapValue& top, ImportMap* m) {
  if (top.Has("files")) m->files = Name(top.Optional("files"), "a file pattern such as '*.bag'");
  if (top.Has("trial_id")) {
    const Value v = top.Optional("trial_id");
    m->trial_id = Name(v, "a regular expression");
    try {
      if (std::regex(m->trial_id).mark_count() < 1)
        v.Expected("a regular expression with a (group)");
    } catch (const std::regex_error& e) {
      v.Expected("a regular expression", "'" + m->trial_id + "' (" + e.what() + ")");
    }
  }
  m->dof = DofValue(top.Required("dof"));
  m->mapping = Name(top.Required("mapping"), "a mapping of the vehicle");
  if (top.Has("use")) {
    const MapValue use(top.Optional("use"), "a map trial: fit | validate");
    for (const MapValue::Entry& e : use.entries()) {
      m->use[e.key] = Choice(e.value, {"fit", "validate"}, "a use") == 0
                          ? model::TrialUse::kFit
                          : model::TrialUse::kValidate;
    }
  }
  if (top.Has("cut")) {
    m->cut = Cut(Choice(top.Optional("cut"), {"file", "activity", "ranges"}, "a cut"));
  }
  if (m->cut == Cut::kRanges) ReadRanges(top.Required("ranges"), m);
  if (top.Has("quiet")) m->quiet_s = Positive(top.Optional("quiet"));
}

void CheckForceSource(const MapValue& top, const ImportMap& m) {
  const bool in_newton = m.unit == CommandUnit::kNewton;
  if (m.WritesForces() && m.thrust_table.empty() && !in_newton) {
    top.Required("forces").Expected(
        "forces only with a thrust_table or commands in N (without forces, cmd_ columns let "
        "the vehicle's thrust model turn commands into force)",
        "forces without either");
  }
  if (!m.WritesForces() && (in_newton || !m.thrust_table.empty())) {
    top.Required("forces");  // thrust in N is no command a vehicle file takes
  }
  if (m.measured.empty()) top.Required("measured").Expected("at least one measured signal");
  if (m.WritesForces() && !m.forces.count(m.dof)) {
    top.Required("forces").Expected(
        "the arms of the trials' DOF " + std::string(model::DofName(m.dof)),
        "forces without " + std::string(model::DofName(m.dof)));
  }
}

// A clock belongs to a measured topic (commands are timed by their arrival).
void CheckClockTopics(const MapValue& top, const ImportMap& m) {
  for (const auto& named : m.clocks) {
    const std::string& topic = named.first;
    const bool measured = std::any_of(m.measured.begin(), m.measured.end(),
                                      [&](const MeasuredSignal& g) { return g.topic == topic; });
    if (!measured) {
      top.Required("clocks").Expected("clocks of topics named under measured", topic);
    }
  }
}

// `csv_topics: {topic: file}`: every topic the map reads must have its file.
void ReadCsvTopics(const MapValue& top, ImportMap* m) {
  const Value v = top.Optional("csv_topics");
  const MapValue files(v, "a map topic: CSV file (rostopic echo -p)");
  for (const MapValue::Entry& e : files.entries()) {
    m->csv_topics[e.key] = Name(e.value, "a CSV file name");
  }
  std::vector<std::string> topics{m->command_topic};
  for (const MeasuredSignal& g : m->measured) topics.push_back(g.topic);
  for (const std::string& topic : topics) {
    if (!m->csv_topics.count(topic)) v.Expected("a CSV file for topic " + topic, v.Describe());
  }
}

}  // namespace

double ImportMap::Thrust(double command) const {
  if (thrust_table.empty()) return command;
  if (command <= thrust_table.front()[0]) return thrust_table.front()[1];
  if (command >= thrust_table.back()[0]) return thrust_table.back()[1];
  const auto hi = std::upper_bound(thrust_table.begin(), thrust_table.end(),
                                   std::array<double, 2>{command, INFINITY});
  const auto lo = hi - 1;
  const double w = (command - (*lo)[0]) / ((*hi)[0] - (*lo)[0]);
  return (1 - w) * (*lo)[1] + w * (*hi)[1];
}

ImportMap ReadImportMap(const std::string& file, const std::string& source_dir, bool read_vehicle) {
  return Guarded(file, [&] {
    const MapValue top = LoadYamlMap(file, "an import map", "a map of import keys");
    top.AllowOnly({"files", "csv_topics", "trial_id", "vehicle", "dof", "mapping", "use",
                   "commands", "thrust_table", "forces", "measured", "clocks", "cut", "quiet",
                   "ranges"});
    ImportMap m;
    m.file = file;
    ReadTrialKeys(top, &m);
    if (read_vehicle && top.Has("vehicle")) {
      m.vehicle = SourcePath(top.Optional("vehicle"), source_dir);
    }
    ReadCommands(top.Required("commands"), &m);
    if (top.Has("thrust_table")) ReadThrustTableKey(top.Optional("thrust_table"), source_dir, &m);
    if (top.Has("forces")) ReadForces(top.Optional("forces"), &m);
    const MapValue measured(top.Required("measured"), "a map column: {topic, field}");
    for (const MapValue::Entry& e : measured.entries()) m.measured.push_back(ReadSignal(e));
    if (top.Has("clocks")) ReadClocks(top.Optional("clocks"), &m);
    CheckClockTopics(top, m);
    if (top.Has("csv_topics")) ReadCsvTopics(top, &m);
    CheckForceSource(top, m);
    return m;
  });
}

}  // namespace uuvplan::io::import
