// Aligned tables for people (issue #18 item 5, docs/cli.md "Tables"): every column left-aligned
// under its title, two spaces apart, widths counted in characters (σ, °, N·m count one each).
// Conventions every table printed by the commands follows (tests/cli/table_units_test.cc):
// the first column is "DOF"; a quantity column carries its unit in its title, "σ (m/s)", or in
// every cell, "4:05 min", "0.84 kg" when the unit changes from row to row.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace uuvplan::cli {

class TextTable {
 public:
  explicit TextTable(std::vector<std::string> titles) : titles_(std::move(titles)) {}
  void AddRow(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  bool empty() const { return rows_.empty(); }
  /// The title line and the rows, each line starting with `indent`.
  void Print(std::ostream& out, const std::string& indent = "  ") const;

 private:
  std::vector<std::string> titles_;
  std::vector<std::vector<std::string>> rows_;
};

/// "0.84 kg" (`digits` significant digits, model::Significant), "0.81 (no unit)" for a pure
/// number (unit "1", e.g. an installation coefficient), "-" when not finite.
std::string Quantity(double value, const std::string& unit, int digits = 3);

/// Width of UTF-8 text in characters (code points).
std::size_t TextWidth(const std::string& text);

}  // namespace uuvplan::cli
