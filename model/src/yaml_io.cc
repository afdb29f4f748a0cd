// Readers of the YAML files of the contract (vehicle, pool, truth, campaign) and the campaign
// writer. Every reader checks the whole file against docs/formats.md and reports the first
// fault as an InputError "<file>:<line>: <key.path>: expected <what>, got <value>"; no
// yaml-cpp exception leaves this file. A key that is present must hold a valid value (an
// empty value is not taken as "use the default"), unknown and repeated keys are errors.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/io.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::model {

namespace {

namespace fs = std::filesystem;

std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string DofList() {
  std::vector<std::string> names;
  for (Dof d : kAllDofs) names.emplace_back(DofName(d));
  return Join(names);
}

// A whole scalar as a finite number (YAML's .nan and .inf are refused: no parameter of the
// contract may be infinite or undefined).
bool ParseNumber(std::string_view text, double* value) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return false;
  }
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, *value);
  return !text.empty() && ec == std::errc() && end == last && std::isfinite(*value);
}

// The shortest text that reads back as exactly `x`.
std::string FormatNumber(double x) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, end);
}

// ---------------------------------------------------------------------------------------------
// Values with their place in the file.

// A YAML value and where it sits: its file, its key path (e.g. `thrusters[1].thrust.c_pos`)
// and the 1-based line to report (a missing key is reported at its parent; 0 = no line).
class Value {
 public:
  Value(YAML::Node node, std::string key_path, const std::string& file, int line)
      : node_(std::move(node)), key_path_(std::move(key_path)), file_(&file), line_(line) {}

  const YAML::Node& node() const { return node_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& file() const { return *file_; }
  int line() const { return line_; }
  /// The key is not in the file at all (an empty value is present, and "nothing").
  bool absent() const { return !node_.IsDefined(); }

  /// A value inside this one.
  Value Child(const YAML::Node& node, std::string key_path, int line) const {
    return Value(node, std::move(key_path), *file_, line);
  }

  [[noreturn]] void Fail(const std::string& what) const {
    const std::string where = line_ > 0 ? *file_ + ":" + std::to_string(line_) : *file_;
    throw InputError(where, key_path_.empty() ? what : key_path_ + ": " + what);
  }
  [[noreturn]] void Expected(const std::string& expectation) const {
    Fail("expected " + expectation + ", got " + Describe());
  }

  /// What the file holds here, for "got ...": 'text', [1, 2], a map, a list, nothing.
  std::string Describe() const {
    if (!node_.IsDefined() || node_.IsNull()) return "nothing";
    if (node_.IsScalar()) return "'" + Shorten(node_.Scalar()) + "'";
    if (node_.IsMap()) return "a map";
    std::vector<std::string> items;
    for (const YAML::Node& item : node_) {
      if (!item.IsScalar() || items.size() == 4) return "a list";
      items.push_back(item.Scalar());
    }
    return "[" + Join(items) + "]";
  }

 private:
  static std::string Shorten(const std::string& s) {
    constexpr std::size_t kMax = 60;
    return s.size() <= kMax ? s : s.substr(0, kMax) + "...";
  }

  YAML::Node node_;
  std::string key_path_;
  const std::string* file_;
  int line_;
};

int LineOf(const YAML::Node& node, int fallback) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? fallback : mark.line + 1;  // yaml-cpp counts lines from 0
}

std::string Where(const std::string& file, const YAML::Mark& mark) {
  return mark.is_null() ? file : file + ":" + std::to_string(mark.line + 1);
}

std::string ChildPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

// A YAML map whose keys are distinct names. Values of keys are reported at the key's line.
class MapValue {
 public:
  struct Entry {
    std::string key;
    Value key_value;  ///< for faults of the key itself (reported with the parent's path)
    Value value;
  };

  MapValue(const Value& v, const std::string& what) : self_(v) {
    if (!v.node().IsMap()) v.Expected(what);
    for (auto it = v.node().begin(); it != v.node().end(); ++it) {
      const int line = LineOf(it->first, v.line());
      Value key_value = v.Child(it->first, v.key_path(), line);
      if (!it->first.IsScalar()) {
        key_value.Fail("expected names as keys, got " + key_value.Describe());
      }
      const std::string& key = it->first.Scalar();
      for (const Entry& e : entries_) {
        if (e.key == key) {
          key_value.Fail("key '" + key + "' appears twice (also at line " +
                         std::to_string(e.key_value.line()) + ")");
        }
      }
      entries_.push_back({key, key_value, v.Child(it->second, ChildPath(v.key_path(), key), line)});
    }
  }

