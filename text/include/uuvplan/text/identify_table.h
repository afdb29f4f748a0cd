// The `identify` result as a readable table (its JSON is io::IdentifyJson).
#pragma once

#include <ostream>

#include "uuvplan/ident/identify.h"

namespace uuvplan::text {

/// Readable tables: per DOF the parameters (value, σ, percentile error, significance) and the
/// fit figures, then warnings and what was excluded from the data.
void PrintIdentifyTable(const ident::IdentifyResult& result, std::ostream& out);

}  // namespace uuvplan::text
