// Trial logs as CSV (contract §Trial log, docs/formats.md): lines starting with '#' are
// comments, the first other line is the header, then one row per time with as many
// comma-separated cells as the header (no quoting). Known columns are t, force_<dof>,
// pos_<dof>, vel_<dof> and mapping; any other column is ignored with a note. An empty cell is
// a missing sample (NaN; -1 in the mapping column). Angles (pos_roll/pitch/yaw) are unwrapped.
//
// The reader streams the file through a fixed buffer and stores only the known columns, so a
// log of a million rows costs little more than its numbers (bench/csv_read_bench.cc).
#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/model/input_error.h"
#include "uuvplan/model/io.h"

namespace uuvplan::model {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kChunkBytes = std::size_t{1} << 20;

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

// Comment ('#' first) and blank lines carry no data and may appear anywhere.
bool IsSkipped(std::string_view line) {
  const std::string_view s = Trim(line);
  return s.empty() || s.front() == '#';
}

// Parses a whole cell as a finite number (an optional leading '+' is allowed; NaN and
// infinities are not numbers here). False if the cell is anything else.
bool ParseNumber(std::string_view cell, double* value) {
  const char* first = cell.data();
  const char* last = first + cell.size();
  if (first != last && *first == '+') {
    ++first;
    if (first != last && *first == '-') return false;
  }
  const auto [end, ec] = std::from_chars(first, last, *value);
  return ec == std::errc() && end == last && first != last && std::isfinite(*value);
}

[[noreturn]] void Fail(const std::string& path, int line, const std::string& what) {
  throw InputError(path + ":" + std::to_string(line), what);
}

std::FILE* OpenForReading(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    throw InputError(path, "cannot open file: " + std::string(std::strerror(errno)));
  }
  return file;
}

// Reads a file line by line through one buffer that grows only for a line longer than it.
// The view returned by Next() stays valid until the following call.
class LineReader {
 public:
  explicit LineReader(const std::string& path)
      : path_(path), file_(OpenForReading(path)), buffer_(kChunkBytes) {}
  ~LineReader() { std::fclose(file_); }
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  /// The next line without its end of line; false at the end of the file.
  bool Next(std::string_view* line) {
    while (true) {
      const char* begin = buffer_.data() + begin_;
      const auto* newline = static_cast<const char*>(std::memchr(begin, '\n', end_ - begin_));
      if (newline != nullptr || (at_eof_ && begin_ < end_)) {
        const char* stop = newline != nullptr ? newline : buffer_.data() + end_;
        *line = std::string_view(begin, static_cast<std::size_t>(stop - begin));
        if (!line->empty() && line->back() == '\r') line->remove_suffix(1);
        begin_ = static_cast<std::size_t>(stop - buffer_.data()) + (newline != nullptr ? 1 : 0);
        ++line_number_;
        return true;
      }
      if (at_eof_) return false;
      Refill();
    }
  }
  int line_number() const { return line_number_; }

 private:
  // Keeps the partial line at the front of the buffer and appends the next chunk of the file.
  void Refill() {
    const std::size_t partial = end_ - begin_;
    std::memmove(buffer_.data(), buffer_.data() + begin_, partial);
    begin_ = 0;
    end_ = partial;
    if (end_ == buffer_.size()) buffer_.resize(2 * buffer_.size());
    const std::size_t n = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_);
    if (n == 0 && std::ferror(file_)) {
      throw InputError(path_, "read error: " + std::string(std::strerror(errno)));
    }
    end_ += n;
    at_eof_ = n == 0;
  }

  std::string path_;
  std::FILE* file_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;  // first unread byte
  std::size_t end_ = 0;    // end of the bytes read so far
  bool at_eof_ = false;
  int line_number_ = 0;
};

// Number of '\n' in the file: an upper bound on its rows, so that columns are reserved once
// instead of growing (growth would briefly hold two copies of every column).
std::size_t CountNewlines(const std::string& path) {
  std::FILE* file = OpenForReading(path);
  std::vector<char> chunk(kChunkBytes);
  std::size_t count = 0;
  std::size_t n;
  while ((n = std::fread(chunk.data(), 1, chunk.size(), file)) > 0) {
    count += static_cast<std::size_t>(std::count(chunk.data(), chunk.data() + n, '\n'));
  }
  std::fclose(file);
  return count;
}

// Undoes the wrapping of an angle to (-pi, pi]: wherever two consecutive samples (empty cells
// skipped) differ by more than pi, this and all later samples are shifted by the multiple of
// 2·pi that brings the step back within pi. Returns the number of such jumps.
int Unwrap(std::vector<double>* angle) {
  double previous = kNaN;
  double offset = 0.0;
  int jumps = 0;
  for (double& x : *angle) {
    if (std::isnan(x)) continue;
    const double raw = x;
    const double step = raw - previous;
    if (std::abs(step) > kPi) {  // false while `previous` is NaN
      offset -= 2.0 * kPi * std::round(step / (2.0 * kPi));
      ++jumps;
    }
    previous = raw;
    x = raw + offset;
  }
  return jumps;
}

}  // namespace