  /// Every key must be one of `allowed`.
  void AllowOnly(std::initializer_list<std::string_view> allowed) const {
    AllowOnly(std::vector<std::string_view>(allowed));
  }
  void AllowOnly(const std::vector<std::string_view>& allowed) const {
    for (const Entry& e : entries_) {
      if (std::find(allowed.begin(), allowed.end(), e.key) != allowed.end()) continue;
      std::vector<std::string> names(allowed.begin(), allowed.end());
      e.key_value.Fail("unknown key '" + e.key + "' (allowed: " + Join(names) + ")");
    }
  }


  /// The value of `key`; absent() when the map does not have it.
  Value Optional(std::string_view key) const {
    for (const Entry& e : entries_) {
      if (e.key == key) return e.value;
    }
    return self_.Child(YAML::Node(YAML::NodeType::Undefined),
                       ChildPath(self_.key_path(), std::string(key)), self_.line());
  }

  Value Required(std::string_view key) const {
    Value v = Optional(key);
    if (v.absent()) self_.Fail("missing required key '" + std::string(key) + "'");
    return v;
  }

  bool Has(std::string_view key) const { return !Optional(key).absent(); }
  const std::vector<Entry>& entries() const { return entries_; }
  const Value& self() const { return self_; }

 private:
  Value self_;
  std::vector<Entry> entries_;
};

// ---------------------------------------------------------------------------------------------
// Scalars and lists.

template <typename Accept>
double NumberIf(const Value& v, const std::string& expectation, Accept accept) {
  double x = 0.0;
  if (!v.node().IsScalar() || !ParseNumber(v.node().Scalar(), &x) || !accept(x)) {
    v.Expected(expectation);
  }
  return x;
}

double AnyNumber(const Value& v) {
  return NumberIf(v, "a number", [](double) { return true; });
}
double Positive(const Value& v) {
  return NumberIf(v, "a positive number", [](double x) { return x > 0; });
}
double NonNegative(const Value& v) {
  return NumberIf(v, "a number >= 0", [](double x) { return x >= 0; });
}
double Probability(const Value& v) {
  return NumberIf(v, "a probability in [0, 1)", [](double x) { return x >= 0 && x < 1; });
}

int WholeNonNegative(const Value& v) {
  int n = -1;
  if (v.node().IsScalar()) {
    const std::string& s = v.node().Scalar();
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec != std::errc() || end != s.data() + s.size()) n = -1;
  }
  if (n < 0) v.Expected("a whole number >= 0");
  return n;
}

std::string Name(const Value& v, const std::string& expectation = "a name") {
  if (!v.node().IsScalar() || v.node().Scalar().empty()) v.Expected(expectation);
  return v.node().Scalar();
}

// One of `choices`; returns its index.
int Choice(const Value& v, std::initializer_list<std::string_view> choices,
           const std::string& what) {
  std::vector<std::string> names(choices.begin(), choices.end());
  if (v.node().IsScalar()) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == v.node().Scalar()) return static_cast<int>(i);
    }
  }
  v.Expected(what + " (" + Join(names) + ")");
}

Dof DofValue(const Value& v) {
  if (v.node().IsScalar()) {
    if (auto dof = ParseDof(v.node().Scalar())) return *dof;
  }
  v.Expected("a DOF (" + DofList() + ")");
}

std::vector<Value> List(const Value& v, const std::string& expectation) {
  if (!v.node().IsSequence()) v.Expected(expectation);
  std::vector<Value> items;
  for (std::size_t i = 0; i < v.node().size(); ++i) {
    const YAML::Node item = v.node()[i];
    items.push_back(
        v.Child(item, v.key_path() + "[" + std::to_string(i) + "]", LineOf(item, v.line())));
  }
  return items;
}

// [lo, hi] of two numbers.
std::array<double, 2> Pair(const Value& v, const std::string& expectation) {
  const std::vector<Value> items = List(v, expectation);
  if (items.size() != 2) v.Expected(expectation);
  return {AnyNumber(items[0]), AnyNumber(items[1])};
}

// Added-mass bounds are fractions of the rigid-body value: 0 <= lo <= hi.
std::array<double, 2> AddedMassBounds(const Value& v) {
  const std::string expectation = "[lo, hi] with 0 <= lo <= hi (fractions of the rigid-body value)";
  const auto b = Pair(v, expectation);
  if (!(b[0] >= 0 && b[0] <= b[1])) v.Expected(expectation);
  return b;
}

// ---------------------------------------------------------------------------------------------
// Files.

// Why `path` cannot be read as a file, or "" if it can.
std::string UnreadableReason(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return "it is a directory";
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return std::strerror(errno);
  std::fclose(file);
  return "";
}

