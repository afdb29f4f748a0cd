// MCAP (mcap.dev/spec): after the magic, records of (uint8 opcode, uint64 length, content);
// strings are (uint32 length, bytes), little endian throughout. Schema (0x03) records carry the
// message definition ("ros2msg" or "ros1msg"), Channel (0x04) records a topic and its message
// encoding ("cdr" or "ros1"), Message (0x05) records the log time (ns) and the bytes; Chunk
// (0x06) records hold further records, stored, lz4 or zstd. The Footer (0x02) ends the data.
#include <algorithm>
#include <cstdint>
#include <map>

#include "recording/byte_cursor.h"
#include "recording/decompress.h"
#include "recording/recording_parts.h"

namespace uuvplan::io::recording {
namespace {

enum class McapOp : std::uint8_t {
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06
};

std::string_view String(ByteCursor& c) { return c.Take(c.Read<std::uint32_t>(), "a string"); }

struct Schema {
  std::string name;
  std::string encoding;
  std::string definition;
};

class McapReader {
 public:
  McapReader(const std::vector<std::string>& wanted, Recording* recording)
      : wanted_(wanted), recording_(*recording) {}

  // Reads records until the footer or the end; false after the footer.
  bool Records(ByteCursor& c) {
    while (!c.AtEnd()) {
      const auto opcode = c.Read<std::uint8_t>();
      const auto length = c.Read<std::uint64_t>();
      const std::size_t offset = c.FileOffset();
      ByteCursor content(c.Take(length, "a record"), c.file(), offset);
      switch (McapOp(opcode)) {
        case McapOp::kFooter:
          if (in_chunk_) content.Fail("expected records of messages in a chunk, got a footer");
          return false;
        case McapOp::kSchema:
          ReadSchema(content);
          break;
        case McapOp::kChannel:
          ReadChannel(content);
          break;
        case McapOp::kMessage:
          ReadMessage(content);
          break;
        case McapOp::kChunk:
          if (in_chunk_) content.Fail("expected records of messages in a chunk, got a chunk");
          ReadChunk(content);
          break;
        default:
          break;  // header, indexes, statistics, attachments, metadata, data end
      }
    }
    return true;
  }

 private:
  bool Wanted(const std::string& topic) const {
    return std::find(wanted_.begin(), wanted_.end(), topic) != wanted_.end();
  }

  void ReadSchema(ByteCursor& c) {
    const auto id = c.Read<std::uint16_t>();
    Schema& s = schemas_[id];
    s.name = std::string(String(c));
    s.encoding = std::string(String(c));
    s.definition = std::string(c.Take(c.Read<std::uint32_t>(), "a schema"));
  }

  void ReadChannel(ByteCursor& c) {
    const auto id = c.Read<std::uint16_t>();
    const auto schema_id = c.Read<std::uint16_t>();
    const std::string topic(String(c));
    const std::string encoding(String(c));
    const auto found = schemas_.find(schema_id);  // id 0 (or none yet): a schemaless channel
    const Schema schema =
        found == schemas_.end() ? Schema{"(no schema)", "none", ""} : found->second;
    const bool known = (encoding == "cdr" && schema.encoding == "ros2msg") ||
                       (encoding == "ros1" && schema.encoding == "ros1msg");
    if (!known && Wanted(topic)) {
      c.Fail("expected topic " + topic + " in ROS messages (cdr/ros2msg or ros1/ros1msg), got " +
             encoding + "/" + schema.encoding);
    }
    topics_[id] = topic;
    RecordedTopic& t = recording_.topics[topic];
    t.type = schema.name;
    t.definition = schema.definition;
    t.encoding = encoding == "ros1" ? MessageEncoding::kRos1 : MessageEncoding::kCdr;
  }

  void ReadMessage(ByteCursor& c) {
    const auto channel = c.Read<std::uint16_t>();
    c.Read<std::uint32_t>();  // sequence
    const auto log_time_ns = c.Read<std::uint64_t>();
    c.Read<std::uint64_t>();  // publish time
    const auto topic = topics_.find(channel);
    if (topic == topics_.end()) c.Fail("expected a message whose channel comes before it");
    if (!Wanted(topic->second)) return;
    RecordedTopic& t = recording_.topics[topic->second];
    const long long sec = (long long)(log_time_ns / 1000000000u);
    if (recording_.epoch_s < 0) recording_.epoch_s = sec;
    t.times.push_back(double(sec - recording_.epoch_s) + 1e-9 * double(log_time_ns % 1000000000u));
    t.messages.emplace_back(c.Take(c.Remaining(), "a message"));
  }

  void ReadChunk(ByteCursor& c) {
    c.Take(16, "the chunk's times");  // message_start_time, message_end_time (uint64 ns)
    const auto size = c.Read<std::uint64_t>();
    c.Read<std::uint32_t>();  // uncompressed crc
    const std::string compression(String(c));
    const std::string where = c.file() + ": chunk at byte " + std::to_string(c.FileOffset());
    const std::string bytes = Decompressed(c.Take(c.Read<std::uint64_t>(), "the chunk's records"),
                                           compression, std::size_t(size), where);
    ByteCursor inner(bytes, where);
    in_chunk_ = true;
    Records(inner);
    in_chunk_ = false;
  }

  const std::vector<std::string>& wanted_;
  Recording& recording_;
  bool in_chunk_ = false;  ///< a chunk holds no chunk (mcap.dev/spec "Chunk")
  std::map<std::uint16_t, Schema> schemas_;
  std::map<std::uint16_t, std::string> topics_;  ///< by channel id
};

}  // namespace

void ReadMcap(std::string_view bytes, const std::vector<std::string>& wanted,
              Recording* recording) {
  recording->format = "MCAP";
  ByteCursor c(bytes.substr(kMcapMagic.size()), recording->path, kMcapMagic.size());
  McapReader(wanted, recording).Records(c);
}

}  // namespace uuvplan::io::recording
