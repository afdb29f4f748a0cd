#include "uuvplan/io/recording.h"

#include "recording/field_decoder.h"
#include "recording/recording_parts.h"
#include "uuvplan/io/files.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {
namespace {

using model::InputError;

std::string TopicList(const Recording& r) {
  std::string list;
  for (const auto& [name, topic] : r.topics) {
    list += (list.empty() ? "" : ", ") + name + " (" + topic.type + ")";
  }
  return list.empty() ? "no topics" : list;
}

}  // namespace

Recording ReadRecording(const std::string& path, const std::vector<std::string>& wanted) {
  const std::string bytes = ReadFileText(path);
  Recording r;
  r.path = path;
  const std::string_view view(bytes);
  if (view.substr(0, recording::kRosBagMagic.size()) == recording::kRosBagMagic) {
    recording::ReadRosBag(view, wanted, &r);
  } else if (view.substr(0, recording::kMcapMagic.size()) == recording::kMcapMagic) {
    recording::ReadMcap(view, wanted, &r);
  } else {
    throw InputError(
        path, "expected a ROS bag (format 2.0, '#ROSBAG V2.0') or an MCAP file, got " +
                  std::string(view.substr(0, 4) == "#ROS" ? "another bag version" : "neither"));
  }
  return r;
}

std::vector<std::vector<double>> FieldValues(const Recording& recording, const std::string& topic,
                                             const std::vector<std::string>& fields,
                                             const std::string& where) {
  const auto t = recording.topics.find(topic);
  if (t == recording.topics.end()) {
    throw InputError(where, "expected topic " + topic + " in " + recording.path + ", which has " +
                                TopicList(recording));
  }
  const std::string place = where + ": " + recording.path + ": topic " + topic;
  const recording::FieldDecoder decoder(t->second, fields, place);
  std::vector<std::vector<double>> columns(fields.size());
  for (auto& column : columns) column.reserve(t->second.messages.size());
  for (std::size_t i = 0; i < t->second.messages.size(); ++i) {
    std::vector<double> values;
    try {
      values = decoder.Decode(t->second.messages[i], place);
    } catch (const InputError& e) {  // "<place>: <what>" becomes "<place>: message i: <what>"
      const std::string what = e.what();
      const bool placed = what.rfind(place + ": ", 0) == 0;
      throw InputError(place + ": message " + std::to_string(i + 1),
                       placed ? what.substr(place.size() + 2) : what);
    }
    for (std::size_t j = 0; j < fields.size(); ++j) columns[j].push_back(values[j]);
  }
  return columns;
}

}  // namespace uuvplan::io