// A file's top-level map; `what` describes the expected content for an empty file.
YAML::Node LoadYaml(const std::string& file, const std::string& what) {
  if (const std::string reason = UnreadableReason(file); !reason.empty()) {
    throw InputError(file, "cannot open file: " + reason);
  }
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    throw InputError(Where(file, e.mark), "not valid YAML: " + e.msg);
  }
  if (root.IsNull()) throw InputError(file, "empty file: expected " + what);
  return root;
}

// Runs a reader of `file`, turning any exception other than InputError into one that names
// the file: a reader never lets a yaml-cpp or library exception escape.
template <typename Read>
auto Guarded(const std::string& file, Read read) -> decltype(read()) {
  try {
    return read();
  } catch (const InputError&) {
    throw;
  } catch (const YAML::Exception& e) {
    throw InputError(Where(file, e.mark), e.msg);
  } catch (const std::exception& e) {
    throw InputError(file, std::string("cannot read: ") + e.what());
  }
}

// `file` as written in `base_file`, relative to the directory of `base_file`.
std::string Resolve(const std::string& base_file, const std::string& file) {
  const fs::path p(file);
  if (p.is_absolute()) return file;
  return (fs::path(base_file).parent_path() / p).lexically_normal().string();
}

// A file named at `v` (relative to v's file), which must be readable; returns its path.
std::string ReadableFile(const Value& v) {
  const std::string written = Name(v, "a file name");
  const std::string path = Resolve(v.file(), written);
  if (const std::string reason = UnreadableReason(path); !reason.empty()) {
    v.Fail("cannot open '" + path + "': " + reason);
  }
  return path;
}

// ---------------------------------------------------------------------------------------------
// Vehicle.

ThrustModel ParseThrust(const Value& v) {
  const MapValue m(v, "a map {model: square, c_pos, c_neg} or {model: poly2, a, b}");
  ThrustModel model;
  const Value kind = m.Required("model");
  if (Choice(kind, {"square", "poly2"}, "a thrust model") == 0) {
    // seed 000 eq. 6: tau = c·V|V|, c by sign of V.
    m.AllowOnly({"model", "c_pos", "c_neg", "deduction"});
    model.kind = ThrustModel::Kind::kSquare;
    model.c_pos = Positive(m.Required("c_pos"));
    model.c_neg = Positive(m.Required("c_neg"));
  } else {
    // seed 002 eq. 1: tau = a·V² + b·V for V >= 0, which must grow to give thrust at all.
    m.AllowOnly({"model", "a", "b", "deduction"});
    model.kind = ThrustModel::Kind::kPoly2;
    model.a = NonNegative(m.Required("a"));
    model.b = AnyNumber(m.Required("b"));
    if (!(model.a > 0 || model.b > 0)) {
      v.Fail("poly2 thrust must grow with the command: expected a > 0 or b > 0");
    }
  }
  if (const Value d = m.Optional("deduction"); !d.absent()) {
    model.deduction =
        NumberIf(d, "a thrust deduction in [0, 1)", [](double t) { return t >= 0 && t < 1; });
  }
  return model;
}

Thruster ParseThruster(const Value& v, const std::vector<Thruster>& previous) {
  const MapValue m(v, "a thruster {name, thrust, command}");
  m.AllowOnly({"name", "thrust", "command"});
  Thruster t;
  const Value name = m.Required("name");
  t.name = Name(name, "a thruster name");
  for (const Thruster& p : previous) {
    if (p.name == t.name) name.Fail("thruster '" + t.name + "' is defined twice");
  }
  t.model = ParseThrust(m.Required("thrust"));
  const Value command = m.Required("command");
  const std::string expectation = "a command range [lo, hi] with lo < hi";
  const auto range = Pair(command, expectation);
  if (!(range[0] < range[1])) command.Expected(expectation);
  t.command_min = range[0];
  t.command_max = range[1];
  return t;
}

std::vector<Thruster> ParseThrusters(const Value& v) {
  const std::string expectation = "a list of at least one thruster {name, thrust, command}";
  std::vector<Thruster> thrusters;
  for (const Value& item : List(v, expectation)) {
    thrusters.push_back(ParseThruster(item, thrusters));
  }
  if (thrusters.empty()) v.Expected(expectation);
  return thrusters;
}

std::vector<std::string> ThrusterNames(const std::vector<Thruster>& thrusters) {
  std::vector<std::string> names;
  for (const Thruster& t : thrusters) names.push_back(t.name);
  return names;
}

