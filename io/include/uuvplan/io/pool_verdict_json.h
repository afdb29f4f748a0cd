// The pool verdict as JSON (planner/pool/pool_verdict.h; docs/formats.md, "verdict"): SI values,
// each length with its `unit` and whether it is free or wall to wall.
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/model/pool.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::io {

/// {"hosted", "sentence", "lines", "dofs": {<dof>: {"hosted", "limit", "reason", "extent",
/// "need", "need_verified", "undetermined"}}, "required": {"length", "width", "depth" (m, wall
/// to wall), "unit": "m", "measure": "wall to wall", "free": {...}, "turns", "exists"}}.
nlohmann::json PoolVerdictJson(const planner::PoolVerdict& verdict, const model::Pool& pool);

}  // namespace uuvplan::io
