// The samples of a device that stamps them with its own clock (a microcontroller's millis())
// on the recorder's clock: the device clock runs at a slightly different rate and its samples
// reach the recorder after a varying transport delay (USB, network), never before they were
// taken. So the line arrival = a + b·device is fitted by least squares and then shifted down
// to the earliest arrival: the samples that met the least delay fix the offset, the rest fix
// the rate. What remains is the least delay itself, which no recording can observe.
#pragma once

#include <string>
#include <vector>

namespace uuvplan::io::import {

/// Recorder times of samples stamped `device_s` (s, non-decreasing) that arrived at
/// `arrival_s`; a device clock that runs backwards is model::InputError naming `where`.
std::vector<double> OnRecorderClock(const std::vector<double>& device_s,
                                    const std::vector<double>& arrival_s, const std::string& where);

}  // namespace uuvplan::io::import