// shares: {thruster: share}, tau_i = share_i·phi (seed 000 Table I).
std::vector<std::pair<int, double>> ParseShares(const Value& v,
                                                const std::vector<Thruster>& thrusters) {
  const MapValue m(v, "a map {thruster: share}");
  std::vector<std::pair<int, double>> shares;
  for (const MapValue::Entry& e : m.entries()) {
    int index = -1;
    for (std::size_t i = 0; i < thrusters.size(); ++i) {
      if (thrusters[i].name == e.key) index = static_cast<int>(i);
    }
    if (index < 0) {
      e.key_value.Fail("unknown thruster '" + e.key +
                       "' (thrusters: " + Join(ThrusterNames(thrusters)) + ")");
    }
    shares.emplace_back(index,
                        NumberIf(e.value, "a non-zero share (thruster force per unit DOF force)",
                                 [](double s) { return s != 0; }));
  }
  if (shares.empty()) v.Expected("at least one thruster share");
  return shares;
}

ThrustMapping ParseMapping(const std::string& name, const Value& v,
                           const std::vector<Thruster>& thrusters) {
  const MapValue m(v, "a mapping {dof, shares, open_water}");
  m.AllowOnly({"dof", "shares", "open_water"});
  ThrustMapping mapping;
  mapping.name = name;
  mapping.dof = DofValue(m.Required("dof"));
  mapping.shares = ParseShares(m.Required("shares"), thrusters);
  if (const Value ow = m.Optional("open_water"); !ow.absent()) {
    constexpr OpenWater kValues[] = {OpenWater::kPositive, OpenWater::kNegative, OpenWater::kBoth,
                                     OpenWater::kNone};
    mapping.open_water = kValues[Choice(ow, {"positive", "negative", "both", "none"},
                                        "the direction of open-water thrust")];
  }
  return mapping;
}

std::vector<ThrustMapping> ParseMappings(const Value& v, const std::vector<Thruster>& thrusters) {
  const MapValue m(v, "a map of mappings {<name>: {dof, shares, open_water}}");
  std::vector<ThrustMapping> mappings;
  for (const MapValue::Entry& e : m.entries()) {
    mappings.push_back(ParseMapping(e.key, e.value, thrusters));
  }
  if (mappings.empty()) v.Expected("at least one mapping");
  return mappings;
}

// A key of a per-DOF map must be a DOF name.
Dof DofKey(const MapValue::Entry& e) { return DofValue(e.key_value); }

std::map<Dof, double> ParseInertia(const Value& v) {
  const MapValue m(v, "a map {<rotational DOF>: kg·m²}");
  std::map<Dof, double> inertia;
  for (const MapValue::Entry& e : m.entries()) {
    const Dof dof = DofKey(e);
    if (!IsRotational(dof)) {
      e.key_value.Fail("inertia is given for rotational DOFs only (roll, pitch, yaw), got '" +
                       e.key + "' (the inertia of a translation is the mass)");
    }
    inertia[dof] = Positive(e.value);
  }
  return inertia;
}

DragPrior ParseDrag(const Value& v) {
  const MapValue m(v, "a drag prior {k, kq, rel_sigma}");
  m.AllowOnly({"k", "kq", "rel_sigma"});
  DragPrior drag;
  drag.k = NonNegative(m.Required("k"));
  drag.kq = NonNegative(m.Required("kq"));
  if (const Value s = m.Optional("rel_sigma"); !s.absent()) drag.rel_sigma = Positive(s);
  return drag;
}

// dofs.<dof> of a vehicle: a priori drag and added mass. A truth file adds params and effects
// (read by ParseTruthDof).
DofPrior ParsePrior(const Value& v, bool truth) {
  const MapValue m(v, "a map {drag, added_mass}");
  if (truth) {
    m.AllowOnly({"drag", "added_mass", "params", "effects"});
  } else {
    m.AllowOnly({"drag", "added_mass"});
  }
  DofPrior prior;
  if (const Value d = m.Optional("drag"); !d.absent()) prior.drag = ParseDrag(d);
  if (const Value a = m.Optional("added_mass"); !a.absent()) prior.added_mass = AddedMassBounds(a);
  return prior;
}

SensorSpec ParseSensorSpec(const Value& v) {
  const MapValue m(v, "a sensor {rate, sigma}");
  m.AllowOnly({"rate", "sigma"});
  SensorSpec spec;
  spec.rate_hz = Positive(m.Required("rate"));
  spec.sigma = Positive(m.Required("sigma"));
  return spec;
}

DofSensors ParseDofSensors(const Value& v) {
  const MapValue m(v, "a map {position: {rate, sigma}, velocity: {rate, sigma}}");
  m.AllowOnly({"position", "velocity"});
  DofSensors sensors;
  if (const Value p = m.Optional("position"); !p.absent()) sensors.position = ParseSensorSpec(p);
  if (const Value s = m.Optional("velocity"); !s.absent()) sensors.velocity = ParseSensorSpec(s);
  if (!sensors.position && !sensors.velocity) v.Expected("a position and/or a velocity sensor");
  return sensors;
}

