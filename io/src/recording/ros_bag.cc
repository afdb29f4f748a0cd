// ROS bag format 2.0 (wiki.ros.org/Bags/Format/2.0): after the magic line, records of
// (uint32 header_len, header, uint32 data_len, data); a header is a run of (uint32 len,
// "name=value") fields whose `op` byte names the record. Read in file order: connection records
// (0x07) define topics, message data records (0x02) hold messages, chunks (0x05) hold both,
// stored or compressed (bz2, lz4); index records (0x04, 0x06) and the bag header (0x03) add
// nothing a sequential reader needs.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>

#include "recording/byte_cursor.h"
#include "recording/decompress.h"
#include "recording/recording_parts.h"

namespace uuvplan::io::recording {
namespace {

using Fields = std::map<std::string, std::string_view>;

enum class BagOp : std::uint8_t { kMessage = 0x02, kChunk = 0x05, kConnection = 0x07 };

struct Record {
  Fields header;
  std::string_view data;
  std::size_t data_offset;  ///< in the file (or in the chunk)
};

Fields ReadFields(std::string_view bytes, const std::string& file, std::size_t offset) {
  Fields fields;
  ByteCursor c(bytes, file, offset);
  while (!c.AtEnd()) {
    const std::string_view field = c.Take(c.Read<std::uint32_t>(), "a header field");
    const auto eq = field.find('=');
    if (eq == std::string_view::npos) c.Fail("expected a header field 'name=value'");
    fields[std::string(field.substr(0, eq))] = field.substr(eq + 1);
  }
  return fields;
}

Record ReadRecord(ByteCursor& c) {
  const std::size_t header_offset = c.FileOffset() + 4;
  const std::string_view header = c.Take(c.Read<std::uint32_t>(), "a record header");
  Record r{ReadFields(header, c.file(), header_offset), {}, 0};
  const std::uint32_t data_len = c.Read<std::uint32_t>();
  r.data_offset = c.FileOffset();
  r.data = c.Take(data_len, "a record's data");
  return r;
}

std::string_view FieldOf(const Fields& f, const char* name, const ByteCursor& c) {
  const auto it = f.find(name);
  if (it == f.end()) c.Fail(std::string("expected a record with a '") + name + "' field");
  return it->second;
}

template <typename T>
T FieldAs(const Fields& f, const char* name, const ByteCursor& c) {
  const std::string_view raw = FieldOf(f, name, c);
  if (raw.size() != sizeof(T)) {
    c.Fail(std::string("expected a '") + name + "' field of " + std::to_string(sizeof(T)) +
           " bytes");
  }
  T value;
  std::memcpy(&value, raw.data(), sizeof(T));
  return value;
}

class BagReader {
 public:
  BagReader(const std::vector<std::string>& wanted, Recording* recording)
      : wanted_(wanted), recording_(*recording) {}

  void Records(ByteCursor& c) {
    while (!c.AtEnd()) {
      const Record r = ReadRecord(c);
      switch (BagOp(FieldAs<std::uint8_t>(r.header, "op", c))) {
        case BagOp::kConnection:
          Connection(r, c);
          break;
        case BagOp::kMessage:
          Message(r, c);
          break;
        case BagOp::kChunk:
          if (in_chunk_) c.Fail("expected connections and messages in a chunk, got a chunk");
          Chunk(r, c);
          break;
        default:
          break;  // bag header, index data, chunk info
      }
    }
  }

 private:
  void Connection(const Record& r, const ByteCursor& c) {
    const auto conn = FieldAs<std::uint32_t>(r.header, "conn", c);
    const std::string topic(FieldOf(r.header, "topic", c));
    const Fields d = ReadFields(r.data, c.file(), r.data_offset);
    topics_[conn] = topic;
    RecordedTopic& t = recording_.topics[topic];
    t.type = std::string(FieldOf(d, "type", c));
    t.definition = std::string(FieldOf(d, "message_definition", c));
    t.encoding = MessageEncoding::kRos1;
  }

  void Message(const Record& r, const ByteCursor& c) {
    const auto conn = FieldAs<std::uint32_t>(r.header, "conn", c);
    const auto topic = topics_.find(conn);
    if (topic == topics_.end()) {
      c.Fail("expected a message of a connection defined before it, got connection " +
             std::to_string(conn));
    }
    if (std::find(wanted_.begin(), wanted_.end(), topic->second) == wanted_.end()) return;
    const auto time = FieldAs<std::uint64_t>(r.header, "time", c);  // uint32 sec, uint32 nsec
    RecordedTopic& t = recording_.topics[topic->second];
    const long long sec = (long long)(time & 0xffffffffu);
    if (recording_.epoch_s < 0) recording_.epoch_s = sec;
    t.times.push_back(double(sec - recording_.epoch_s) + 1e-9 * double(time >> 32));
    t.messages.emplace_back(r.data);
  }

  void Chunk(const Record& r, const ByteCursor& c) {
    const std::string compression(FieldOf(r.header, "compression", c));
    const auto size = FieldAs<std::uint32_t>(r.header, "size", c);
    const std::string where = c.file() + ": chunk at byte " + std::to_string(r.data_offset);
    const std::string bytes = Decompressed(r.data, compression, size, where);
    ByteCursor inner(bytes, where);
    in_chunk_ = true;
    Records(inner);
    in_chunk_ = false;
  }

  const std::vector<std::string>& wanted_;
  Recording& recording_;
  std::map<std::uint32_t, std::string> topics_;  ///< by connection id
  bool in_chunk_ = false;  ///< a chunk holds connections and messages only (format 2.0)
};

}  // namespace

void ReadRosBag(std::string_view bytes, const std::vector<std::string>& wanted,
                Recording* recording) {
  recording->format = "ROS bag 2.0";
  ByteCursor c(bytes.substr(kRosBagMagic.size()), recording->path, kRosBagMagic.size());
  BagReader(wanted, recording).Records(c);
}

}  // namespace uuvplan::io::recording
