// The pool verdict in words (planner/pool/pool_verdict.h), the same lines in every command
// (schedule, check-pool, next, loop, demo), in the JSON that carries them and in the report:
// units on every number, free travel and wall to wall said apart.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::text {

/// One line: "Pool P CAN host …", "… can host … for PART of the a priori box …" (the box about
/// the identified model when the vehicle file has one), "… CANNOT host …", and why nothing was
/// planned when nothing was.
std::string VerdictSentence(const planner::PoolVerdict& verdict, const model::Pool& pool);

/// The answer to "can this pool host it?" in the verdict's own words: "CAN host it", "can
/// host it for PART of the a priori box only" (of the box about the identified model when
/// `identified_box`, about the base's estimates when also `derived_box`: PoolVerdict), "CANNOT
/// host it".
std::string VerdictAnswer(planner::Hostability hostability, bool identified_box = false,
                          bool derived_box = false);

/// A point of the a priori box of `dof`: "m 495 kg, drag ×0.5 of the prior (kq 12 N·s²/m²)".
std::string BoxPointLabel(const planner::BoxPoint& point, model::Dof dof);

/// Why `dof` is not hosted: the planner's message, each failing trial of a given plan with its
/// reasons, and what a larger pool does not lift (empty when hosted).
std::string DofReason(const planner::PoolVerdict& verdict, const planner::DofVerdict& dof,
                      const model::Pool& pool);

/// The verdict as readable lines, the first being VerdictSentence: the pool, one line per DOF,
/// the pool that would host them and the assumptions judged on.
std::vector<std::string> VerdictLines(const planner::PoolVerdict& verdict, const model::Pool& pool);

/// "\nVerdict: " and VerdictLines, one per line.
void PrintVerdict(const planner::PoolVerdict& verdict, const model::Pool& pool, std::ostream& out);

/// The loop's message, read against the verdict it ran under: a loop that met a vehicle
/// outside the hostable part of the box (LoopResult::outside_part, planner::ReadLoopEnd) says
/// so, with the verdict's sentence, before the stop's own message.
std::string LoopEndMessage(const planner::LoopResult& result, const planner::PoolVerdict& verdict,
                           const model::Pool& pool);

}  // namespace uuvplan::text