// The vehicle keys of `root`; a truth file may also have virtual_pool (read by ReadTruth).
Vehicle ParseVehicle(const MapValue& root, bool truth) {
  if (truth) {
    root.AllowOnly({"name", "mass", "size", "inertia", "added_mass", "thrusters", "min_thrust",
                    "mappings", "dofs", "sensors", "virtual_pool"});
  } else {
    root.AllowOnly({"name", "mass", "size", "inertia", "added_mass", "thrusters", "min_thrust",
                    "mappings", "dofs", "sensors"});
  }
  Vehicle vehicle;
  vehicle.name = Name(root.Required("name"), "a vehicle name");
  vehicle.mass = Positive(root.Required("mass"));
  const Value size = root.Required("size");
  const std::vector<Value> sides = List(size, "[length, width, height] in m");
  if (sides.size() != 3) size.Expected("[length, width, height] in m");
  for (int i = 0; i < 3; ++i) vehicle.size[i] = Positive(sides[i]);
  if (const Value v = root.Optional("inertia"); !v.absent()) vehicle.inertia = ParseInertia(v);
  if (const Value v = root.Optional("added_mass"); !v.absent()) {
    vehicle.added_mass = AddedMassBounds(v);
  }
  vehicle.thrusters = ParseThrusters(root.Required("thrusters"));
  if (const Value v = root.Optional("min_thrust"); !v.absent()) vehicle.min_thrust = NonNegative(v);
  vehicle.mappings = ParseMappings(root.Required("mappings"), vehicle.thrusters);
  if (const Value v = root.Optional("dofs"); !v.absent()) {
    const MapValue priors(v, "a map {<dof>: {drag, added_mass}}");
    for (const MapValue::Entry& e : priors.entries()) {
      vehicle.priors[DofKey(e)] = ParsePrior(e.value, truth);
    }
  }
  if (const Value v = root.Optional("sensors"); !v.absent()) {
    const MapValue sensors(v, "a map {<dof>: {position, velocity}}");
    for (const MapValue::Entry& e : sensors.entries()) {
      vehicle.sensors[DofKey(e)] = ParseDofSensors(e.value);
    }
  }
  return vehicle;
}

// ---------------------------------------------------------------------------------------------
// Truth.

void SetParam(DofTruth* truth, const std::string& name, double value, const Value& where) {
  if (!truth->params.emplace(name, value).second) {
    where.Fail("parameter '" + name + "' is given twice");
  }
}

// A qualified family's map in a truth file, {<qualifier>: value} (e.g. eta:
// {<mapping>.<pos|neg>: v}, seed 000 eq. 3), each qualifier and value checked by the family.
void ParseQualified(const ParameterFamily& family, const Value& v, Dof dof, const Vehicle& vehicle,
                    DofTruth* truth) {
  const MapValue m(v, "a map {<" + std::string(family.meaning) + ">: value}");
  for (const MapValue::Entry& e : m.entries()) {
    const std::string problem = family.check_qualifier(e.key, dof, vehicle);
    if (!problem.empty()) e.key_value.Expected(problem);
    const double x = NumberIf(e.value, family.Expected(),
                              [&family](double y) { return family.Admissible(y); });
    SetParam(truth, std::string(family.name) + e.key, x, e.value);
  }
  if (m.entries().empty()) v.Expected("at least one entry");
}

// params: the true standard-model parameters of the DOF. m is required; k, kq, bias and
// bias_step default to 0 (eta to 1, i.e. not listed).
void ParseParams(const Value& v, Dof dof, const Vehicle& vehicle, DofTruth* truth) {
  const MapValue m(v, "a map {m, k, kq, bias, bias_step, eta}");
  m.AllowOnly({"m", "k", "kq", "bias", "bias_step", "eta"});
  truth->params[param::kMass] = Positive(m.Required("m"));
  const auto optional = [&m](const char* key, double (*read)(const Value&)) {
    const Value x = m.Optional(key);
    return x.absent() ? 0.0 : read(x);
  };
  truth->params[param::kLinearDrag] = optional("k", NonNegative);
  truth->params[param::kQuadraticDrag] = optional("kq", NonNegative);
  truth->params[param::kBias] = optional("bias", AnyNumber);
  truth->params[param::kBiasStep] = optional("bias_step", AnyNumber);
  if (const Value eta = m.Optional("eta"); !eta.absent()) {
    ParseQualified(*FamilyNamed(param::kEtaPrefix), eta, dof, vehicle, truth);
  }
}

