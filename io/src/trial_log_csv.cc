// Trial logs as CSV (contract §Trial log, docs/formats.md): lines starting with '#' are
// comments, the first other line is the header, then one row per time with as many
// comma-separated cells as the header (no quoting). Known columns are t, force_<dof>,
// pos_<dof>, vel_<dof>, cmd_<thruster> and mapping; any other column is ignored with a note. An
// empty cell is a missing sample (NaN; -1 in the mapping column). Angles (pos_roll/pitch/yaw) are
// unwrapped.
//
// The reader streams the file through a fixed buffer and stores only the known columns, so a
// log of a million rows costs little more than its numbers (bench/csv_read_bench.cc).
#include "uuvplan/io/trial_log_csv.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/io/number_text.h"
#include "uuvplan/io/place.h"
#include "uuvplan/model/commanded_force.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/numbers.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/work_limits.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the trial log

namespace {

using model::kNaN;
constexpr std::size_t kChunkBytes = std::size_t{1} << 20;

// The read buffer for `path`: a chunk, or less for a smaller file (a campaign of 100 logs of
// 90 kB spent a third of its time zeroing and faulting in two 1 MiB buffers per log).
std::size_t ChunkFor(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return kChunkBytes;
  return static_cast<std::size_t>(
      std::min<std::uintmax_t>(kChunkBytes, std::max<std::uintmax_t>(4096, size + 1)));
}
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// Comment ('#' first) and blank lines carry no data and may appear anywhere.
bool IsSkipped(std::string_view line) {
  const std::string_view s = TrimBlanks(line);
  return s.empty() || s.front() == '#';
}

// A fault of the row at `line` of `path` as a whole.
[[noreturn]] void Fail(const std::string& path, int line, const std::string& what) {
  Place(path, line, "").Fail(what);
}

// A cell as the message quotes it: at most 40 characters.
std::string Quoted(std::string_view cell) {
  constexpr std::size_t kMax = 40;
  return "'" + std::string(cell.substr(0, kMax)) + (cell.size() > kMax ? "...'" : "'");
}

std::FILE* OpenForReading(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    Place(path, 0, "").Fail("cannot open file: " + std::string(std::strerror(errno)));
  }
  return file;
}

// Reads a file line by line through one buffer that grows only for a line longer than it.
// The view returned by Next() stays valid until the following call.
class LineReader {
 public:
  explicit LineReader(const std::string& path)
      : path_(path), file_(OpenForReading(path)), buffer_(ChunkFor(path)) {}
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
      Place(path_, 0, "").Fail("read error: " + std::string(std::strerror(errno)));
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
  std::vector<char> chunk(ChunkFor(path));
  std::size_t count = 0;
  std::size_t n;
  while ((n = std::fread(chunk.data(), 1, chunk.size(), file)) > 0) {
    count += static_cast<std::size_t>(std::count(chunk.data(), chunk.data() + n, '\n'));
  }
  std::fclose(file);
  return count;
}

class TrialLogParser {
 public:
  TrialLogParser(const std::string& path, const std::vector<std::string>* allowed_mappings)
      : path_(path), allowed_mappings_(allowed_mappings) {}

  TrialLog Parse() {
    const std::size_t max_rows = CountNewlines(path_) + 1;
    if (static_cast<double>(max_rows) > model::limits::kMaxLogRows) {
      Place(path_, 0, "")
          .Fail(std::to_string(max_rows) + " lines, more than the " +
                Significant(model::limits::kMaxLogRows, 3) +
                " rows a trial log may have: split the trial");
    }
    LineReader reader(path_);
    std::string_view line;
    bool has_header = false;
    while (!has_header && reader.Next(&line)) has_header = !IsSkipped(line);
    if (!has_header) {
      Place(path_, 0, "")
          .Fail(
              "empty file: expected a header line such as 't,force_surge,vel_surge' followed by "
              "data rows");
    }
    const int header_line = reader.line_number();
    // A UTF-8 byte order mark (spreadsheet exports) is not part of the first column's name.
    if (header_line == 1 && StartsWith(line, kByteOrderMark))
      line.remove_prefix(kByteOrderMark.size());
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
    // A thruster's command: the reader does not know the vehicle; ForceFromCommands checks
    // the name (a map's values keep their address as others are added).
    constexpr std::string_view kCommand = "cmd_";
    if (name.size() > kCommand.size() && name.substr(0, kCommand.size()) == kCommand) {
      return &log_.commands[std::string(name.substr(kCommand.size()))];
    }
    return nullptr;
  }

