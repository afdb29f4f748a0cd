// The readers of the two recording formats behind ReadRecording (recording.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/io/recording.h"

namespace uuvplan::io::recording {

/// "#ROSBAG V2.0\n": a ROS 1 bag (wiki.ros.org/Bags/Format/2.0).
inline constexpr std::string_view kRosBagMagic = "#ROSBAG V2.0\n";
/// "\x89MCAP0\r\n": an MCAP file (mcap.dev/spec).
inline constexpr std::string_view kMcapMagic = "\x89MCAP0\r\n";

/// Puts the messages of `topic` in time order (stable: messages of one time keep theirs).
void SortByTime(RecordedTopic* topic);

/// Reads the bag `bytes` of `recording->path` into `recording` (messages of `wanted` only).
void ReadRosBag(std::string_view bytes, const std::vector<std::string>& wanted,
                Recording* recording);
/// Reads the MCAP `bytes` of `recording->path` into `recording` (messages of `wanted` only).
void ReadMcap(std::string_view bytes, const std::vector<std::string>& wanted, Recording* recording);

}  // namespace uuvplan::io::recording
