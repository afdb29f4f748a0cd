#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>

#include "import/device_clock.h"
#include "import/import_map.h"
#include "import/trial_windows.h"
#include "uuvplan/io/import.h"
#include "uuvplan/io/new_directory.h"
#include "uuvplan/io/recording.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {
namespace import {
namespace {

namespace fs = std::filesystem;
using model::InputError;
using Window = std::array<double, 2>;

// `rostopic echo -p` exports: SOURCE itself when it holds the command topic's CSV, else each
// of its directories that does (one run each).
std::vector<std::string> CsvRunDirectories(const std::string& source, const ImportMap& m) {
  const std::string& file = m.csv_topics.at(m.command_topic);
  if (fs::is_regular_file(fs::path(source) / file)) return {DirectoryPath(source).string()};
  std::vector<std::string> runs;
  if (fs::is_directory(source)) {
    for (const fs::directory_entry& e : fs::directory_iterator(source)) {
      if (e.is_directory() && fs::is_regular_file(e.path() / file)) runs.push_back(e.path());
    }
  }
  std::sort(runs.begin(), runs.end());
  if (runs.empty()) {
    throw InputError(source, "expected a directory holding " + file + " (csv_topics of " +
                                 m.command_topic + "), or directories that do, found none");
  }
  return runs;
}

std::vector<std::string> RecordingFiles(const std::string& source, const ImportMap& m) {
  if (!m.csv_topics.empty()) return CsvRunDirectories(source, m);
  if (fs::is_regular_file(source)) return {source};
  if (!fs::is_directory(source)) {
    throw InputError(source,
                     "expected a recording (ROS bag or MCAP file) or a directory of them, got "
                     "no such file or directory");
  }
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(source)) {
    const std::string name = e.path().filename().string();
    const std::string ext = e.path().extension().string();
    const bool chosen = m.files.empty() ? ext == ".bag" || ext == ".mcap"
                                        : fnmatch(m.files.c_str(), name.c_str(), 0) == 0;
    if (chosen && e.is_regular_file()) files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    throw InputError(source, "expected recordings (" +
                                 (m.files.empty() ? "*.bag, *.mcap" : m.files) + "), found none");
  }
  return files;
}

std::string TrialIdOf(const std::string& file, const ImportMap& m) {
  const std::string stem = fs::path(file).stem().string();  // a run directory: its name
  if (m.trial_id.empty()) return stem;
  std::smatch match;
  if (!std::regex_search(stem, match, std::regex(m.trial_id)) || match[1].str().empty()) {
    throw InputError(m.file + ": trial_id", "expected a pattern that names the recording '" + stem +
                                                "' (its first group), got no match of '" +
                                                m.trial_id + "'");
  }
  return match[1].str();
}

struct Commands {
  std::vector<double> times;
  std::vector<std::vector<double>> values;  ///< per thruster: normalised command, or N
};

Commands ReadCommands(const Recording& r, const ImportMap& m) {
  std::vector<std::string> fields;
  for (const auto& thruster : m.thrusters) fields.push_back(thruster.second);
  Commands c;
  c.values = FieldValues(r, m.command_topic, fields, m.file + ": commands");
  c.times = r.topics.at(m.command_topic).times;
  if (c.times.empty()) {
    throw InputError(r.path,
                     "expected messages on the command topic " + m.command_topic + ", found none");
  }
  for (std::size_t k = 0; k < c.values.size(); ++k) {
    for (std::size_t i = 0; i < c.times.size(); ++i) {
      c.values[k][i] = m.Command(c.values[k][i]);
      const double u = c.values[k][i];
      const bool in_range = m.unit == CommandUnit::kNewton || std::abs(u) <= 1 + 1e-9;
      if (std::isfinite(u) && in_range) continue;
      const std::string where = r.path + ": topic " + m.command_topic + ": message " +
                                std::to_string(i + 1) + ": " + fields[k] + " (" + m.file +
                                ": commands.thrusters." + m.thrusters[k].first + ")";
      if (!std::isfinite(u)) throw InputError(where, "expected a number, got none");
      throw InputError(where,
                       "expected a command within [-1, 1] (u = (pwm - neutral)/full_scale "
                       "with the map's commands.neutral and full_scale), got " +
                           std::to_string(u));
    }
  }
  return c;
}

// The samples of one measured topic, on the recorder clock.
struct TopicSamples {
  std::string topic;
  std::vector<const MeasuredSignal*> signals;
  std::vector<double> times;
  std::vector<std::vector<double>> values;  ///< per signal, in uuvplan's units and axes
};

std::vector<double> SampleTimes(const Recording& r, const ImportMap& m, const std::string& topic,
                                const std::vector<double>& stamps) {
  const std::vector<double>& arrival = r.topics.at(topic).times;
  const auto clock = m.clocks.find(topic);
  if (clock == m.clocks.end()) return arrival;
  const std::string where = r.path + ": topic " + topic + ": " + clock->second.field;
  std::vector<double> device(stamps.size());
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    device[i] = stamps[i] * clock->second.scale;
    if (!std::isfinite(device[i])) {
      throw InputError(where, "expected a time stamp in every message, got none in message " +
                                  std::to_string(i + 1));
    }
  }
  if (!clock->second.align) return device;
  return OnRecorderClock(device, arrival, where);
}