  void ReadHeader(std::string_view line, int line_number) {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      AddColumn(std::string(TrimBlanks(line.substr(start, comma - start))), line_number);
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    const bool has_time = std::any_of(columns_.begin(), columns_.end(),
                                      [](const Column& c) { return c.kind == Kind::kTime; });
    if (has_time) return;
    const bool any_known = std::any_of(columns_.begin(), columns_.end(),
                                       [](const Column& c) { return c.kind != Kind::kIgnored; });
    // A file that is no trial log at all is not quoted back (it may be anything).
    if (!any_known) {
      Place(path_, line_number, "header")
          .Expected("a 't' column (time, s)",
                    "no known column among " + std::to_string(columns_.size()) +
                        " (is this a trial log? a header such as 't,force_surge,vel_surge')");
    }
    std::vector<std::string> names;
    for (const Column& c : columns_) names.push_back(Quoted(c.name));
    Place(path_, line_number, "header")
        .Expected("a 't' column (time, s)", "columns " + Join(names));
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
          Place(path_, line_number, "header").Fail("column '" + name + "' appears twice");
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

  // The place of a cell of column `name`.
  Place Cell(const std::string& name, int line_number) const {
    return Place(path_, line_number, "column '" + name + "'");
  }

  [[noreturn]] void WrongCellCount(std::size_t cells, int line_number) const {
    Fail(path_, line_number,
         "expected " + std::to_string(columns_.size()) + " cells as in the header, got " +
             std::to_string(cells));
  }

  void Store(const Column& column, std::string_view raw, int line_number) {
    switch (column.kind) {
      case Kind::kNumber:
        StoreNumber(column, TrimBlanks(raw), line_number);
        break;
      case Kind::kTime:
        StoreTime(TrimBlanks(raw), line_number);
        break;
      case Kind::kMapping:
        StoreMapping(TrimBlanks(raw), line_number);
        break;
      case Kind::kIgnored:
        break;
    }
  }

  void StoreNumber(const Column& column, std::string_view cell, int line_number) {
    double value = kNaN;
    if (!cell.empty() && !ParseNumber(cell, &value)) {
      Cell(column.name, line_number).Expected("a number or an empty cell", Quoted(cell));
    }
    column.values->push_back(value);
  }

  // t is never empty and strictly increases (contract §Trial log).
  void StoreTime(std::string_view cell, int line_number) {
    double t;
    if (!ParseNumber(cell, &t)) {
      Cell("t", line_number).Expected("a time (s)", cell.empty() ? "an empty cell" : Quoted(cell));
    }
    if (!log_.t.empty() && !(t > log_.t.back())) {
      Cell("t", line_number)
          .Expected("a time after the previous row's " + ShortestNumber(log_.t.back()) +
                        " (times must strictly increase)",
                    Quoted(cell));
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
      Cell("mapping", line_number)
          .Expected(
              "a mapping of the vehicle on the trial's DOF (" + Join(*allowed_mappings_) + ")",
              Quoted(name));
    }
    log_.mapping_names.emplace_back(name);
  }

  const std::string path_;
  const std::vector<std::string>* allowed_mappings_;
  std::vector<Column> columns_;
  TrialLog log_;
  int last_mapping_ = -1;
};

}  // namespace

TrialLog ReadTrialLog(const std::string& path) { return TrialLogParser(path, nullptr).Parse(); }

TrialLog ReadTrialLog(const std::string& path, const std::vector<std::string>& mappings) {
  return TrialLogParser(path, &mappings).Parse();
}

TrialLog ReadTrialOf(const std::string& path, const Vehicle& vehicle, Dof dof,
                     const std::string& mapping) {
  std::vector<std::string> mappings;
  for (int i : vehicle.MappingsOf(dof)) mappings.push_back(vehicle.mappings[i].name);
  TrialLog log = ReadTrialLog(path, mappings);
  if (log.HasAnyForce()) {  // the force as logged: cmd_ columns are other columns then
    for (const auto& [name, values] : log.commands) {
      log.notes.push_back("ignored column 'cmd_" + name + "' (the log gives force_ columns)");
    }
    log.commands.clear();
  }
  ForceFromCommands(vehicle, dof, mapping, path, &log);
  return log;
}

}  // namespace uuvplan::io