void UnwrapAngles(TrialLog* log) {
  for (Dof dof : {Dof::kRoll, Dof::kPitch, Dof::kYaw}) {
    const int jumps = Unwrap(&log->position[Index(dof)]);
    if (jumps > 0) {
      log->notes.push_back("unwrapped pos_" + std::string(DofName(dof)) + ": " +
                           std::to_string(jumps) + " jump(s) of more than pi rad");
    }
  }
}

namespace {

class TrialLogParser {
 public:
  TrialLogParser(const std::string& path, const std::vector<std::string>* allowed_mappings)
      : path_(path), allowed_mappings_(allowed_mappings) {}

  TrialLog Parse() {
    const std::size_t max_rows = CountNewlines(path_) + 1;
    LineReader reader(path_);
    std::string_view line;
    bool has_header = false;
    while (!has_header && reader.Next(&line)) has_header = !IsSkipped(line);
    if (!has_header) {
      throw InputError(path_,
                       "empty file: expected a header line such as "
                       "'t,force_surge,vel_surge' followed by data rows");
    }
    const int header_line = reader.line_number();
    ReadHeader(line, header_line);
    Reserve(max_rows);
    while (reader.Next(&line)) {
      if (!IsSkipped(line)) ReadRow(line, reader.line_number());
    }
    if (log_.t.empty()) {
      Fail(path_, header_line, "no data rows after the header: expected at least one row");
    }
    model::UnwrapAngles(&log_);
    return std::move(log_);
  }

 private:
  enum class Kind { kTime, kNumber, kMapping, kIgnored };
  struct Column {
    std::string name;
    Kind kind = Kind::kIgnored;
    std::vector<double>* values = nullptr;  // kTime, kNumber
  };

  // The storage of a known numeric column, or nullptr for an unknown name.
  std::vector<double>* NumericColumn(std::string_view name) {
    if (name == "t") return &log_.t;
    struct Prefix {
      std::string_view text;
      std::array<std::vector<double>, kNumDofs>* columns;
    };
    for (const Prefix& p : {Prefix{"force_", &log_.force}, Prefix{"pos_", &log_.position},
                            Prefix{"vel_", &log_.velocity}}) {
      if (name.substr(0, p.text.size()) != p.text) continue;
      if (auto dof = ParseDof(name.substr(p.text.size()))) return &(*p.columns)[Index(*dof)];
    }
    return nullptr;
  }

  void ReadHeader(std::string_view line, int line_number) {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      AddColumn(std::string(Trim(line.substr(start, comma - start))), line_number);
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    const bool has_time = std::any_of(columns_.begin(), columns_.end(),
                                      [](const Column& c) { return c.kind == Kind::kTime; });
    if (!has_time) {
      std::string names;
      for (const Column& c : columns_) names += (names.empty() ? "'" : ", '") + c.name + "'";
      Fail(path_, line_number, "header: expected a 't' column (time, s), got columns " + names);
    }
  }

  void AddColumn(std::string name, int line_number) {
    Column column;
    column.values = NumericColumn(name);
    column.kind = column.values == &log_.t   ? Kind::kTime
                  : column.values != nullptr ? Kind::kNumber
                  : name == "mapping"        ? Kind::kMapping
                                             : Kind::kIgnored;
    if (column.kind == Kind::kIgnored) {
      log_.notes.push_back("ignored column '" + name + "'");
    } else {
      for (const Column& other : columns_) {
        if (other.name == name) {
          Fail(path_, line_number, "header: column '" + name + "' appears twice");
        }
      }
    }
    column.name = std::move(name);
    columns_.push_back(std::move(column));
  }

  void Reserve(std::size_t rows) {
    for (Column& c : columns_) {
      if (c.values != nullptr) c.values->reserve(rows);
      if (c.kind == Kind::kMapping) log_.mapping.reserve(rows);
    }
  }

  void ReadRow(std::string_view line, int line_number) {
    const char* cell = line.data();
    const char* const end = cell + line.size();
    std::size_t index = 0;
    while (true) {
      const auto* comma = static_cast<const char*>(std::memchr(cell, ',', end - cell));
      const char* stop = comma != nullptr ? comma : end;
      if (index == columns_.size()) {
        const auto more = static_cast<std::size_t>(std::count(stop, end, ','));
        WrongCellCount(columns_.size() + 1 + more, line_number);
      }
      Store(columns_[index], std::string_view(cell, static_cast<std::size_t>(stop - cell)),
            line_number);
      ++index;
      if (comma == nullptr) break;
      cell = comma + 1;
    }
    if (index != columns_.size()) WrongCellCount(index, line_number);
  }