// A logged value in uuvplan's units and axes; a heading turned from ENU back within (-π, π]
// (the trial reader unwraps headings logged within one turn).
double Converted(const MeasuredSignal& g, double logged) {
  const double x = (logged * g.scale + g.offset) * g.sign + g.turn;
  return g.turn != 0.0 ? std::remainder(x, 2 * M_PI) : x;
}

TopicSamples ReadTopic(const Recording& r, const ImportMap& m, const std::string& topic) {
  TopicSamples s{topic, {}, {}, {}};
  std::vector<std::string> fields;
  for (const MeasuredSignal& signal : m.measured) {
    if (signal.topic == topic) s.signals.push_back(&signal), fields.push_back(signal.field);
  }
  const auto clock = m.clocks.find(topic);
  if (clock != m.clocks.end()) fields.push_back(clock->second.field);
  std::vector<std::vector<double>> raw = FieldValues(r, topic, fields, m.file + ": measured");
  // In message order: RowsIn orders the samples of every topic by time together.
  s.times =
      SampleTimes(r, m, topic, clock != m.clocks.end() ? raw.back() : r.topics.at(topic).times);
  for (std::size_t j = 0; j < s.signals.size(); ++j) {
    const MeasuredSignal& g = *s.signals[j];
    if (std::none_of(raw[j].begin(), raw[j].end(), [](double x) { return std::isfinite(x); })) {
      throw InputError(m.file + ": measured." + g.column,
                       "expected a field with a number in some message of " + topic + " in " +
                           r.path + ", got none in field " + g.field +
                           " (an index past the array's end?)");
    }
    std::vector<double> column;
    for (double x : raw[j]) column.push_back(Converted(g, x));
    s.values.push_back(column);
  }
  return s;
}

std::vector<TopicSamples> ReadMeasured(const Recording& r, const ImportMap& m) {
  std::vector<TopicSamples> topics;
  for (const MeasuredSignal& signal : m.measured) {
    const bool seen = std::any_of(topics.begin(), topics.end(),
                                  [&](const TopicSamples& t) { return t.topic == signal.topic; });
    if (!seen) topics.push_back(ReadTopic(r, m, signal.topic));
  }
  return topics;
}

// Row times: every measured sample within the window (samples of several topics at one time
// share a row); per row, which sample of each topic it holds (-1: none).
struct Rows {
  std::vector<double> times;
  std::vector<std::vector<long>> sample;  ///< [topic][row]
};

Rows RowsIn(const Window& w, const std::vector<TopicSamples>& topics) {
  std::vector<std::tuple<double, std::size_t, std::size_t>> samples;
  for (std::size_t k = 0; k < topics.size(); ++k) {
    for (std::size_t i = 0; i < topics[k].times.size(); ++i) {
      const double t = topics[k].times[i];
      if (t >= w[0] && t <= w[1]) samples.emplace_back(t, k, i);
    }
  }
  std::sort(samples.begin(), samples.end());
  Rows rows;
  rows.sample.resize(topics.size());
  for (const auto& [t, k, i] : samples) {
    if (rows.times.empty() || t - rows.times.back() > 1e-9) {
      rows.times.push_back(t);
      for (auto& column : rows.sample) column.push_back(-1);
    }
    rows.sample[k].back() = long(i);
  }
  return rows;
}

// Force (N or N·m) of `dof` from the commands of message `i`: Σ arm · thrust (the map's forces).
double ForceAt(const ImportMap& m, const Commands& c, model::Dof dof, std::size_t i) {
  double force = 0.0;
  for (std::size_t k = 0; k < m.thrusters.size(); ++k) {
    const auto& arms = m.forces.at(dof);
    const auto arm = arms.find(m.thrusters[k].first);
    if (arm != arms.end()) force += arm->second * m.Thrust(c.values[k][i]);
  }
  return force;
}