// coupling's `motion: {<dof>: {offset, amplitude, omega}}`: the other DOFs' velocities that
// drive a term reading them, in the virtual pool (truth.h AuxMotion).
void ParseOtherMotion(const Value& motion, Dof dof, DofTruth* truth) {
  const MapValue motions(motion, "a map {<dof>: {offset, amplitude, omega}}");
  for (const MapValue::Entry& e : motions.entries()) {
    const Dof other = DofKey(e);
    if (other == dof) {
      e.key_value.Fail("motion of '" + e.key +
                       "' itself comes from the simulation; expected another DOF");
    }
    const MapValue s(e.value, "a velocity {offset, amplitude, omega}");
    s.AllowOnly({"offset", "amplitude", "omega"});
    AuxMotion aux;
    if (const Value x = s.Optional("offset"); !x.absent()) aux.offset = AnyNumber(x);
    if (const Value x = s.Optional("amplitude"); !x.absent()) aux.amplitude = AnyNumber(x);
    if (const Value x = s.Optional("omega"); !x.absent()) aux.omega = NonNegative(x);
    truth->aux_motion[VelocityLetter(other)] = aux;
  }
}

// The keys an effect's settings may hold: its parameters (a qualified family by its file
// key), its settings, and `motion` where its terms read other DOFs.
std::vector<std::string> SettingKeys(const EffectEntry& effect) {
  std::vector<std::string> keys;
  for (const ParameterFamily& f : effect.parameters) {
    keys.emplace_back(f.qualified() ? f.file_key : f.name);
  }
  for (const EffectSetting& s : effect.settings) keys.emplace_back(s.file_key);
  if (effect.reads_other_motion) keys.emplace_back("motion");
  return keys;
}

// dofs.<dof>.effects.<effect>: {settings}, as the effect table declares them (effects.h):
// each parameter in its admissible range (a value not given defaults to its `defaults_to`
// parameter's, else is required), each setting a positive number.
void ParseEffectSettings(const EffectEntry& effect, const Value& v, Dof dof,
                         const Vehicle& vehicle, DofTruth* truth) {
  const MapValue m(v, "the settings of effect " + effect.name);
  const std::vector<std::string> keys = SettingKeys(effect);
  m.AllowOnly(std::vector<std::string_view>(keys.begin(), keys.end()));
  const bool all_default = std::all_of(effect.parameters.begin(), effect.parameters.end(),
                                       [](const ParameterFamily& f) { return !f.defaults_to.empty(); });
  if (m.entries().empty() && all_default) m.self().Expected(model::Join(keys, " and/or "));
  for (const ParameterFamily& f : effect.parameters) {
    if (f.qualified()) {
      ParseQualified(f, m.Required(f.file_key), dof, vehicle, truth);
      continue;
    }
    const Value x = m.Optional(f.name);
    if (x.absent() && !f.defaults_to.empty()) {
      SetParam(truth, std::string(f.name), truth->params.at(std::string(f.defaults_to)), m.self());
      continue;
    }
    const Value given = m.Required(f.name);
    SetParam(truth, std::string(f.name),
             NumberIf(given, f.Expected(), [&f](double y) { return f.Admissible(y); }), given);
  }
  for (const EffectSetting& s : effect.settings) {
    truth->settings[std::string(s.setting)] = Positive(m.Required(s.file_key));
  }
  if (effect.reads_other_motion) {
    if (const Value motion = m.Optional("motion"); !motion.absent()) {
      ParseOtherMotion(motion, dof, truth);
    }
  }
}

// dofs.<dof>.params and .effects of a truth file; nullopt when the DOF has neither.
std::optional<DofTruth> ParseTruthDof(const Value& v, Dof dof, const Vehicle& vehicle) {
  const MapValue m(v, "a map {drag, added_mass, params, effects}");
  const Value effects = m.Optional("effects");
  if (!m.Has("params")) {
    if (!effects.absent()) m.Required("params");  // effects act on the true parameters
    return std::nullopt;
  }
  DofTruth truth;
  ParseParams(m.Required("params"), dof, vehicle, &truth);
  if (effects.absent()) return truth;
  const MapValue settings(effects, "a map {<effect>: {settings}}");
  for (const MapValue::Entry& e : settings.entries()) {
    const EffectEntry* effect = Effects().Find(e.key);
    if (!effect) e.key_value.Expected("an effect (" + Effects().NameList() + ")");
    ParseEffectSettings(*effect, e.value, dof, vehicle, &truth);
  }
  return truth;
}

