// Numbers in messages: four significant digits unless told otherwise (one formatter for the
// identification's notes and warnings).
#pragma once

#include <string>

#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

inline std::string Fmt(double v, int precision = 4) { return model::Significant(v, precision); }

}  // namespace uuvplan::ident
