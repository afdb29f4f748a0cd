// The `identify` result as a readable table (its JSON is io::IdentifyJson).
#pragma once

#include <ostream>
#include <string>

#include "uuvplan/ident/identify.h"

namespace uuvplan::cli {

/// Readable tables: per DOF the parameters (value, σ, percentile error, significance) and the
/// fit figures, then warnings and what was excluded from the data.
void PrintIdentifyTable(const ident::IdentifyResult& result, std::ostream& out);

/// A number for a table: `precision` significant digits, "-" when not finite.
std::string Cell(double v, int precision = 4);

}  // namespace uuvplan::cli