// virtual_pool: {step, dropout_probability, outlier_probability, outlier_size}.
void ParseVirtualPool(const Value& v, Truth* truth) {
  const MapValue m(v, "a map {step, dropout_probability, outlier_probability, outlier_size}");
  m.AllowOnly({"step", "dropout_probability", "outlier_probability", "outlier_size"});
  if (const Value x = m.Optional("step"); !x.absent()) truth->integration_step_s = Positive(x);
  if (const Value x = m.Optional("dropout_probability"); !x.absent()) {
    truth->defects.dropout_probability = Probability(x);
  }
  if (const Value x = m.Optional("outlier_probability"); !x.absent()) {
    truth->defects.outlier_probability = Probability(x);
  }
  if (const Value x = m.Optional("outlier_size"); !x.absent()) {
    truth->defects.outlier_size = NonNegative(x);
  }
}

// ---------------------------------------------------------------------------------------------
// Campaign.

// The trial's default mapping: named, or the vehicle's only mapping on the trial's DOF.
std::string TrialMapping(const MapValue& m, Dof dof, const Vehicle& vehicle) {
  std::vector<std::string> names;
  for (int i : vehicle.MappingsOf(dof)) names.push_back(vehicle.mappings[i].name);
  const Value v = m.Optional("mapping");
  if (v.absent() && names.size() == 1) return names.front();
  if (v.absent()) {
    m.self().Fail("missing required key 'mapping' (the vehicle has " +
                  std::to_string(names.size()) + " " + std::string(DofName(dof)) + " mappings" +
                  (names.empty() ? "" : ": " + Join(names)) + ")");
  }
  const std::string name = v.node().IsScalar() ? v.node().Scalar() : "";
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    v.Expected(names.empty()
                   ? "a mapping on " + std::string(DofName(dof)) + ", but the vehicle has none"
                   : "a " + std::string(DofName(dof)) + " mapping of the vehicle (" + Join(names) +
                         ")");
  }
  return name;
}

// A trial's log must hold its DOF's nominal force and a measured position or velocity.
void CheckTrialColumns(const TrialEntry& trial, const Value& where) {
  const std::string dof(DofName(trial.dof));
  const std::string need =
      " (a " + dof + " trial needs force_" + dof + " and pos_" + dof + " or vel_" + dof + ")";
  const auto has_sample = [](const std::vector<double>& c) {
    return std::any_of(c.begin(), c.end(), [](double x) { return !std::isnan(x); });
  };
  const auto& force = trial.log.force[Index(trial.dof)];
  if (force.empty()) where.Fail(trial.file + " has no 'force_" + dof + "' column" + need);
  if (!has_sample(force)) where.Fail(trial.file + ": column 'force_" + dof + "' has no value");
  const auto& pos = trial.log.position[Index(trial.dof)];
  const auto& vel = trial.log.velocity[Index(trial.dof)];
  if (pos.empty() && vel.empty()) {
    where.Fail(trial.file + " has no 'pos_" + dof + "' or 'vel_" + dof + "' column" + need);
  }
  if (!has_sample(pos) && !has_sample(vel)) {
    where.Fail(trial.file + ": columns 'pos_" + dof + "' and 'vel_" + dof + "' have no value");
  }
}

TrialEntry ParseTrial(const Value& v, const Vehicle& vehicle, const TrialEntry* previous) {
  const MapValue m(v, "a trial {file, dof, mapping, ballast_steps, use, start}");
  m.AllowOnly({"file", "dof", "mapping", "ballast_steps", "use", "start"});
  TrialEntry trial;
  const Value file = m.Required("file");
  trial.path = ReadableFile(file);
  trial.file = file.node().Scalar();
  trial.dof = DofValue(m.Required("dof"));
  trial.mapping = TrialMapping(m, trial.dof, vehicle);
  if (const Value x = m.Optional("ballast_steps"); !x.absent()) {
    trial.ballast_steps = WholeNonNegative(x);
  }
  if (const Value x = m.Optional("use"); !x.absent()) {
    trial.use = Choice(x, {"fit", "validate"}, "a use") == 0 ? TrialUse::kFit : TrialUse::kValidate;
  }
  if (const Value x = m.Optional("start"); !x.absent()) {
    trial.start = AnyNumber(x);
    trial.has_start = true;
    // Trials are listed in the order they were run (contract §Campaign).
    if (previous != nullptr && previous->has_start && trial.start < previous->start) {
      x.Expected("a start >= the previous trial's " + FormatNumber(previous->start) +
                 " s (trials are listed in the order they were run)");
    }
  }
  std::vector<std::string> mappings;
  for (int i : vehicle.MappingsOf(trial.dof)) mappings.push_back(vehicle.mappings[i].name);
  trial.log = ReadTrialLog(trial.path, mappings);
  CheckTrialColumns(trial, v);
  return trial;
}

}  // namespace

Vehicle ReadVehicle(const std::string& path) {
  return Guarded(path, [&] {
    const YAML::Node root =
        LoadYaml(path, "a vehicle (name, mass, size, thrusters, mappings, ...)");
    return ParseVehicle(MapValue(Value(root, "", path, 0), "a map of vehicle keys"), false);
  });
}

