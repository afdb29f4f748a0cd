// The pool file (contract §Pool).
#pragma once

#include <string>

#include "uuvplan/model/pool.h"

namespace uuvplan::io {

/// Reads a pool; the name defaults to the file's stem. Faults are model::InputError.
model::Pool ReadPool(const std::string& path);

}  // namespace uuvplan::io
