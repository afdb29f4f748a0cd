// The checked reader of YAML files: a Value is a YAML node with its Place (file, line, key
// path); MapValue checks a map's keys (names, no repeats, only the allowed ones); the readers
// below turn a Value into a number, a name, a DOF... or report "<file>:<line>: <key.path>:
// expected <what>, got <value>". A key that is present must hold a valid value (an empty value
// is not taken as "use the default").
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/io/place.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::io {

// A YAML value and where it sits (a missing key is reported at its parent's line).
class Value : public Place {
 public:
  Value(YAML::Node node, std::string key_path, const std::string& file, int line)
      : Place(file, line, std::move(key_path)), node_(std::move(node)) {}

  const YAML::Node& node() const { return node_; }
  /// The key is not in the file at all (an empty value is present, and "nothing").
  bool absent() const { return !node_.IsDefined(); }

  /// A value inside this one.
  Value Child(const YAML::Node& node, std::string key_path, int line) const {
    return Value(node, std::move(key_path), file(), line);
  }

  using Place::Expected;
  /// Fails with "expected <expectation>, got <Describe()>".
  [[noreturn]] void Expected(const std::string& expectation) const {
    Place::Expected(expectation, Describe());
  }

  /// What the file holds here, for "got ...": 'text', [1, 2], a map, a list, nothing.
  std::string Describe() const;

 private:
  YAML::Node node_;
};

// A YAML map whose keys are distinct names. Values of keys are reported at the key's line.
class MapValue {
 public:
  struct Entry {
    std::string key;
    Value key_value;  ///< for faults of the key itself (reported with the parent's path)
    Value value;
  };

  /// Fails with Expected(what) unless `v` is a map of distinct scalar keys.
  MapValue(const Value& v, const std::string& what);

  /// Every key must be one of `allowed`.
  void AllowOnly(std::initializer_list<std::string_view> allowed) const;
  void AllowOnly(const std::vector<std::string_view>& allowed) const;
  /// The value of `key`; absent() when the map does not have it.
  Value Optional(std::string_view key) const;
  /// The value of `key`; fails with "missing required key '<key>'" when absent.
  Value Required(std::string_view key) const;

  bool Has(std::string_view key) const { return !Optional(key).absent(); }
  const std::vector<Entry>& entries() const { return entries_; }
  const Value& self() const { return self_; }

 private:
  Value self_;
  std::vector<Entry> entries_;
};

/// The 1-based line of `node`, or `fallback` when yaml-cpp does not know it.
int LineOf(const YAML::Node& node, int fallback);

/// A finite number for which `accept` holds; otherwise Expected(expectation).
template <typename Accept>
double NumberIf(const Value& v, const std::string& expectation, Accept accept);

double AnyNumber(const Value& v);
double Positive(const Value& v);
double NonNegative(const Value& v);
/// A probability in [0, 1).
double Probability(const Value& v);
int WholeNonNegative(const Value& v);
/// A non-empty scalar.
std::string Name(const Value& v, const std::string& expectation = "a name");
/// One of `choices`; returns its index.
int Choice(const Value& v, std::initializer_list<std::string_view> choices,
           const std::string& what);
/// The value `names` gives the scalar at `v`; otherwise Expected(what and the names).
template <typename E, std::size_t N>
E EnumValue(const Value& v, const model::EnumNames<E, N>& names, const std::string& what) {
  if (v.node().IsScalar()) {
    if (const std::optional<E> e = names.Parse(v.node().Scalar())) return *e;
  }
  v.Expected(what + " (" + names.List() + ")");
}
model::Dof DofValue(const Value& v);
/// A key of a per-DOF map must be a DOF name.
model::Dof DofKey(const MapValue::Entry& e);
/// The items of a list.
std::vector<Value> List(const Value& v, const std::string& expectation);
/// [lo, hi] of two numbers.
std::array<double, 2> Pair(const Value& v, const std::string& expectation);
/// [x, y, z] of three numbers; otherwise Expected(expectation).
std::array<double, 3> Triple(const Value& v, const std::string& expectation);
/// A file named at `v` (relative to v's file), which must be readable; returns its path.
std::string ReadableFile(const Value& v);

/// The top-level node of a YAML file; `what` describes the expected content of an empty file.
YAML::Node LoadYaml(const std::string& file, const std::string& what);
/// The top-level map of a YAML file (LoadYaml, then MapValue with `map_what`).
MapValue LoadYamlMap(const std::string& file, const std::string& what, const std::string& map_what);

/// Runs a reader of `file`, turning any exception other than model::InputError into one that
/// names the file: a reader never lets a yaml-cpp or library exception escape.
template <typename Read>
auto Guarded(const std::string& file, Read read) -> decltype(read());

// ---------------------------------------------------------------------------------------------

bool ParseYamlNumber(const Value& v, double* x);
[[noreturn]] void RethrowAsInputError(const std::string& file);

template <typename Accept>
double NumberIf(const Value& v, const std::string& expectation, Accept accept) {
  double x = 0.0;
  if (!ParseYamlNumber(v, &x) || !accept(x)) v.Expected(expectation);
  return x;
}

template <typename Read>
auto Guarded(const std::string& file, Read read) -> decltype(read()) {
  try {
    return read();
  } catch (...) {
    RethrowAsInputError(file);
  }
}

}  // namespace uuvplan::io
