// The checked JSON reader (json_value.h).
#include "uuvplan/io/json_value.h"

#include <cmath>
#include <limits>

#include "text_checks.h"
#include "uuvplan/io/files.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

using nlohmann::json;

namespace {

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

std::string JsonValue::Describe() const {
  const nlohmann::json& v = *value_;
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

std::optional<JsonValue> JsonValue::Optional(const std::string& key) const {
  if (!value_->is_object()) return std::nullopt;
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return JsonValue(*it, file(), KeyPath(key));
}

JsonValue JsonValue::Required(const std::string& key, const std::string& why) const {
  std::optional<JsonValue> v = Optional(key);
  if (!v) Fail("missing required key '" + key + "'" + (why.empty() ? "" : " (" + why + ")"));
  return *v;
}

JsonValue JsonValue::Item(std::size_t index) const {
  return JsonValue((*value_)[index], file(), ItemPath(index));
}

double Number(const JsonValue& v, const std::string& expectation) {
  if (!v.json().is_number() || !std::isfinite(v.json().get<double>())) v.Expected(expectation);
  return v.json().get<double>();
}

double NumberOrNaN(const JsonValue& v, const std::string& expectation) {
  return v.json().is_null() ? std::numeric_limits<double>::quiet_NaN() : Number(v, expectation);
}

double PositiveNumber(const JsonValue& v, const std::string& unit) {
  const std::string expectation = "a positive number (" + unit + ")";
  const double x = Number(v, expectation);
  if (!(x > 0)) v.Expected(expectation);
  return x;
}

double NonNegativeNumber(const JsonValue& v, const std::string& expectation) {
  const double x = Number(v, expectation);
  if (x < 0) v.Expected(expectation);
  return x;
}

int WholeNonNegative(const JsonValue& v) {
  const std::string expectation = "a whole number >= 0";
  const double x = Number(v, expectation);
  if (x < 0 || x != std::floor(x) || x > 1e6) v.Expected(expectation);
  return static_cast<int>(x);
}

std::string String(const JsonValue& v, const std::string& expectation) {
  if (!v.json().is_string() || v.json().get<std::string>().empty()) v.Expected(expectation);
  return v.json().get<std::string>();
}

json LoadJson(const std::string& path) {
  const std::string text = ReadFileText(path);
  CheckInputText(path, text, false);
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: ...";
    // keep what follows the position and put the position in our own "file:line:col" form.
    std::string why = e.what();
    if (const auto colon = why.find(": ", why.find("parse error")); colon != std::string::npos) {
      why = why.substr(colon + 2);
    }
    const std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
    throw model::InputError(path + ":" + LineColumn(text, at),
                            "not valid JSON: " + WithoutQuotedInput(why));
  } catch (const json::exception& e) {
    // A number beyond the double range ("2e+308": out_of_range.406, found by fuzz_plan).
    std::string why = e.what();
    if (const auto bracket = why.find("] "); bracket != std::string::npos)
      why = why.substr(bracket + 2);
    throw model::InputError(path, "not valid JSON: " + WithoutQuotedInput(why));
  }
}

json JsonNumber(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

}  // namespace uuvplan::io
