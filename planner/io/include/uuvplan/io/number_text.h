// Numbers as text, read and written in one place for every format of the io layer. Reading
// takes a whole cell or scalar as a finite number; writing gives either the shortest text that
// reads back exactly (model::ShortestNumber, YAML and JSON) or `digits` significant digits as
// %.<digits>g would, without the locale (CSV columns).
#pragma once

#include <string>
#include <string_view>

#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using model::ShortestNumber;

/// `text` without leading and trailing blanks (spaces, tabs; a trailing '\r' too).
std::string_view TrimBlanks(std::string_view text);

/// Parses the whole of `text` as a finite number (an optional leading '+' is allowed; NaN and
/// infinities are not numbers here). False if `text` is anything else.
bool ParseNumber(std::string_view text, double* value);

/// Appends `value` as %.<digits>g would, without the locale.
void AppendGeneral(double value, int digits, std::string* out);

}  // namespace uuvplan::io
