// The files the pool team takes to the pool (planner/pool/command_sheet.h), written by
// `uuvplan schedule --commands DIR` as one new directory, whole or not at all:
//   <trial id>.csv  t_s, one column per thruster (its name; the thruster's command units, as the
//                   vehicle file's thrusters[i].command range), expected_position_m (or _rad):
//                   each row's commands hold until the next row; the last row stops every
//                   thruster at the trial's end;
//   run_sheet.md    the trials in order: mapping, start position and heading, duration, expected
//                   travel over the a priori box, abort distances, the commands file.
#pragma once

#include <map>
#include <string>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/pool/command_sheet.h"

namespace uuvplan::io {

/// The commands file of one trial (CSV text).
std::string CommandsCsv(const planner::CommandSheet& sheet, const planner::TrialCommands& trial);

/// The run sheet (Markdown).
std::string RunSheetMarkdown(const planner::CommandSheet& sheet, const model::Vehicle& vehicle,
                             const model::Pool& pool);

/// Writes the directory `dir` (must not exist or be empty): every trial's CSV and run_sheet.md.
void WriteCommandFiles(const std::string& dir, const planner::CommandSheet& sheet,
                       const model::Vehicle& vehicle, const model::Pool& pool);

/// The command files of `schedule` (planner::MakeCommandSheet at 20 Hz, travel and abort lines
/// over the box `options` plan over), written as WriteCommandFiles writes them.
void WriteScheduleCommands(const std::string& dir, const model::Vehicle& vehicle,
                           const model::Pool& pool, const planner::Schedule& schedule,
                           const planner::ScheduleOptions& options);

}  // namespace uuvplan::io
