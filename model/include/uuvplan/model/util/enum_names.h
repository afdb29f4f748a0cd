// One name table per enum, one lookup: `constexpr EnumNames<Status, 3> kStatusNames{{...}}`
// then `kStatusNames.Name(s)` and `kStatusNames.Parse("ok")`. Replaces a switch per enum.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace uuvplan::model {

template <typename E, std::size_t N>
struct EnumNames {
  std::array<std::pair<E, std::string_view>, N> entries;

  /// The name of `value`; "?" for a value missing from the table (a programming error).
  constexpr std::string_view Name(E value) const {
    for (const auto& [e, name] : entries) {
      if (e == value) return name;
    }
    return "?";
  }
  /// The name of `value`, or "<prefix>(<number>)" for a value the table leaves out (a
  /// library's return codes beyond those it names).
  std::string NameOrNumber(E value, std::string_view prefix) const {
    const std::string_view name = Name(value);
    if (name != "?") return std::string(name);
    return std::string(prefix) + "(" + std::to_string(static_cast<int>(value)) + ")";
  }
  /// The value named `name`, or nullopt.
  constexpr std::optional<E> Parse(std::string_view name) const {
    for (const auto& [e, n] : entries) {
      if (n == name) return e;
    }
    return std::nullopt;
  }
  /// "a, b, c": the names, for messages.
  std::string List() const {
    std::string out;
    for (const auto& entry : entries) {
      out += (out.empty() ? "" : ", ") + std::string(entry.second);
    }
    return out;
  }
};

}  // namespace uuvplan::model
