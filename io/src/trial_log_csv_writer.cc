// Writing trial logs as CSV (contract §Trial log): numbers with 10 significant digits, times
// as many as keep them strictly increasing, empty cells for missing samples; every log written
// reads back (trial_log_csv.cc).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "uuvplan/io/files.h"
#include "uuvplan/io/number_text.h"
#include "uuvplan/io/trial_log_csv.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the trial log

namespace {

constexpr int kDigits = 10;

// Times are written with kDigits significant digits when that keeps them strictly increasing
// (the written value must lie between the previous written time and the next exact time),
// and exactly otherwise. Returns the value that will be read back.
double AppendTime(double t, double previous_written, double next, std::string* out) {
  std::string text;
  AppendGeneral(t, kDigits, &text);
  double rounded;
  std::from_chars(text.data(), text.data() + text.size(), rounded);
  if (rounded > previous_written && rounded < next) {
    out->append(text);
    return rounded;
  }
  out->append(ShortestNumber(t));
  return t;
}

struct OutputColumn {
  std::string name;
  const std::vector<double>* values;
};

std::vector<OutputColumn> OutputColumns(const std::string& path, const TrialLog& log) {
  std::vector<OutputColumn> columns;
  for (Dof dof : kAllDofs) {
    const std::string name(DofName(dof));
    const int i = Index(dof);
    for (const OutputColumn& c : {OutputColumn{"force_" + name, &log.force[i]},
                                  OutputColumn{"pos_" + name, &log.position[i]},
                                  OutputColumn{"vel_" + name, &log.velocity[i]}}) {
      if (c.values->empty()) continue;
      if (c.values->size() != log.size()) {
        throw std::invalid_argument("WriteTrialLog " + path + ": column " + c.name + " has " +
                                    std::to_string(c.values->size()) + " values for " +
                                    std::to_string(log.size()) + " times");
      }
      columns.push_back(c);
    }
  }
  for (const auto& [thruster, values] : log.commands) {
    if (thruster.empty() || thruster.find_first_of(",\n\r") != std::string::npos) {
      throw std::invalid_argument("WriteTrialLog " + path + ": thruster name '" + thruster +
                                  "' cannot be written in a CSV header");
    }
    if (values.size() != log.size()) {
      throw std::invalid_argument("WriteTrialLog " + path + ": column cmd_" + thruster + " has " +
                                  std::to_string(values.size()) + " values for " +
                                  std::to_string(log.size()) + " times");
    }
    columns.push_back({"cmd_" + thruster, &values});
  }
  return columns;
}

// The writer refuses what the reader would reject, so that every log it writes reads back.
void CheckWritable(const std::string& path, const TrialLog& log,
                   const std::vector<OutputColumn>& columns) {
  const auto fail = [&path](const std::string& what) {
    throw std::invalid_argument("WriteTrialLog " + path + ": " + what);
  };
  if (log.t.empty()) fail("no rows");
  for (std::size_t i = 0; i < log.t.size(); ++i) {
    if (!std::isfinite(log.t[i]) || (i > 0 && !(log.t[i] > log.t[i - 1]))) {
      fail("t must be finite and strictly increasing (row " + std::to_string(i) + ")");
    }
  }
  for (const OutputColumn& c : columns) {
    if (std::any_of(c.values->begin(), c.values->end(), [](double v) { return std::isinf(v); })) {
      fail("column " + c.name + " holds an infinite value");
    }
  }
  if (log.mapping.empty()) return;
  if (log.mapping.size() != log.size()) fail("mapping column has the wrong length");
  for (int m : log.mapping) {
    if (m < -1 || m >= static_cast<int>(log.mapping_names.size())) fail("bad mapping index");
  }
  for (const std::string& name : log.mapping_names) {
    if (name.empty() || name.find_first_of(",\n\r") != std::string::npos ||
        TrimBlanks(name) != name) {
      fail("mapping name '" + name + "' cannot be written in a CSV cell");
    }
  }
}

void AppendComment(const std::string& comment, std::string* out) {
  if (comment.empty()) return;
  std::size_t start = 0;
  while (start < comment.size()) {
    const std::size_t newline = std::min(comment.find('\n', start), comment.size());
    out->append("# ").append(comment, start, newline - start).push_back('\n');
    start = newline + 1;
  }
}

}  // namespace

void WriteTrialLog(const std::string& path, const TrialLog& log, const std::string& comment) {
  const std::vector<OutputColumn> columns = OutputColumns(path, log);
  CheckWritable(path, log, columns);
  const bool has_mapping = !log.mapping.empty();

  std::string text;
  text.reserve(log.size() * (columns.size() + 2) * (kDigits + 4) + comment.size() + 256);
  AppendComment(comment, &text);
  text += "t";
  for (const OutputColumn& c : columns) text += "," + c.name;
  text += has_mapping ? ",mapping\n" : "\n";

  double previous = -std::numeric_limits<double>::infinity();
  const double kEnd = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < log.size(); ++i) {
    previous = AppendTime(log.t[i], previous, i + 1 < log.size() ? log.t[i + 1] : kEnd, &text);
    for (const OutputColumn& c : columns) {
      text += ',';
      const double v = (*c.values)[i];
      if (!std::isnan(v)) AppendGeneral(v, kDigits, &text);
    }
    if (has_mapping) {
      text += ',';
      if (log.mapping[i] >= 0) text += log.mapping_names[log.mapping[i]];
    }
    text += '\n';
  }
  WriteFileAtomically(path, text);
}

}  // namespace uuvplan::io
