// Where a recording's trials lie on the recorder clock: the whole span of the thruster
// commands (one trial per recording), or each span of thruster activity (some command off
// zero), spans closer than a quiet pause merged.
#pragma once

#include <array>
#include <vector>

namespace uuvplan::io::import {

/// [start, end] (s): from the first to the last command message.
std::vector<std::array<double, 2>> WholeWindow(const std::vector<double>& command_times);

/// One [start, end] per span of activity: from the first message with some command off zero
/// to the first message after the span with every command at zero (or the last message); spans
/// less than `quiet_s` apart are one. `commands[k][i]`: thruster k at message i.
std::vector<std::array<double, 2>> ActivityWindows(const std::vector<double>& command_times,
                                                   const std::vector<std::vector<double>>& commands,
                                                   double quiet_s);

}  // namespace uuvplan::io::import