// The command u ∈ [-1, 1] in a thruster's own units: 0 at its neutral, ±1 at the ends of its
// command range (a PWM range gives back the µs).
double VehicleCommand(const model::Thruster& t, double u) {
  return t.neutral + u * (u >= 0 ? t.command_max - t.neutral : t.neutral - t.command_min);
}

void AddCommandColumns(const ImportMap& m, const Commands& c, const Rows& rows,
                       const model::Vehicle& vehicle, model::TrialLog* log) {
  std::vector<std::size_t> held(rows.times.size());  // the last command message at or before
  std::size_t j = 0;
  for (std::size_t r = 0; r < rows.times.size(); ++r) {
    while (j + 1 < c.times.size() && c.times[j + 1] <= rows.times[r]) ++j;
    held[r] = j;
  }
  for (const auto& [dof, arms] : m.forces) {
    auto& column = log->force[model::Index(dof)];
    for (std::size_t i : held) column.push_back(ForceAt(m, c, dof, i));
  }
  if (m.WritesForces()) return;
  for (std::size_t k = 0; k < m.thrusters.size(); ++k) {
    const std::string& name = m.thrusters[k].first;
    const model::Thruster& thruster = vehicle.thrusters[std::size_t(vehicle.ThrusterIndex(name))];
    auto& column = log->commands[name];
    for (std::size_t i : held) column.push_back(VehicleCommand(thruster, c.values[k][i]));
  }
}

model::TrialLog TrialLogIn(const Window& w, const Commands& c,
                           const std::vector<TopicSamples>& topics, const ImportMap& m,
                           const model::Vehicle& vehicle) {
  const Rows rows = RowsIn(w, topics);
  model::TrialLog log;
  for (double t : rows.times) log.t.push_back(t - w[0]);
  for (std::size_t k = 0; k < topics.size(); ++k) {
    for (std::size_t j = 0; j < topics[k].signals.size(); ++j) {
      const MeasuredSignal& g = *topics[k].signals[j];
      auto& column = (g.position ? log.position : log.velocity)[model::Index(g.dof)];
      for (long i : rows.sample[k]) column.push_back(i < 0 ? NAN : topics[k].values[j][i]);
    }
  }
  AddCommandColumns(m, c, rows, vehicle, &log);
  return log;
}

std::string UtcText(double unix_s) {
  const long long ms = std::llround(unix_s * 1000.0);
  const std::time_t whole = std::time_t(ms / 1000);
  std::tm utc{};
  gmtime_r(&whole, &utc);
  char text[48];
  const std::size_t n = std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  std::snprintf(text + n, sizeof text - n, ".%03lldZ", ms % 1000);
  return text;
}

// How the force or command columns were made, for the log's header.
std::string CommandNote(const ImportMap& m, const Recording& r) {
  std::ostringstream s;
  s << "commands: " << m.command_topic << " (" << r.topics.at(m.command_topic).type << "):";
  for (const auto& [name, field] : m.thrusters) s << " " << name << " = " << field;
  if (m.unit == CommandUnit::kPwmMicroseconds) {
    s << "; PWM us -> u = (pwm - " << model::ShortestNumber(m.neutral) << ")/"
      << model::ShortestNumber(m.full_scale);
  }
  s << "; held from the last command message\n";
  for (const auto& [dof, arms] : m.forces) {
    s << "force_" << model::DofName(dof) << " =";
    for (const auto& [name, arm] : arms)
      s << " " << (arm < 0 ? "- " : "+ ") << model::ShortestNumber(std::abs(arm)) << "*" << name;
    s << (m.thrust_table_file.empty() ? " (thrust as logged, N)"
                                      : " (thrust in N from the table " + m.thrust_table_file + ")")
      << "\n";
  }
  if (!m.WritesForces()) {
    s << "cmd_<thruster>: u in the vehicle's command units (its neutral at 0, its range's ends at "
         "+-1); the vehicle's thrust model makes the force\n";
  }
  return s.str();
}

std::string SignalNote(const ImportMap& m, const MeasuredSignal& g) {
  std::ostringstream s;
  s << g.column << ": " << g.topic << " " << g.field;
  if (g.scale != 1.0) s << " * " << model::ShortestNumber(g.scale);
  if (g.offset != 0.0) s << " + " << model::ShortestNumber(g.offset);
  s << " (" << g.frame << (g.sign < 0 ? ", sign flipped to NED/FRD" : "")
    << (g.turn != 0.0 ? ", heading pi/2 - psi" : "") << ")";
  const auto clock = m.clocks.find(g.topic);
  if (clock != m.clocks.end()) {
    s << "; time from " << clock->second.field << " * "
      << model::ShortestNumber(clock->second.scale) << " s"
      << (clock->second.align ? ", mapped onto the recorder clock (line through the earliest "
                                "arrivals)"
                              : "");
  }
  return s.str() + "\n";
}