  [[noreturn]] void WrongCellCount(std::size_t cells, int line_number) const {
    Fail(path_, line_number,
         "expected " + std::to_string(columns_.size()) + " cells as in the header, got " +
             std::to_string(cells));
  }

  void Store(const Column& column, std::string_view raw, int line_number) {
    switch (column.kind) {
      case Kind::kNumber:
        StoreNumber(column, Trim(raw), line_number);
        break;
      case Kind::kTime:
        StoreTime(Trim(raw), line_number);
        break;
      case Kind::kMapping:
        StoreMapping(Trim(raw), line_number);
        break;
      case Kind::kIgnored:
        break;
    }
  }

  void StoreNumber(const Column& column, std::string_view cell, int line_number) {
    double value = kNaN;
    if (!cell.empty() && !ParseNumber(cell, &value)) {
      Fail(path_, line_number,
           "column '" + column.name + "': expected a number or an empty cell, got '" +
               std::string(cell) + "'");
    }
    column.values->push_back(value);
  }

  // t is never empty and strictly increases (contract §Trial log).
  void StoreTime(std::string_view cell, int line_number) {
    double t;
    if (!ParseNumber(cell, &t)) {
      Fail(path_, line_number,
           "column 't': expected a time (s), got " +
               (cell.empty() ? std::string("an empty cell") : "'" + std::string(cell) + "'"));
    }
    if (!log_.t.empty() && !(t > log_.t.back())) {
      char previous[32];
      const auto [end, ec] = std::to_chars(previous, previous + sizeof previous, log_.t.back());
      Fail(path_, line_number,
           "column 't': expected a time after the previous row's " + std::string(previous, end) +
               " (times must strictly increase), got '" + std::string(cell) + "'");
    }
    log_.t.push_back(t);
  }

  // Mapping names are few; the row usually repeats the previous row's mapping.
  void StoreMapping(std::string_view cell, int line_number) {
    if (cell.empty()) {
      log_.mapping.push_back(-1);
      return;
    }
    if (last_mapping_ < 0 || log_.mapping_names[last_mapping_] != cell) {
      const auto& names = log_.mapping_names;
      const auto it = std::find(names.begin(), names.end(), cell);
      last_mapping_ = static_cast<int>(it - names.begin());
      if (it == names.end()) AddMappingName(cell, line_number);
    }
    log_.mapping.push_back(last_mapping_);
  }

  void AddMappingName(std::string_view name, int line_number) {
    if (allowed_mappings_ != nullptr &&
        std::find(allowed_mappings_->begin(), allowed_mappings_->end(), name) ==
            allowed_mappings_->end()) {
      std::string allowed;
      for (const std::string& m : *allowed_mappings_) allowed += (allowed.empty() ? "" : ", ") + m;
      Fail(path_, line_number,
           "column 'mapping': expected a mapping of the vehicle on the "
           "trial's DOF (" +
               allowed + "), got '" + std::string(name) + "'");
    }
    log_.mapping_names.emplace_back(name);
  }


  const std::string path_;
  const std::vector<std::string>* allowed_mappings_;
  std::vector<Column> columns_;
  TrialLog log_;
  int last_mapping_ = -1;
};

// ---------------------------------------------------------------------------------------------
// Writing.

// Appends `value` as %.<digits>g would, without the locale.
void AppendNumber(double value, int digits, std::string* out) {
  char buffer[32];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  out->append(buffer, end);
}

// Appends the shortest text that reads back as exactly `value`.
void AppendExact(double value, std::string* out) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out->append(buffer, end);
}

constexpr int kDigits = 10;

// Times are written with kDigits significant digits when that keeps them strictly increasing
// (the written value must lie between the previous written time and the next exact time),
// and exactly otherwise. Returns the value that will be read back.
double AppendTime(double t, double previous_written, double next, std::string* out) {
  char buffer[32];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, t, std::chars_format::general, kDigits);
  double rounded;
  std::from_chars(buffer, end, rounded);
  if (rounded > previous_written && rounded < next) {
    out->append(buffer, end);
    return rounded;
  }
  AppendExact(t, out);
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
    if (name.empty() || name.find_first_of(",\n\r") != std::string::npos || Trim(name) != name) {
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

TrialLog ReadTrialLog(const std::string& path) { return TrialLogParser(path, nullptr).Parse(); }

TrialLog ReadTrialLog(const std::string& path, const std::vector<std::string>& mappings) {
  return TrialLogParser(path, &mappings).Parse();
}

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
      if (!std::isnan(v)) AppendNumber(v, kDigits, &text);
    }
    if (has_mapping) {
      text += ',';
      if (log.mapping[i] >= 0) text += log.mapping_names[log.mapping[i]];
    }
    text += '\n';
  }
  WriteFileAtomically(path, text);
}

}  // namespace uuvplan::model
