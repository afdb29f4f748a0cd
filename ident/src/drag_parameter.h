// Which parameters are drag coefficients (they only dissipate: a negative value is implausible,
// and a model keeps at least one of them).
#pragma once

#include <string>

#include "uuvplan/model/effects.h"

namespace uuvplan::ident {

/// k, kq and their negative-side twins.
inline bool IsDragParameter(const std::string& name) {
  return name == model::param::kLinearDrag || name == model::param::kQuadraticDrag ||
         name == model::param::kLinearDragNeg || name == model::param::kQuadraticDragNeg;
}

}  // namespace uuvplan::ident
