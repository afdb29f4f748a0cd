// Numbers with their units for people. A pure number (unit "1", e.g. an installation
// coefficient) carries no unit in a sentence (UnitSuffix) and says "(no unit)" where a column
// of quantities has no unit in its title (CellUnit). `digits` are significant digits
// (model::Significant).
#pragma once

#include <string>

namespace uuvplan::text {

/// " N·s/m" after a value, or nothing for a pure number (unit "1").
std::string UnitSuffix(const std::string& unit);

/// " N·s/m" after a value in a table cell, " (no unit)" for a pure number.
std::string CellUnit(const std::string& unit);

/// A number for a table: `digits` significant digits, "-" when not finite.
std::string Cell(double value, int digits = 4);

/// "0.84 kg" in a table cell, "0.81 (no unit)" for a pure number (its column has no unit
/// title to say so), "-" when not finite.
std::string Quantity(double value, const std::string& unit, int digits = 3);

/// "0.082 ± 0.003 s": the value to `value_digits` and σ to `sigma_digits` significant digits,
/// then the unit (UnitSuffix); the value alone with its unit when σ is not finite.
std::string ValueSigma(double value, double sigma, const std::string& unit, int value_digits = 3,
                       int sigma_digits = 2);

/// "0.0823 ± 0.0031 s" in a table cell: σ to two significant digits and the value to the same
/// decimals (3 when σ is not positive and finite), then the unit as CellUnit gives it.
std::string ValueSigmaCell(double value, double sigma, const std::string& unit);

/// A relative error as a signed percentage with one decimal ("+6.3%", "-0.1%"), as the error
/// breakdown prints it, so that a sentence quoting it reads the table's number.
std::string SignedPercent(double fraction);

}  // namespace uuvplan::text
