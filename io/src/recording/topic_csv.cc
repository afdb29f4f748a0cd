// `rostopic echo -p TOPIC > FILE.csv` (ROS 1 rostopic, its "plot" format): a header
// `%time,field.a,field.b.c,field.data0,...` and one row per message, `%time` the recorder's
// receipt time in ns, message fields flattened by path (arrays by index appended: data0), time
// fields in ns, strings as written.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "recording/recording_parts.h"
#include "uuvplan/io/files.h"
#include "uuvplan/io/recording.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {
namespace {

std::vector<std::string> CsvCells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

double CsvNumber(const std::string& cell) {
  char* end = nullptr;
  const double x = std::strtod(cell.c_str(), &end);
  return end != cell.c_str() && *end == '\0' ? x : NAN;
}

// `ns` since 1970 as s after `epoch_s` (the first time read sets it).
double SinceEpoch(long long ns, long long* epoch_s) {
  if (*epoch_s < 0) *epoch_s = ns / 1000000000;
  return double(ns - *epoch_s * 1000000000) * 1e-9;
}

RecordedTopic ReadTopicCsv(const std::string& path, long long* epoch_s) {
  std::istringstream in(ReadFileText(path));
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> names = CsvCells(line);
  if (names.empty() || names[0] != "%time") {
    throw model::InputError(path + ":1",
                            "expected a `rostopic echo -p` CSV (first column "
                            "%time), got '" +
                                line.substr(0, 60) + "'");
  }
  RecordedTopic t;
  t.type = "rostopic echo -p CSV";
  t.encoding = MessageEncoding::kCsv;
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> cells = CsvCells(line);
    char* end = nullptr;
    const long long ns = std::strtoll(cells[0].c_str(), &end, 10);
    if (cells.size() != names.size() || end == cells[0].c_str() || *end != '\0' || ns < 0) {
      throw model::InputError(path + ":" + std::to_string(number),
                              "expected " + std::to_string(names.size()) +
                                  " cells, the first a time in ns, got " +
                                  std::to_string(cells.size()) + " starting '" + cells[0] + "'");
    }
    t.times.push_back(SinceEpoch(ns, epoch_s));
    for (std::size_t k = 1; k < names.size(); ++k) {
      t.columns[names[k]].push_back(CsvNumber(cells[k]));
    }
  }
  return t;
}

}  // namespace

Recording ReadTopicCsvs(const std::string& dir, const std::map<std::string, std::string>& files) {
  Recording r;
  r.path = dir;
  r.format = "rostopic echo -p CSV";
  for (const auto& [topic, file] : files) {
    r.topics[topic] = ReadTopicCsv((std::filesystem::path(dir) / file).string(), &r.epoch_s);
  }
  for (auto& named : r.topics) recording::SortByTime(&named.second);
  return r;
}

}  // namespace uuvplan::io
