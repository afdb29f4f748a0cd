// The checked reader of JSON files: a JsonValue is a JSON value with its Place (file and key
// path; JSON values carry no line), and the readers below turn it into a number, a string...
// or report "<file>: <key.path>: expected <what>, got <value>". Keys the contract does not
// name are ignored (it welcomes more keys). Also the one writer rule: NaN is written as null.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "uuvplan/io/place.h"

namespace uuvplan::io {

class JsonValue : public Place {
 public:
  JsonValue(const nlohmann::json& value, std::string file, std::string key_path)
      : Place(std::move(file), 0, std::move(key_path)), value_(&value) {}

  const nlohmann::json& json() const { return *value_; }

  using Place::Expected;
  /// Fails with "expected <expectation>, got <Describe()>".
  [[noreturn]] void Expected(const std::string& expectation) const {
    Place::Expected(expectation, Describe());
  }
  /// What the file holds here, for "got ...": the number 3, the string "x", an array, ...
  std::string Describe() const;

  /// The value of `key`, if this is an object that has it.
  std::optional<JsonValue> Optional(const std::string& key) const;
  /// The value of `key`; fails with "missing required key '<key>' (<why>)" when absent.
  JsonValue Required(const std::string& key, const std::string& why = "") const;
  /// Item `index` of this array.
  JsonValue Item(std::size_t index) const;

 private:
  const nlohmann::json* value_;
};

/// A finite number.
double Number(const JsonValue& v, const std::string& expectation = "a number");
/// A finite number, or NaN for null (what the writers put for a non-finite one).
double NumberOrNaN(const JsonValue& v, const std::string& expectation = "a number or null");
/// A number > 0, described as "a positive number (<unit>)".
double PositiveNumber(const JsonValue& v, const std::string& unit);
/// A number >= 0, described as `expectation` ("a number >= 0 (s)").
double NonNegativeNumber(const JsonValue& v, const std::string& expectation);
int WholeNonNegative(const JsonValue& v);
/// A non-empty string.
std::string String(const JsonValue& v, const std::string& expectation);

/// The top-level value of a JSON file; a syntax error is reported as
/// "<file>:<line>:<column>: not valid JSON: <why>".
nlohmann::json LoadJson(const std::string& path);

/// `x`, or null when it is not finite (JSON has no NaN).
nlohmann::json JsonNumber(double x);

}  // namespace uuvplan::io
