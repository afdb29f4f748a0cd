// The loop's figure: per DOF, each parameter's percentile error 100·σ/|θ|
// (ref 000 §III-A) against the accumulated pool time — achieved after each trial (solid,
// markers) and as the planner predicted it for the trial it planned (dashed) — with the target.
#pragma once

#include "uuvplan/io/loop_json.h"
#include "uuvplan/report/chart.h"

namespace uuvplan::report {

Figure LoopFigure(const io::LoopHistory& history);

}  // namespace uuvplan::report
