// Small text helpers shared by every layer (one copy each).
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace uuvplan::model {

inline bool StartsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

inline bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

/// "a, b, c" (or with another separator).
template <typename Container>
std::string Join(const Container& items, std::string_view separator = ", ") {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += separator;
    out += std::string_view(item);
  }
  return out;
}

/// `digits` significant digits for people ("0.0523", "1.5", "1234"): positional between 0.001
/// and 10⁷ (a whole number keeps all its integer digits rather than an exponent, "1234" not
/// "1.2e+03"), trailing zeros dropped; an exponent only outside that range ("2.5e-05").
inline std::string Significant(double x, int digits) {
  std::ostringstream os;
  const double a = std::abs(x);
  if (!std::isfinite(x) || x == 0 || a < 1e-3 || a >= 1e7) {
    os.precision(digits);
    os << x;
    return os.str();
  }
  const int exponent = static_cast<int>(std::floor(std::log10(a)));
  const int decimals = std::max(0, digits - 1 - exponent);
  os << std::fixed << std::setprecision(decimals) << x;
  std::string text = os.str();
  if (decimals > 0) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text == "-0" ? "0" : text;
}

/// `decimals` digits after the point, kept even when zero ("0.90", "1.250"): a figure whose
/// resolution is fixed (a correlation, a stage's seconds).
inline std::string Decimals(double x, int decimals) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(decimals) << x;
  return os.str();
}

/// A duration for people: "45.2 s" under a minute, else minutes and seconds "4:05 min" (never
/// "2.4e+02 s").
inline std::string DurationText(double seconds) {
  if (!std::isfinite(seconds) || std::abs(seconds) < 59.95) return Significant(seconds, 3) + " s";
  const long total = std::lround(std::abs(seconds));
  std::ostringstream os;
  os << (seconds < 0 ? "-" : "") << total / 60 << ":" << std::setw(2) << std::setfill('0')
     << total % 60 << " min";
  return os.str();
}

/// An angle (rad) for people: degrees, with turns beyond one turn ("57.3°", "1080° (3 turns)").
inline std::string AngleText(double radians) {
  const double degrees = radians * 180.0 / M_PI;
  std::string text = Significant(degrees, 4) + "°";
  if (std::abs(degrees) >= 360.0) text += " (" + Significant(degrees / 360.0, 3) + " turns)";
  return text;
}

/// The shortest text that reads back as exactly `x` (std::to_chars round trip).
inline std::string ShortestNumber(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

}  // namespace uuvplan::model
