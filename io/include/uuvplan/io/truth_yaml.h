// The truth file (contract §Truth): a vehicle file plus the true parameters and effects of each
// DOF and the virtual pool's defects.
#pragma once

#include <string>

#include "uuvplan/model/truth.h"

namespace uuvplan::io {

/// Reads a truth file. Faults are model::InputError naming the file, line and key.
model::Truth ReadTruth(const std::string& path);

}  // namespace uuvplan::io
