// A recording as a robot's logger writes it: a ROS 1 bag (format 2.0, chunks uncompressed, bz2
// or lz4) or an MCAP file (ROS 2 CDR or ROS 1 messages; chunks uncompressed, lz4 or zstd), read
// natively, or the CSV files `rostopic echo -p` exports, one per topic. Each topic keeps its
// type, the message definition stored in the file and every message's recorder time and bytes
// (a CSV topic: its columns); FieldValues reads named numeric fields from them.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace uuvplan::io {

/// How a topic's messages are serialised: ROS 1 (packed little endian), CDR (ROS 2), or
/// already flattened into the columns of a `rostopic echo -p` CSV.
enum class MessageEncoding { kRos1, kCdr, kCsv };

struct RecordedTopic {
  std::string type;        ///< message type as recorded, e.g. std_msgs/UInt16MultiArray
  std::string definition;  ///< message definition text stored in the recording
  MessageEncoding encoding = MessageEncoding::kRos1;
  std::vector<double> times;          ///< recorder (log) time of each message, s after epoch_s
  std::vector<std::string> messages;  ///< each message's serialised bytes
  /// kCsv: the columns by name (`field.data3`, `field.twist.linear.x`), a value per message.
  std::map<std::string, std::vector<double>> columns;
};

struct Recording {
  std::string path;
  std::string format;  ///< "ROS bag 2.0", "MCAP" or "rostopic echo -p CSV"
  /// Whole s since 1970 of the first message: times are kept from it, so that a double holds
  /// them to the ns (counted from 1970 it would round them to 0.24 µs).
  long long epoch_s = -1;
  std::map<std::string, RecordedTopic> topics;  ///< by topic name; messages only of `wanted`
};

/// Reads the ROS bag or MCAP file at `path` (told apart by their magic bytes). Every topic is
/// listed; messages are kept for the topics in `wanted` only, in time order (a recording may
/// store them otherwise). Faults are model::InputError naming the file and the byte offset.
Recording ReadRecording(const std::string& path, const std::vector<std::string>& wanted);

/// The `rostopic echo -p` CSV exports in `dir`, by topic (`files`: topic → file name in dir):
/// `%time` (ns) is the recorder time, `field.<path>` each field, arrays flattened (`data3`),
/// times in ns. A cell that is no number (a frame id) is read as missing.
Recording ReadTopicCsvs(const std::string& dir, const std::map<std::string, std::string>& files);

/// The numeric fields `fields` of every message of `topic`: one column per field, one row per
/// message. A field is a path through the message definition: `data[3]`, `twist.linear.x`,
/// `header.stamp` (a time is read in s after epoch_s). Unknown topics and fields are
/// model::InputError naming `where`, the recording and what it holds.
std::vector<std::vector<double>> FieldValues(const Recording& recording, const std::string& topic,
                                             const std::vector<std::string>& fields,
                                             const std::string& where);

}  // namespace uuvplan::io
