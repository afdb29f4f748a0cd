#include "recording/field_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

#include "uuvplan/model/input_error.h"

namespace uuvplan::io::recording {
namespace {

using model::InputError;

bool IsTimeStruct(const std::string& type) {
  return type == "builtin_interfaces/Time" || type == "builtin_interfaces/Duration";
}

bool StartsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

// The serialised bytes of one message, read in order (ROS 1 packed, or CDR aligned).
class Bytes {
 public:
  Bytes(std::string_view data, MessageEncoding encoding, long long epoch_s,
        const std::string& where)
      : data_(data), cdr_(encoding == MessageEncoding::kCdr), epoch_s_(epoch_s), where_(where) {
    if (!cdr_) return;
    Need(4);
    // CDR encapsulation (OMG DDS-XTypes 7.6.3.1.2): 00 00 big endian, 00 01 little endian.
    if (data_[0] != 0 || (data_[1] != 0 && data_[1] != 1)) {
      throw InputError(where_, "expected a CDR message (encapsulation 00 00 or 00 01), got kind " +
                                   std::to_string(int(data_[0])) + " " +
                                   std::to_string(int(data_[1])));
    }
    big_endian_ = data_[1] == 0;
    origin_ = pos_ = 4;
  }

  void Align(std::size_t n) {
    if (cdr_ && n > 1) pos_ += (n - (pos_ - origin_) % n) % n;
  }
  void Need(std::size_t n) const {
    if (pos_ + n > data_.size()) {
      throw InputError(where_, "expected a message of at least " + std::to_string(pos_ + n) +
                                   " bytes as its definition says, got " +
                                   std::to_string(data_.size()));
    }
  }
  std::size_t pos() const { return pos_; }
  std::size_t Remaining() const { return pos_ < data_.size() ? data_.size() - pos_ : 0; }
  void Skip(std::size_t n) {
    Need(n);
    pos_ += n;
  }

  template <typename T>
  T ReadAt(std::size_t at) const {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, data_.data() + at, sizeof(T));
    if (big_endian_) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }
  template <typename T>
  T Read() {
    Align(sizeof(T));
    Need(sizeof(T));
    const T value = ReadAt<T>(pos_);
    pos_ += sizeof(T);
    return value;
  }
  std::uint32_t Length() { return Read<std::uint32_t>(); }
  /// A time stamp (s and ns since 1970) as s after the recording's epoch.
  double Since(long long sec, std::uint32_t nsec) const {
    return double(sec - epoch_s_) + 1e-9 * nsec;
  }

  // A primitive of `type` at byte `at` (already aligned and within the message).
  double PrimitiveAt(const std::string& type, std::size_t at) const {
    if (type == "float64") return ReadAt<double>(at);
    if (type == "float32") return ReadAt<float>(at);
    if (type == "int64") return double(ReadAt<std::int64_t>(at));
    if (type == "uint64") return double(ReadAt<std::uint64_t>(at));
    if (type == "int32") return ReadAt<std::int32_t>(at);
    if (type == "uint32") return ReadAt<std::uint32_t>(at);
    if (type == "int16") return ReadAt<std::int16_t>(at);
    if (type == "uint16") return ReadAt<std::uint16_t>(at);
    if (type == "int8") return ReadAt<std::int8_t>(at);
    if (type == "time") return Since(ReadAt<std::uint32_t>(at), ReadAt<std::uint32_t>(at + 4));
    if (type == "duration") return ReadAt<std::int32_t>(at) + 1e-9 * ReadAt<std::int32_t>(at + 4);
    if (type == "byte" && !cdr_) return ReadAt<std::int8_t>(at);  // ROS 1 byte: int8
    return ReadAt<std::uint8_t>(at);  // bool, uint8, char; ROS 2 byte: an octet
  }
  // Alignment of a primitive: its size (ROS 1 time and duration are two 4-byte words).
  static std::size_t AlignmentOf(const std::string& type, int size) {
    return type == "time" || type == "duration" ? 4 : std::size_t(size);
  }

 private:
  std::string_view data_;
  bool cdr_;
  long long epoch_s_;
  bool big_endian_ = false;
  std::size_t origin_ = 0;
  std::size_t pos_ = 0;
  const std::string& where_;
};

// One walk through a message, storing the wanted fields' values.
class Walk {
 public:
  Walk(const MessageDefinitions& d, const std::vector<std::string>& fields, Bytes* in,
       std::vector<double>* out)
      : d_(d), fields_(fields), in_(*in), out_(*out) {}

  void Message(const std::string& type, const std::string& prefix) {
    for (const FieldDefinition& f : d_.types.at(type)) Field(f, prefix + f.name);
  }

 private:
  int Slot(const std::string& path) const {
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      if (fields_[i] == path) return int(i);
    }
    return -1;
  }

  void Field(const FieldDefinition& f, const std::string& path) {
    if (!f.array) return Value(f.type, path);
    const std::uint32_t n = f.fixed_length >= 0 ? std::uint32_t(f.fixed_length) : in_.Length();
    const int size = PrimitiveSize(f.type);
    if (size > 0) return PrimitiveArray(f.type, size, n, path);
    const std::size_t least = size == 0 ? 4 : d_.min_size.at(f.type);  // a string: its length
    if (least == 0) return;  // items of a type without fields take no bytes
    if (n > in_.Remaining() / least) in_.Need(std::size_t(n) * least);  // fails: too short
    for (std::uint32_t i = 0; i < n; ++i) Value(f.type, path + "[" + std::to_string(i) + "]");
  }

