// Numbers with their units (quantity_text.h).
#include "uuvplan/text/quantity_text.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "uuvplan/model/util/text.h"

namespace uuvplan::text {

std::string UnitSuffix(const std::string& unit) { return unit == "1" ? "" : " " + unit; }

std::string CellUnit(const std::string& unit) { return unit == "1" ? " (no unit)" : " " + unit; }

std::string Cell(double value, int digits) {
  return std::isfinite(value) ? model::Significant(value, digits) : "-";
}

std::string Quantity(double value, const std::string& unit, int digits) {
  if (!std::isfinite(value)) return "-";
  return model::Significant(value, digits) + CellUnit(unit);
}

std::string ValueSigma(double value, double sigma, const std::string& unit, int value_digits,
                       int sigma_digits) {
  std::string text = model::Significant(value, value_digits);
  if (std::isfinite(sigma)) text += " ± " + model::Significant(sigma, sigma_digits);
  return text + UnitSuffix(unit);
}

std::string ValueSigmaCell(double value, double sigma, const std::string& unit) {
  const int decimals = sigma > 0 && std::isfinite(sigma)
                           ? std::clamp(1 - static_cast<int>(std::floor(std::log10(sigma))), 0, 6)
                           : 3;
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << value << " ± " << sigma << CellUnit(unit);
  return s.str();
}

std::string SignedPercent(double fraction) {
  std::ostringstream s;
  s.precision(1);
  s << std::fixed << std::showpos << 100.0 * fraction << "%";
  return s.str();
}

}  // namespace uuvplan::text