std::string TrialComment(const ImportMap& m, const Recording& r, const Window& w,
                         const model::TrialLog& log) {
  std::ostringstream s;
  s << "imported by uuvplan import from " << r.path << " (" << r.format << "), map " << m.file
    << "\n";
  const double epoch = double(r.epoch_s);
  s << "t = 0 at " << UtcText(epoch + w[0]) << " (recorder clock, unix "
    << model::Decimals(epoch + w[0], 3) << "); " << model::Decimals(w[1] - w[0], 2) << " s, "
    << log.size() << " rows\n";
  s << CommandNote(m, r);
  for (const MeasuredSignal& g : m.measured) s << SignalNote(m, g);
  std::string text = s.str();
  text.pop_back();
  return text;
}

// The map's ranges of recording `id`, each within the span of its commands.
std::vector<Window> RangeWindows(const ImportMap& m, const Commands& c, const std::string& id) {
  const auto ranges = m.ranges.find(id);
  if (ranges == m.ranges.end()) {
    throw InputError(m.file + ": ranges",
                     "expected the ranges of every recording, got none for " + id);
  }
  const double span = c.times.back() - c.times.front();
  std::vector<Window> windows;
  for (const auto& range : ranges->second) {
    if (range[1] > span + 1e-6) {
      throw InputError(m.file + ": ranges." + id,
                       "expected ranges within the commands' span [0, " + std::to_string(span) +
                           "] s, got one ending at " + std::to_string(range[1]) + " s");
    }
    windows.push_back({c.times.front() + range[0], c.times.front() + range[1]});
  }
  return windows;
}

std::vector<Window> WindowsOf(const ImportMap& m, const Commands& c, const std::string& id) {
  switch (m.cut) {
    case Cut::kFile:
      return WholeWindow(c.times);
    case Cut::kActivity:
      return ActivityWindows(c.times, c.values, m.quiet_s);
    case Cut::kRanges:
      return RangeWindows(m, c, id);
  }
  return {};
}

std::vector<std::string> WantedTopics(const ImportMap& m) {
  std::vector<std::string> topics{m.command_topic};
  for (const MeasuredSignal& g : m.measured) topics.push_back(g.topic);
  return topics;
}

struct Imported {
  model::TrialEntry entry;
  std::string comment;
  ImportedTrial summary;
  double start = 0.0;  ///< recorder time of t = 0
};

void ImportRecording(const std::string& path, const ImportMap& m, const model::Vehicle& vehicle,
                     std::vector<Imported>* out) {
  const Recording r = m.csv_topics.empty() ? ReadRecording(path, WantedTopics(m))
                                           : ReadTopicCsvs(path, m.csv_topics);
  const Commands c = ReadCommands(r, m);
  const std::vector<TopicSamples> topics = ReadMeasured(r, m);
  const std::string id = TrialIdOf(path, m);
  const std::vector<Window> windows = WindowsOf(m, c, id);
  for (std::size_t k = 0; k < windows.size(); ++k) {
    Imported t;
    t.entry.log = TrialLogIn(windows[k], c, topics, m, vehicle);
    if (t.entry.log.size() < 2) {
      throw InputError(
          path, "expected measured samples between " + UtcText(double(r.epoch_s) + windows[k][0]) +
                    " and " + UtcText(double(r.epoch_s) + windows[k][1]) +
                    " (a trial's commands), found " + std::to_string(t.entry.log.size()));
    }
    const std::string trial = windows.size() == 1 ? id : id + "_" + std::to_string(k + 1);
    t.entry.file = "trials/" + trial + ".csv";
    t.entry.dof = m.dof;
    t.entry.mapping = m.mapping;
    const auto use = m.use.find(trial);
    t.entry.use = use == m.use.end() ? model::TrialUse::kFit : use->second;
    t.start = double(r.epoch_s) + windows[k][0];
    t.comment = TrialComment(m, r, windows[k], t.entry.log);
    const double span = t.entry.log.t.back() - t.entry.log.t.front();
    t.summary = {path, span, double(t.entry.log.size() - 1) / span};
    out->push_back(std::move(t));
  }
}