  // T[n] of a fixed-size primitive: contiguous after the first item's alignment.
  void PrimitiveArray(const std::string& type, int size, std::uint32_t n, const std::string& path) {
    if (n > 0) in_.Align(Bytes::AlignmentOf(type, size));
    const std::size_t start = in_.pos();
    in_.Skip(std::size_t(size) * n);
    const std::string item = path + "[";
    for (std::size_t j = 0; j < fields_.size(); ++j) {
      if (!StartsWith(fields_[j], item)) continue;
      const long k = std::strtol(fields_[j].c_str() + item.size(), nullptr, 10);
      if (k >= 0 && k < long(n)) out_[j] = in_.PrimitiveAt(type, start + std::size_t(k) * size);
    }
  }

  void Value(const std::string& type, const std::string& path) {
    const int size = PrimitiveSize(type);
    if (size == 0) return in_.Skip(in_.Length());  // string: length (with CDR's NUL), bytes
    if (size > 0) {
      in_.Align(Bytes::AlignmentOf(type, size));
      const std::size_t at = in_.pos();
      in_.Skip(std::size_t(size));
      const int slot = Slot(path);
      if (slot >= 0) out_[std::size_t(slot)] = in_.PrimitiveAt(type, at);
      return;
    }
    const int slot = IsTimeStruct(type) ? Slot(path) : -1;
    if (slot < 0) return Message(type, path + ".");
    const long long sec = in_.Read<std::int32_t>();  // builtin_interfaces/Time: sec, nanosec
    const std::uint32_t nanosec = in_.Read<std::uint32_t>();
    out_[std::size_t(slot)] =
        type == "builtin_interfaces/Time" ? in_.Since(sec, nanosec) : double(sec) + 1e-9 * nanosec;
  }

  const MessageDefinitions& d_;
  const std::vector<std::string>& fields_;
  Bytes& in_;
  std::vector<double>& out_;
};

// Numeric paths of `type` for an error message (`data[i]`, `twist.linear.x`), a few levels deep.
void NumericPaths(const MessageDefinitions& d, const std::string& type, const std::string& prefix,
                  int depth, std::vector<std::string>* paths) {
  for (const FieldDefinition& f : d.types.at(type)) {
    const std::string path = prefix + f.name + (f.array ? "[i]" : "");
    const int size = PrimitiveSize(f.type);
    if (size > 0 || IsTimeStruct(f.type)) {
      paths->push_back(path);
    } else if (size < 0 && depth < 4) {
      NumericPaths(d, f.type, path + ".", depth + 1, paths);
    }
  }
}

// "" when `path` names a number (or a time) of `type`, else what is wrong.
std::string PathFault(const MessageDefinitions& d, std::string type, const std::string& path) {
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = std::min(path.find('.', begin), path.size());
    std::string name = path.substr(begin, end - begin);
    const std::size_t bracket = name.find('[');
    const bool indexed = bracket != std::string::npos;
    long index = 0;
    if (indexed) {
      const std::string digits = name.substr(bracket + 1, name.size() - bracket - 2);
      if (name.back() != ']' || digits.empty() || digits.size() > 9 ||
          digits.find_first_not_of("0123456789") != std::string::npos ||
          (digits.size() > 1 && digits[0] == '0')) {
        return "'" + name + "' is not name[index] with a whole index";
      }
      index = std::stol(digits);
      name = name.substr(0, bracket);
    }
    const std::vector<FieldDefinition>& fields = d.types.at(type);
    auto f = std::find_if(fields.begin(), fields.end(),
                          [&](const FieldDefinition& x) { return x.name == name; });
    if (f == fields.end()) return type + " has no field '" + name + "'";
    if (f->array != indexed)
      return "'" + name + "' " + (f->array ? "needs" : "takes no") + " [index]";
    if (f->fixed_length >= 0 && index >= f->fixed_length) {
      return "'" + name + "' holds " + std::to_string(f->fixed_length) + " items";
    }
    const bool last = end == path.size();
    const int size = PrimitiveSize(f->type);
    if (last) {
      return size > 0 || IsTimeStruct(f->type) ? "" : "'" + name + "' is not a number";
    }
    if (size >= 0) return "'" + name + "' has no fields";
    type = f->type;
    begin = end + 1;
  }
}

std::string Joined(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& x : items) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

FieldDecoder::FieldDecoder(const RecordedTopic& topic, std::vector<std::string> fields,
                           long long epoch_s, const std::string& where)
    : definitions_(ParseDefinitions(topic.type, topic.definition, where)),
      encoding_(topic.encoding),
      epoch_s_(epoch_s),
      fields_(std::move(fields)) {
  for (const std::string& path : fields_) {
    const std::string fault = PathFault(definitions_, definitions_.root, path);
    if (fault.empty()) continue;
    std::vector<std::string> numeric;
    NumericPaths(definitions_, definitions_.root, "", 0, &numeric);
    throw InputError(where, "field '" + path + "': " + fault + "; the numeric fields of " +
                                definitions_.root + " are " + Joined(numeric));
  }
}

std::vector<double> FieldDecoder::Decode(std::string_view message, const std::string& where) const {
  std::vector<double> values(fields_.size(), std::numeric_limits<double>::quiet_NaN());
  Bytes in(message, encoding_, epoch_s_, where);
  Walk(definitions_, fields_, &in, &values).Message(definitions_.root, "");
  return values;
}

}  // namespace uuvplan::io::recording
