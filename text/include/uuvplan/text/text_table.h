// Aligned tables for people (docs/cli.md "Tables"): every column left-aligned under its title,
// two spaces apart, widths counted in characters (σ, °, N·m count one each).
// Conventions every table printed by the commands follows (tests/cli/table_units_test.cc):
// the first column is "DOF"; a quantity column carries its unit in its title, "σ (m/s)", or in
// every cell, "4:05 min", "0.84 kg" when the unit changes from row to row.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace uuvplan::text {

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

/// Width of UTF-8 text in characters (code points).
std::size_t TextWidth(const std::string& text);

/// A column of a table whose widths are part of its format (a fixed layout, unlike TextTable's
/// fitted one): `width` as std::setw pads (bytes: "σ" counts two), right- or left-aligned; a
/// wider cell is written whole, unpadded.
struct FixedColumn {
  std::size_t width = 0;
  bool right = false;
};

/// One line of `cells` padded to `columns` (no newline): the title line or a row of a table
/// with fixed columns (score, simulate, demo, a diagnosis' corrected thrust map).
std::string FixedRow(const std::vector<FixedColumn>& columns,
                     const std::vector<std::string>& cells);

}  // namespace uuvplan::text