void CheckVehicle(const ImportMap& m, const model::Vehicle& v, const std::string& vehicle_file) {
  const int mapping = v.MappingIndex(m.mapping);
  if (mapping < 0 || v.mappings[std::size_t(mapping)].dof != m.dof) {
    throw InputError(m.file + ": mapping", "expected a " + std::string(model::DofName(m.dof)) +
                                               " mapping of " + vehicle_file + ", got '" +
                                               m.mapping + "'");
  }
  if (m.WritesForces()) return;
  for (const auto& thruster : m.thrusters) {
    if (v.ThrusterIndex(thruster.first) >= 0) continue;
    throw InputError(
        m.file + ": commands.thrusters." + thruster.first,
        "expected a thruster of " + vehicle_file + " (cmd_ columns need the vehicle's)");
  }
  for (const model::Thruster& t : v.thrusters) {  // a log of commands holds every thruster's
    const bool named = std::any_of(m.thrusters.begin(), m.thrusters.end(),
                                   [&](const auto& x) { return x.first == t.name; });
    if (!named) {
      throw InputError(m.file + ": commands.thrusters",
                       "expected a field for every thruster of " + vehicle_file +
                           " (cmd_ columns), got none for " + t.name +
                           " (a thruster at rest still has its command logged)");
    }
  }
}

// Every trial the map's `use` names is one of the trials imported.
void CheckUses(const ImportMap& m, const std::vector<Imported>& trials) {
  std::string ids;
  for (const Imported& t : trials)
    ids += (ids.empty() ? "" : ", ") + fs::path(t.entry.file).stem().string();
  for (const auto& named : m.use) {
    const std::string& id = named.first;
    const bool found = std::any_of(trials.begin(), trials.end(), [&](const Imported& t) {
      return t.entry.file == "trials/" + id + ".csv";
    });
    if (!found)
      throw InputError(m.file + ": use." + id, "expected a trial of the import (" + ids + ")");
  }
}

// Every recording the map's `ranges` names is one being imported.
void CheckRangesNameRecordings(const ImportMap& m, const std::vector<std::string>& recordings) {
  std::set<std::string> ids;
  for (const std::string& path : recordings) ids.insert(TrialIdOf(path, m));
  for (const auto& named : m.ranges) {
    if (ids.count(named.first)) continue;
    std::string list;
    for (const std::string& id : ids) list += (list.empty() ? "" : ", ") + id;
    throw InputError(m.file + ": ranges." + named.first,
                     "expected a recording being imported (" + list + ")");
  }
}

ImportedCampaign Import(const std::string& source, const std::string& map_file,
                        const std::string& vehicle_file) {
  const std::string source_dir =
      fs::is_directory(source) ? source : fs::path(source).parent_path().string();
  const ImportMap m =
      ReadImportMap(map_file, source_dir.empty() ? "." : source_dir, vehicle_file.empty());
  const std::string vehicle_path = vehicle_file.empty() ? m.vehicle : vehicle_file;
  if (vehicle_path.empty()) {
    throw InputError(map_file, "expected a vehicle: the map's 'vehicle' key or --vehicle");
  }
  ImportedCampaign out;
  out.campaign.vehicle = ReadVehicle(vehicle_path);
  out.campaign.vehicle_file = vehicle_path;
  CheckVehicle(m, out.campaign.vehicle, vehicle_path);
  std::vector<Imported> trials;
  const std::vector<std::string> recordings = RecordingFiles(source, m);
  CheckRangesNameRecordings(m, recordings);
  for (const std::string& path : recordings)
    ImportRecording(path, m, out.campaign.vehicle, &trials);
  std::stable_sort(trials.begin(), trials.end(),
                   [](const Imported& a, const Imported& b) { return a.start < b.start; });
  CheckUses(m, trials);
  for (Imported& t : trials) {
    for (const model::TrialEntry& e : out.campaign.trials) {
      if (e.file == t.entry.file) {
        throw InputError(map_file + ": trial_id", "expected one trial per name, got two " + e.file +
                                                      " (from " + t.summary.recording + ")");
      }
    }
    t.entry.start = t.start - trials.front().start;
    t.entry.has_start = true;
    out.campaign.trials.push_back(std::move(t.entry));
    out.comments.push_back(t.comment);
    out.trials.push_back(t.summary);
  }
  return out;
}

}  // namespace
}  // namespace import

ImportedCampaign ImportRecordings(const std::string& source, const std::string& map_file,
                                  const std::string& vehicle_file) {
  return import::Import(source, map_file, vehicle_file);
}

}  // namespace uuvplan::io
