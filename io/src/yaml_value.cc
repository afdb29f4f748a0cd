// The checked YAML reader (yaml_value.h): values with their place, map key checks, scalars.
#include "uuvplan/io/yaml_value.h"

#include <charconv>
#include <exception>

#include "text_checks.h"
#include "uuvplan/io/files.h"
#include "uuvplan/io/number_text.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using model::Join;

namespace {

std::string Shorten(const std::string& s) {
  constexpr std::size_t kMax = 60;
  return s.size() <= kMax ? s : s.substr(0, kMax) + "...";
}

std::string Where(const std::string& file, const YAML::Mark& mark) {
  return mark.is_null() ? file : file + ":" + std::to_string(mark.line + 1);
}

std::string DofList() {
  std::vector<std::string> names;
  for (model::Dof d : model::kAllDofs) names.emplace_back(model::DofName(d));
  return Join(names);
}

}  // namespace

std::string Value::Describe() const {
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

int LineOf(const YAML::Node& node, int fallback) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? fallback : mark.line + 1;  // yaml-cpp counts lines from 0
}

MapValue::MapValue(const Value& v, const std::string& what) : self_(v) {
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
    entries_.push_back({key, key_value, v.Child(it->second, v.KeyPath(key), line)});
  }
}

void MapValue::AllowOnly(std::initializer_list<std::string_view> allowed) const {
  AllowOnly(std::vector<std::string_view>(allowed));
}

void MapValue::AllowOnly(const std::vector<std::string_view>& allowed) const {
  for (const Entry& e : entries_) {
    if (std::find(allowed.begin(), allowed.end(), e.key) != allowed.end()) continue;
    e.key_value.Fail("unknown key '" + e.key + "' (allowed: " + Join(allowed) + ")");
  }
}

Value MapValue::Optional(std::string_view key) const {
  for (const Entry& e : entries_) {
    if (e.key == key) return e.value;
  }
  return self_.Child(YAML::Node(YAML::NodeType::Undefined), self_.KeyPath(std::string(key)),
                     self_.line());
}

Value MapValue::Required(std::string_view key) const {
  Value v = Optional(key);
  if (v.absent()) self_.Fail("missing required key '" + std::string(key) + "'");
  return v;
}

// A whole scalar as a finite number (YAML's .nan and .inf are refused: no parameter of the
// contract may be infinite or undefined).
bool ParseYamlNumber(const Value& v, double* x) {
  return v.node().IsScalar() && ParseNumber(TrimBlanks(v.node().Scalar()), x);
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

std::string Name(const Value& v, const std::string& expectation) {
  if (!v.node().IsScalar() || v.node().Scalar().empty()) v.Expected(expectation);
  return v.node().Scalar();
}

int Choice(const Value& v, std::initializer_list<std::string_view> choices,
           const std::string& what) {
  if (v.node().IsScalar()) {
    int i = 0;
    for (std::string_view c : choices) {
      if (c == v.node().Scalar()) return i;
      ++i;
    }
  }
  v.Expected(what + " (" + Join(choices) + ")");
}

model::Dof DofValue(const Value& v) {
  if (v.node().IsScalar()) {
    if (auto dof = model::ParseDof(v.node().Scalar())) return *dof;
  }
  v.Expected("a DOF (" + DofList() + ")");
}

model::Dof DofKey(const MapValue::Entry& e) { return DofValue(e.key_value); }

std::vector<Value> List(const Value& v, const std::string& expectation) {
  if (!v.node().IsSequence()) v.Expected(expectation);
  std::vector<Value> items;
  for (std::size_t i = 0; i < v.node().size(); ++i) {
    const YAML::Node item = v.node()[i];
    items.push_back(v.Child(item, v.ItemPath(i), LineOf(item, v.line())));
  }
  return items;
}

std::array<double, 2> Pair(const Value& v, const std::string& expectation) {
  const std::vector<Value> items = List(v, expectation);
  if (items.size() != 2) v.Expected(expectation);
  return {AnyNumber(items[0]), AnyNumber(items[1])};
}

std::array<double, 3> Triple(const Value& v, const std::string& expectation) {
  const std::vector<Value> items = List(v, expectation);
  if (items.size() != 3) v.Expected(expectation);
  std::array<double, 3> x{};
  for (int i = 0; i < 3; ++i) x[i] = NumberIf(items[i], expectation, [](double) { return true; });
  return x;
}

std::string ReadableFile(const Value& v) {
  const std::string written = Name(v, "a file name");
  const std::string path = ResolveBeside(v.file(), written);
  if (const std::string reason = UnreadableReason(path); !reason.empty()) {
    v.Fail("cannot open '" + path + "': " + reason);
  }
  return path;
}

YAML::Node LoadYaml(const std::string& file, const std::string& what) {
  const std::string text = ReadFileText(file);
  CheckInputText(file, text, true);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw model::InputError(Where(file, e.mark), "not valid YAML: " + e.msg);
  }
  if (root.IsNull()) throw model::InputError(file, "empty file: expected " + what);
  return root;
}

MapValue LoadYamlMap(const std::string& file, const std::string& what,
                     const std::string& map_what) {
  const YAML::Node root = LoadYaml(file, what);
  // A file of another kind is not quoted back (it may be anything: /etc/passwd).
  if (!root.IsMap()) {
    throw model::InputError(file, "expected " + map_what + ", got " +
                                      (root.IsSequence() ? "a list" : "text without YAML keys") +
                                      " (is this the right file?)");
  }
  return MapValue(Value(root, "", file, 0), map_what);
}

void RethrowAsInputError(const std::string& file) {
  try {
    throw;
  } catch (const model::InputError&) {
    throw;
  } catch (const YAML::Exception& e) {
    throw model::InputError(Where(file, e.mark), e.msg);
  } catch (const std::exception& e) {
    throw model::InputError(file, std::string("cannot read: ") + e.what());
  }
}

}  // namespace uuvplan::io
