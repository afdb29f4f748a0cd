// Numbers, units and tables for people (text/quantity_text.h, text/text_table.h): one unit
// rule per place (a sentence drops the unit of a pure number, a cell says "(no unit)"), σ with
// its value, and columns aligned by characters, not bytes.
#include "uuvplan/text/quantity_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include "uuvplan/text/text_table.h"

namespace uuvplan::text {
namespace {

TEST(QuantityText, APureNumberHasNoUnitInASentenceAndSaysSoInACell) {
  EXPECT_EQ(UnitSuffix("N·s/m"), " N·s/m");
  EXPECT_EQ(UnitSuffix("1"), "");
  EXPECT_EQ(Quantity(0.8412, "kg"), "0.841 kg");
  EXPECT_EQ(Quantity(0.8123, "1"), "0.812 (no unit)");
  EXPECT_EQ(Quantity(std::nan(""), "kg"), "-");
  EXPECT_EQ(Cell(1234.5678), "1235");
  EXPECT_EQ(Cell(INFINITY), "-");
}

TEST(QuantityText, ValueWithSigmaAndItsUnit) {
  EXPECT_EQ(ValueSigma(0.0823, 0.00314, "s"), "0.0823 ± 0.0031 s");
  EXPECT_EQ(ValueSigma(0.0823, 0.00314, "s", 2, 2), "0.082 ± 0.0031 s");
  EXPECT_EQ(ValueSigma(0.0823, std::nan(""), "s"), "0.0823 s");  // σ unknown: the value alone
  EXPECT_EQ(ValueSigma(0.56, 0.023, "1"), "0.56 ± 0.023");
}

TEST(QuantityText, ValueSigmaCellRoundsTheValueToSigmasDecimals) {
  EXPECT_EQ(ValueSigmaCell(0.08234, 0.00314, "s"), "0.0823 ± 0.0031 s");
  EXPECT_EQ(ValueSigmaCell(123.456, 12.3, "kg"), "123 ± 12 kg");
  EXPECT_EQ(ValueSigmaCell(0.5612, 0.0231, "1"), "0.561 ± 0.023 (no unit)");
  EXPECT_EQ(ValueSigmaCell(2.0, 0.0, "m"), "2.000 ± 0.000 m");  // σ 0: three decimals
}

TEST(QuantityText, SignedPercentKeepsTheSignAndOneDecimal) {
  EXPECT_EQ(SignedPercent(0.063), "+6.3%");
  EXPECT_EQ(SignedPercent(-0.001), "-0.1%");
}

TEST(TextTable, ColumnsAlignByCharacters) {
  TextTable table({"DOF", "σ (m/s)", "note"});
  table.AddRow({"surge", "0.01", "ok"});
  table.AddRow({"yaw", "0.002", "°/s"});
  std::ostringstream out;
  table.Print(out, "");
  EXPECT_EQ(out.str(),
            "DOF    σ (m/s)  note\n"
            "surge  0.01     ok\n"
            "yaw    0.002    °/s\n");
  EXPECT_EQ(TextWidth("σ (m/s)"), 7u);
}

// Fixed columns pad as std::setw does (bytes), right or left; a wider cell is written whole.
TEST(TextTable, FixedRowPadsLikeSetw) {
  const std::vector<FixedColumn> columns{{6}, {5, true}, {3, true}};
  EXPECT_EQ(FixedRow(columns, {"trial", "dof", "rows"}), "trial   dofrows");
  EXPECT_EQ(FixedRow(columns, {"a", "σ", "1"}), "a        σ  1");
  std::ostringstream setw;
  setw << std::left << std::setw(6) << "a" << std::right << std::setw(5) << "σ" << std::setw(3)
       << "1";
  EXPECT_EQ(FixedRow(columns, {"a", "σ", "1"}), setw.str());
  EXPECT_EQ(FixedRow(columns, {"a", "b", "c", "extra"}), "a         b  cextra");
}

}  // namespace
}  // namespace uuvplan::text