Pool ReadPool(const std::string& path) {
  return Guarded(path, [&] {
    const YAML::Node root = LoadYaml(path, "a pool (name, length, width, depth, margin)");
    const MapValue m(Value(root, "", path, 0), "a map of pool keys");
    m.AllowOnly({"name", "length", "width", "depth", "margin"});
    Pool pool;
    const Value name = m.Optional("name");
    pool.name = name.absent() ? fs::path(path).stem().string() : Name(name, "a pool name");
    pool.length = Positive(m.Required("length"));
    pool.width = Positive(m.Required("width"));
    pool.depth = Positive(m.Required("depth"));
    if (const Value margin = m.Optional("margin"); !margin.absent()) {
      pool.margin = NonNegative(margin);
      if (!(2 * pool.margin < std::min({pool.length, pool.width, pool.depth}))) {
        margin.Expected("a margin that leaves room to move (2·margin < length, width and depth)");
      }
    }
    return pool;
  });
}

Truth ReadTruth(const std::string& path) {
  return Guarded(path, [&] {
    const YAML::Node root = LoadYaml(path, "a truth file (a vehicle plus dofs.<dof>.params)");
    const MapValue m(Value(root, "", path, 0), "a map of vehicle keys");
    Truth truth;
    truth.vehicle = ParseVehicle(m, true);
    if (const Value dofs = m.Optional("dofs"); !dofs.absent()) {
      const MapValue dof_map(dofs, "a map of DOFs");
      for (const MapValue::Entry& e : dof_map.entries()) {
        const Dof dof = DofKey(e);
        if (auto t = ParseTruthDof(e.value, dof, truth.vehicle)) truth.dofs[dof] = std::move(*t);
      }
    }
    if (truth.dofs.empty()) m.self().Fail("expected dofs.<dof>.params for at least one DOF");
    if (const Value v = m.Optional("virtual_pool"); !v.absent()) ParseVirtualPool(v, &truth);
    return truth;
  });
}

Campaign ReadCampaign(const std::string& path) {
  return Guarded(path, [&] {
    const YAML::Node root = LoadYaml(path, "a campaign (vehicle, pool, trials)");
    const MapValue m(Value(root, "", path, 0), "a map of campaign keys");
    m.AllowOnly({"vehicle", "pool", "trials"});
    Campaign campaign;
    campaign.path = path;
    const Value vehicle = m.Required("vehicle");
    campaign.vehicle = ReadVehicle(ReadableFile(vehicle));
    campaign.vehicle_file = vehicle.node().Scalar();
    if (const Value pool = m.Optional("pool"); !pool.absent()) {
      campaign.pool = ReadPool(ReadableFile(pool));
      campaign.pool_file = pool.node().Scalar();
    }
    for (const Value& item :
         List(m.Required("trials"), "a list of trials {file, dof, mapping, ...}")) {
      const TrialEntry* previous = campaign.trials.empty() ? nullptr : &campaign.trials.back();
      campaign.trials.push_back(ParseTrial(item, campaign.vehicle, previous));
    }
    return campaign;
  });
}

void WriteCampaignYaml(const std::string& path, const Campaign& campaign) {
  if (campaign.vehicle_file.empty()) {
    throw std::invalid_argument("WriteCampaignYaml " + path + ": no vehicle file");
  }
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "vehicle" << YAML::Value << campaign.vehicle_file;
  if (campaign.pool_file) out << YAML::Key << "pool" << YAML::Value << *campaign.pool_file;
  out << YAML::Key << "trials" << YAML::Value << YAML::BeginSeq;
  for (const TrialEntry& trial : campaign.trials) {
    if (trial.file.empty()) {
      throw std::invalid_argument("WriteCampaignYaml " + path + ": trial without file");
    }
    out << YAML::BeginMap;
    out << YAML::Key << "file" << YAML::Value << trial.file;
    out << YAML::Key << "dof" << YAML::Value << std::string(DofName(trial.dof));
    if (!trial.mapping.empty()) out << YAML::Key << "mapping" << YAML::Value << trial.mapping;
    out << YAML::Key << "ballast_steps" << YAML::Value << trial.ballast_steps;
    out << YAML::Key << "use" << YAML::Value << (trial.use == TrialUse::kFit ? "fit" : "validate");
    if (trial.has_start) out << YAML::Key << "start" << YAML::Value << FormatNumber(trial.start);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  if (!out.good()) {
    throw std::invalid_argument("WriteCampaignYaml " + path + ": " + out.GetLastError());
  }
  WriteFileAtomically(path, std::string(out.c_str()) + "\n");
}

}  // namespace uuvplan::model
