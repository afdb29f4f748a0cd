#include "uuvplan/io/recording.h"

#include <algorithm>

#include "recording/field_decoder.h"
#include "recording/recording_parts.h"
#include "uuvplan/io/files.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {
namespace {

using model::InputError;

// `bytes` quoted, each byte that is no printable ASCII as \xNN.
std::string Printable(std::string_view bytes) {
  std::string s = "'";
  for (unsigned char c : bytes) {
    if (c >= 32 && c < 127) {
      s += char(c);
    } else {
      static const char* kHex = "0123456789abcdef";
      s += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
    }
  }
  return s + "'";
}

std::string TopicList(const Recording& r) {
  std::string list;
  for (const auto& [name, topic] : r.topics) {
    list += (list.empty() ? "" : ", ") + name + " (" + topic.type + ")";
  }
  return list.empty() ? "no topics" : list;
}

// `data[3]` → column `field.data3`; a time (…stamp) from ns to s (rostopic's plot format).
std::vector<std::vector<double>> CsvFieldValues(const RecordedTopic& t,
                                                const std::vector<std::string>& fields,
                                                long long epoch_s, const std::string& place) {
  std::vector<std::vector<double>> columns;
  for (const std::string& path : fields) {
    std::string name = "field.";
    for (char c : path) {
      if (c != '[' && c != ']') name += c;
    }
    const auto column = t.columns.find(name);
    if (column == t.columns.end()) {
      std::string names;
      for (const auto& c : t.columns) names += (names.empty() ? "" : ", ") + c.first;
      throw InputError(place,
                       "expected a column " + name + " for field '" + path + "', got " + names);
    }
    const bool time = name.size() >= 5 && name.compare(name.size() - 5, 5, "stamp") == 0;
    columns.push_back(column->second);
    if (time) {  // ns since 1970 (0.26 µs apart as a double) to s after the epoch
      for (double& x : columns.back()) x = (x - 1e9 * double(epoch_s)) * 1e-9;
    }
  }
  return columns;
}

}  // namespace

namespace recording {

void SortByTime(RecordedTopic* topic) {
  std::vector<double>& times = topic->times;
  if (std::is_sorted(times.begin(), times.end())) return;
  std::vector<std::size_t> order(times.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return times[a] < times[b]; });
  auto reorder = [&](auto* values) {
    if (values->size() != order.size()) return;
    auto copy = *values;
    for (std::size_t i = 0; i < order.size(); ++i) (*values)[i] = std::move(copy[order[i]]);
  };
  reorder(&topic->times);
  reorder(&topic->messages);
  for (auto& column : topic->columns) reorder(&column.second);
}

}  // namespace recording

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
        path, std::string("expected a ROS bag (format 2.0, '#ROSBAG V2.0') or an MCAP file, got ") +
                  (view.substr(0, 4) == "#ROS" ? "another bag version: " : "a file starting ") +
                  Printable(view.substr(0, 16)));
  }
  for (auto& named : r.topics) recording::SortByTime(&named.second);
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
  if (t->second.encoding == MessageEncoding::kCsv) {
    return CsvFieldValues(t->second, fields, recording.epoch_s, place);
  }
  const recording::FieldDecoder decoder(t->second, fields, recording.epoch_s, place);
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
