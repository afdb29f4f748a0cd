// ROS message definitions as a recording stores them (ROS 1 .msg text with its dependencies in
// "MSG: pkg/Type" sections after lines of '='; ROS 2 "ros2msg" schemas alike), parsed into the
// fields of each type (http://wiki.ros.org/msg, design.ros2.org "Interface definition").
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace uuvplan::io::recording {

struct FieldDefinition {
  std::string type;  ///< a primitive (float64, string, time...) or a message type pkg/Type
  std::string name;
  bool array = false;
  int fixed_length = -1;  ///< T[N]: N; T[] and T[<=N]: -1 (a length precedes the items)
};

/// A type's minimum size while it is being found (ParseDefinitions' cycle check).
inline constexpr std::size_t kUnknownSize = ~std::size_t(0);

struct MessageDefinitions {
  std::string root;  ///< the recorded type, pkg/Type
  std::map<std::string, std::vector<FieldDefinition>> types;
  /// The least bytes each type's value takes: 0 only for a type that is always empty.
  std::map<std::string, std::size_t> min_size;
};

/// "pkg/msg/Type" and "pkg/Type" name the same type: pkg/Type.
std::string NormalisedType(const std::string& type);

/// The bytes of a fixed-size primitive (bool 1 ... float64 8; ROS 1 time/duration 8), 0 for a
/// string and -1 for anything else (a message type).
int PrimitiveSize(const std::string& type);

/// Parses the definition `text` of message type `type`. A constant (`int32 X=1`) is no field;
/// an unknown type named by a field, a type that contains itself or nesting deeper than 64
/// levels is model::InputError naming `where`.
MessageDefinitions ParseDefinitions(const std::string& type, const std::string& text,
                                    const std::string& where);

}  // namespace uuvplan::io::recording
