// ParallelFor (model/util/parallel.h) under the name identification and diagnosis use.
#pragma once

#include "uuvplan/model/util/parallel.h"

namespace uuvplan::ident::diagnosis {

using model::ParallelFor;

}  // namespace uuvplan::ident::diagnosis
