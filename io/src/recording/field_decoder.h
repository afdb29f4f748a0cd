// Reads named numeric fields out of serialised ROS messages: ROS 1 serialisation (packed little
// endian; strings and T[] a uint32 length first; wiki.ros.org/msg "Serialization") and CDR
// (OMG CDR / XCDR1 as ROS 2 writes it: a 4-byte encapsulation header, then every primitive
// aligned to its size counted from the header's end).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "recording/message_definition.h"
#include "uuvplan/io/recording.h"

namespace uuvplan::io::recording {

class FieldDecoder {
 public:
  /// The decoder of `fields` (paths such as `data[3]`, `twist.linear.x`, `header.stamp`: a time
  /// in s after `epoch_s`, the recording's) of the messages of `topic`; a path that names no number
  /// is model::InputError naming `where` with the numeric fields the type has.
  FieldDecoder(const RecordedTopic& topic, std::vector<std::string> fields, long long epoch_s,
               const std::string& where);

  /// The fields' values in one message (NaN for an index beyond a variable array's length);
  /// a message shorter than its definition is model::InputError naming `where`.
  std::vector<double> Decode(std::string_view message, const std::string& where) const;

 private:
  MessageDefinitions definitions_;
  MessageEncoding encoding_;
  long long epoch_s_;
  std::vector<std::string> fields_;
};

}  // namespace uuvplan::io::recording
