// Writers of ROS bag 2.0 and MCAP test recordings, and the message definitions and
// serialisations (ROS 1 and CDR) of the three message types the import tests use.
#include "support/recording_writer.h"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace uuvplan::testing {
namespace {

// --- Message definitions: the .msg files of ROS 1 Noetic (std_msgs, common_msgs) and ROS 2
// Rolling (common_interfaces, rcl_interfaces), trailing spaces dropped. ---

constexpr const char* kMultiArrayIntro =
    R"msg(# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
)msg";

// std_msgs/MultiArrayLayout: its description, fields and accessor notes, in ROS 1 and ROS 2.
constexpr const char* kLayoutIntro =
    R"msg(# The multiarray declares a generic multi-dimensional array of a
# particular data type.  Dimensions are ordered from outer most
# to inner most.
)msg";

constexpr const char* kLayoutFields =
    R"msg(MultiArrayDimension[] dim # Array of dimension properties
uint32 data_offset        # padding)msg";

constexpr const char* kLayoutAccessors =
    R"msg(# Accessors should ALWAYS be written in terms of dimension stride
# and specified outer-most dimension first.
#
# multiarray(i,j,k) = data[data_offset + dim_stride[1]*i + dim_stride[2]*j + k]
#
# A standard, 3-channel 640x480 image with interleaved color channels
# would be specified as:
#
# dim[0].label  = "height"
# dim[0].size   = 480
# dim[0].stride = 3*640*480 = 921600  (note dim[0] stride is just size of image)
# dim[1].label  = "width"
# dim[1].size   = 640
# dim[1].stride = 3*640 = 1920
# dim[2].label  = "channel"
# dim[2].size   = 3
# dim[2].stride = 3
#
# multiarray(i,j,k) refers to the ith row, jth column, and kth channel.
)msg";

constexpr const char* kRos1Dimension =
    R"msg(string label   # label of given dimension
uint32 size    # size of given dimension (in type units)
uint32 stride  # stride of given dimension)msg";

constexpr const char* kRos1Header =
    R"msg(# Standard metadata for higher-level stamped data types.
# This is generally used to communicate timestamped data
# in a particular coordinate frame.
#
# sequence ID: consecutively increasing ID
uint32 seq
#Two-integer timestamp that is expressed as:
# * stamp.sec: seconds (stamp_secs) since epoch (in Python the variable is called 'secs')
# * stamp.nsec: nanoseconds since stamp_secs (in Python the variable is called 'nsecs')
# time-handling sugar is provided by the client library
time stamp
#Frame this data is associated with
string frame_id
)msg";

constexpr const char* kRos1TwistStamped =
    R"msg(# A twist with reference coordinate frame and timestamp
Header header
Twist twist
)msg";

constexpr const char* kRos1Twist =
    R"msg(# This expresses velocity in free space broken into its linear and angular parts.
Vector3  linear
Vector3  angular
)msg";

constexpr const char* kRos1Vector3 = R"msg(# This represents a vector in free space.
# It is only meant to represent a direction. Therefore, it does not
# make sense to apply a translation to it (e.g., when applying a
# generic rigid transformation to a Vector3, tf2 will only apply the
# rotation). If you want your data to be translatable too, use the
# geometry_msgs/Point message instead.

float64 x
float64 y
float64 z)msg";

constexpr const char* kRos2FoxyNote = R"msg(# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

)msg";

constexpr const char* kRos2Header =
    R"msg(# Standard metadata for higher-level stamped data types.
# This is generally used to communicate timestamped data
# in a particular coordinate frame.

# Two-integer timestamp that is expressed as seconds and nanoseconds.
builtin_interfaces/Time stamp

# Transform frame with which this data is associated.
string frame_id
)msg";

constexpr const char* kRos2Time = R"msg(# This message communicates ROS Time defined here:
# https://design.ros2.org/articles/clock_and_time.html

# The seconds component, valid over all int32 values.
int32 sec

# The nanoseconds component, valid in the range [0, 1e9).
uint32 nanosec
)msg";

constexpr const char* kRos2TwistStamped =
    R"msg(# A twist with reference coordinate frame and timestamp

std_msgs/Header header
Twist twist
)msg";

constexpr const char* kRos2Twist =
    R"msg(# This expresses velocity in free space broken into its linear and angular parts.

Vector3  linear
Vector3  angular
)msg";

constexpr const char* kRos2Vector3 = R"msg(# This represents a vector in free space.

# This is semantically different than a point.
# A vector is always anchored at the origin.
# When a transform is applied to a vector, only the rotational component is applied.

float64 x
float64 y
float64 z
)msg";

using Section = std::pair<std::string, std::string>;  // dependency: pkg/Type, its .msg text

// ROS 1 full text (genmsg compute_full_text): the text + "\n", then per dependency (in order
// of first use) the separator line, "MSG: pkg/Type\n", its text + "\n"; the last "\n" dropped.
std::string Ros1FullText(const std::string& text, const std::vector<Section>& dependencies) {
  std::string full = text + "\n";
  for (const auto& [type, dep] : dependencies) {
    full += std::string(80, '=') + "\nMSG: " + type + "\n" + dep + "\n";
  }
  full.pop_back();
  return full;
}

// ros2msg (rosbag2 MessageDefinitionCache::get_full_text): the text, then per dependency
// (depth first, each type's dependencies sorted by name) "\n", the separator line,
// "\nMSG: pkg/Type\n" and its text.
std::string Ros2FullText(const std::string& text, const std::vector<Section>& dependencies) {
  std::string full = text;
  for (const auto& [type, dep] : dependencies) {
    full += "\n" + std::string(80, '=') + "\nMSG: " + type + "\n" + dep;
  }
  return full;
}

// std_msgs/<name>: the ROS 1 and ROS 2 .msg files differ in the Foxy note of ROS 2 and in the
// layout's comments.
TestTopic MultiArrayTopic(const std::string& topic, const std::string& name,
                          const std::string& data_line) {
  const std::string main = kMultiArrayIntro + data_line;
  const std::string foxy = kRos2FoxyNote, intro = kLayoutIntro, notes = kLayoutAccessors;
  const std::string ros1_layout = intro + "\n" + kLayoutFields + " elements at front of data\n\n";
  const std::string ros2_layout =
      intro + "#\n" + notes + "\n" + kLayoutFields + " bytes at front of data\n";
  return {
      topic, "std_msgs/" + name,
      Ros1FullText(main + "\n", {{"std_msgs/MultiArrayLayout", ros1_layout + notes},
                                 {"std_msgs/MultiArrayDimension", kRos1Dimension}}),
      "std_msgs/msg/" + name,
      Ros2FullText(foxy + main, {{"std_msgs/MultiArrayLayout", foxy + ros2_layout},
                                 {"std_msgs/MultiArrayDimension", foxy + kRos1Dimension + "\n"}})};
}

// The md5sum rosbag stores (genmsg's MD5 of the definition), known for the types of this file.
std::string Md5Sum(const std::string& ros1_type) {
  static const auto* const kKnown = new std::map<std::string, std::string>{
      {"std_msgs/UInt16MultiArray", "52f264f1c973c4b73790d384c6cb4484"},
      {"std_msgs/Float32MultiArray", "6a40e0ffa6a17a503ac3f8616991b1f6"},
      {"geometry_msgs/TwistStamped", "98d34b0043a2093cf9d9345ab6eef12e"}};
  const auto it = kKnown->find(ros1_type);
  return it != kKnown->end() ? it->second : std::string(32, '0');
}

// --- Serialisation ---

// `value` as little-endian bytes (an integer or IEEE 754 float of 1, 2, 4 or 8 bytes).
template <typename T>
std::string Le(T value) {
  using U = std::conditional_t<
      sizeof(T) == 8, std::uint64_t,
      std::conditional_t<sizeof(T) == 4, std::uint32_t,
                         std::conditional_t<sizeof(T) == 2, std::uint16_t, std::uint8_t>>>;
  static_assert(sizeof(T) == sizeof(U), "1, 2, 4 or 8 bytes");
  U bits;
  std::memcpy(&bits, &value, sizeof bits);
  std::string bytes(sizeof bits, '\0');
  for (std::size_t i = 0; i < sizeof bits; ++i) bytes[i] = static_cast<char>(bits >> (8 * i));
  return bytes;
}

// A message being serialised. ROS 1: little endian, packed; strings = uint32 length + bytes.
// CDR (XCDR1, little endian): encapsulation 00 01 00 00, then each primitive aligned to its
// size counted from the end of the encapsulation; strings = uint32 length counting a
// terminating NUL, the bytes and the NUL.
class Serialiser {
 public:
  explicit Serialiser(bool cdr) : cdr_(cdr), bytes_(cdr ? std::string("\0\1\0\0", 4) : "") {}
  template <typename T>
  void Put(T value) {
    if (cdr_) bytes_.append((sizeof(T) - (bytes_.size() - 4) % sizeof(T)) % sizeof(T), '\0');
    bytes_ += Le(value);
  }
  void PutString(const std::string& text) {
    Put<std::uint32_t>(text.size() + (cdr_ ? 1 : 0));
    bytes_ += text;
    if (cdr_) bytes_ += '\0';
  }
  bool cdr() const { return cdr_; }
  const std::string& bytes() const { return bytes_; }

 private:
  bool cdr_;
  std::string bytes_;
};

// Seconds as whole seconds and nanoseconds (rounded).
std::pair<std::int64_t, std::uint32_t> SplitTime(double s) {
  double whole = std::floor(s);
  long long nsec = std::llround((s - whole) * 1e9);
  if (nsec >= 1000000000) {
    whole += 1.0;
    nsec -= 1000000000;
  }
  return {static_cast<std::int64_t>(whole), static_cast<std::uint32_t>(nsec)};
}

std::uint64_t Nanoseconds(double s) {
  const auto [sec, nsec] = SplitTime(s);
  return static_cast<std::uint64_t>(sec) * 1000000000u + nsec;
}

// std_msgs/<T>MultiArray with an empty layout: dim (sequence, 0 long), data_offset 0, data.
template <typename T>
TestMessage MultiArrayMessage(int topic, double time_s, const std::vector<T>& data) {
  Serialiser ros1(false), cdr(true);
  for (Serialiser* s : {&ros1, &cdr}) {
    s->Put<std::uint32_t>(0);  // layout.dim: no dimensions
    s->Put<std::uint32_t>(0);  // layout.data_offset
    s->Put<std::uint32_t>(data.size());
    for (T value : data) s->Put(value);
  }
  return {topic, time_s, ros1.bytes(), cdr.bytes()};
}

// --- Files ---

void WriteFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

// One bzip2 stream of block size 9 (rosbag's BZ2Stream).
std::string Bz2(const std::string& raw) {
  auto size = static_cast<unsigned int>(raw.size() + raw.size() / 100 + 600);
  std::string out(size, '\0');
  if (BZ2_bzBuffToBuffCompress(out.data(), &size, const_cast<char*>(raw.data()),
                               static_cast<unsigned int>(raw.size()), 9, 0, 30) != BZ_OK) {
    throw std::runtime_error("bzip2 compression failed");
  }
  out.resize(size);
  return out;
}

// One LZ4 frame (https://github.com/lz4/lz4/blob/dev/doc/lz4_Frame_format.md). With roslz4's
// settings (roslz4 lz4s.c, rosbag's block_size_id 6): independent blocks of up to 1 MiB
// (LZ4F_compressFrame lowers the block size to fit a smaller input) and a content checksum;
// else the library's defaults (linked 64 KiB blocks, no checksum).
// A zstd frame (ZSTD_compress, level 3), as MCAP's "zstd" chunks hold.
std::string ZstdFrame(const std::string& raw) {
  std::string out(ZSTD_compressBound(raw.size()), '\0');
  const std::size_t n = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), 3);
  if (ZSTD_isError(n)) throw std::runtime_error("zstd compression failed");
  out.resize(n);
  return out;
}

std::string Lz4Frame(const std::string& raw, bool roslz4) {
  LZ4F_preferences_t prefs;
  std::memset(&prefs, 0, sizeof prefs);
  if (roslz4) {
    prefs.frameInfo.blockSizeID = LZ4F_max1MB;
    prefs.frameInfo.blockMode = LZ4F_blockIndependent;
    prefs.frameInfo.contentChecksumFlag = LZ4F_contentChecksumEnabled;
  }
  std::string out(LZ4F_compressFrameBound(raw.size(), &prefs), '\0');
  const std::size_t size =
      LZ4F_compressFrame(out.data(), out.size(), raw.data(), raw.size(), &prefs);
  if (LZ4F_isError(size)) throw std::runtime_error(LZ4F_getErrorName(size));
  out.resize(size);
  return out;
}

// --- ROS bag 2.0 (http://wiki.ros.org/Bags/Format/2.0) ---

// Header field: field_len (uint32), name, '=', value.
std::string Field(const std::string& name, const std::string& value) {
  return Le<std::uint32_t>(name.size() + 1 + value.size()) + name + "=" + value;
}
std::string Op(char op) { return Field("op", std::string(1, op)); }
std::string U32Field(const std::string& name, std::size_t value) {
  return Field(name, Le<std::uint32_t>(value));
}
// Time: uint32 sec + uint32 nsec.
std::string BagTime(std::uint64_t ns) {
  return Le<std::uint32_t>(ns / 1000000000u) + Le<std::uint32_t>(ns % 1000000000u);
}
// Record: header_len, header, data_len, data.
std::string BagRecord(const std::string& header, const std::string& data) {
  return Le<std::uint32_t>(header.size()) + header + Le<std::uint32_t>(data.size()) + data;
}

// Connection record: op=0x07, conn, topic; data = the fields topic, type, md5sum and
// message_definition in header format.
std::string ConnectionRecord(std::uint32_t conn, const TestTopic& topic) {
  return BagRecord(Op(0x07) + U32Field("conn", conn) + Field("topic", topic.topic),
                   Field("topic", topic.topic) + Field("type", topic.ros1_type) +
                       Field("md5sum", Md5Sum(topic.ros1_type)) +
                       Field("message_definition", topic.ros1_definition));
}

// A ROS bag being written: the file (its header record a placeholder until Finish), the open
// chunk and its index, and the chunk infos of the closed chunks.
class BagWriter {
 public:
  BagWriter(const std::vector<TestTopic>& topics, BagCompression compression,
            std::size_t chunk_bytes)
      : topics_(topics),
        compression_(compression),
        chunk_bytes_(chunk_bytes),
        conn_of_topic_(topics.size(), -1) {}
  void Add(const TestMessage& message);
  std::string Finish();

 private:
  static constexpr std::size_t kHeaderRecordBytes = 4 + 4096 + 4;  // header_len + data_len = 4096
  struct ChunkInfo {
    std::uint64_t pos = 0, start = 0, end = 0;
    std::map<std::uint32_t, std::uint32_t> counts;  // conn -> messages
  };
  void CloseChunk();

  const std::vector<TestTopic>& topics_;
  BagCompression compression_;
  std::size_t chunk_bytes_;
  std::vector<int> conn_of_topic_, topic_of_conn_;
  std::string file_ = "#ROSBAG V2.0\n" + std::string(kHeaderRecordBytes, ' ');
  std::string chunk_;                           // the open chunk's records, uncompressed
  std::map<std::uint32_t, std::string> index_;  // conn -> (time, offset) entries of the chunk
  ChunkInfo open_;
  std::vector<ChunkInfo> infos_;
};

void BagWriter::Add(const TestMessage& message) {
  int& conn = conn_of_topic_.at(message.topic);
  if (conn < 0) {
    conn = static_cast<int>(topic_of_conn_.size());
    topic_of_conn_.push_back(message.topic);
    chunk_ += ConnectionRecord(conn, topics_[message.topic]);
  }
  const std::uint64_t ns = Nanoseconds(message.time_s);
  open_.start = open_.counts.empty() ? ns : std::min(open_.start, ns);
  open_.end = open_.counts.empty() ? ns : std::max(open_.end, ns);
  ++open_.counts[conn];
  index_[conn] += BagTime(ns) + Le<std::uint32_t>(chunk_.size());
  chunk_ += BagRecord(Op(0x02) + U32Field("conn", conn) + Field("time", BagTime(ns)), message.ros1);
  if (chunk_.size() >= chunk_bytes_) CloseChunk();
}

// Chunk record (op=0x05, compression, size = uncompressed size), then its index data records
// (op=0x04, ver=1, conn, count; data = (time, uint32 offset in the chunk's records) pairs).
void BagWriter::CloseChunk() {
  static const char* const kCompression[] = {"none", "bz2", "lz4"};
  const std::string data = compression_ == BagCompression::kBz2   ? Bz2(chunk_)
                           : compression_ == BagCompression::kLz4 ? Lz4Frame(chunk_, true)
                                                                  : chunk_;
  open_.pos = file_.size();
  file_ += BagRecord(Op(0x05) + Field("compression", kCompression[static_cast<int>(compression_)]) +
                         U32Field("size", chunk_.size()),
                     data);
  for (const auto& [conn, entries] : index_) {
    file_ += BagRecord(Op(0x04) + U32Field("ver", 1) + U32Field("conn", conn) +
                           U32Field("count", entries.size() / 12),
                       entries);
  }
  infos_.push_back(open_);
  open_ = ChunkInfo();
  chunk_.clear();
  index_.clear();
}

// The index section (connection records, chunk info records: op=0x06, ver=1, chunk_pos,
// start_time, end_time, count; data = (conn, count) pairs) and the bag header record (op=0x03,
// index_pos, conn_count, chunk_count; padded with spaces).
std::string BagWriter::Finish() {
  if (!chunk_.empty()) CloseChunk();
  const std::uint64_t index_pos = file_.size();
  for (std::size_t conn = 0; conn < topic_of_conn_.size(); ++conn) {
    file_ += ConnectionRecord(conn, topics_[topic_of_conn_[conn]]);
  }
  for (const ChunkInfo& info : infos_) {
    std::string counts;
    for (const auto& [conn, n] : info.counts) counts += Le(conn) + Le(n);
    file_ +=
        BagRecord(Op(0x06) + U32Field("ver", 1) + Field("chunk_pos", Le(info.pos)) +
                      Field("start_time", BagTime(info.start)) +
                      Field("end_time", BagTime(info.end)) + U32Field("count", info.counts.size()),
                  counts);
  }
  const std::string header = Op(0x03) + Field("index_pos", Le(index_pos)) +
                             U32Field("conn_count", topic_of_conn_.size()) +
                             U32Field("chunk_count", infos_.size());
  file_.replace(13, kHeaderRecordBytes, BagRecord(header, std::string(4096 - header.size(), ' ')));
  return std::move(file_);
}

// --- MCAP (https://mcap.dev/spec) ---

constexpr char kMcapMagic[] = "\x89MCAP0\r\n";  // 8 bytes
constexpr std::size_t kMcapChunkBytes = 768 * 1024;

// Record: opcode (uint8), content length (uint64), content.
std::string McapRecord(char op, const std::string& content) {
  return std::string(1, op) + Le<std::uint64_t>(content.size()) + content;
}
std::string Str(const std::string& text) { return Le<std::uint32_t>(text.size()) + text; }

// The data section being written: records at top level or gathered into chunks.
class McapData {
 public:
  McapData(bool chunked, McapCompression compression)
      : chunked_(chunked), compression_(compression) {}
  void Add(const std::string& record) { (chunked_ ? chunk_ : file_) += record; }
  void AddMessage(const std::string& record, std::uint64_t log_time);
  std::string Finish();

 private:
  void CloseChunk();
  bool chunked_;
  McapCompression compression_;
  std::string file_ =
      std::string(kMcapMagic) + McapRecord(0x01, Str("ros2") + Str("uuvplan tests"));
  std::string chunk_;
  bool has_messages_ = false;
  std::uint64_t start_ = 0, end_ = 0;
};

void McapData::AddMessage(const std::string& record, std::uint64_t log_time) {
  start_ = has_messages_ ? std::min(start_, log_time) : log_time;
  end_ = has_messages_ ? std::max(end_, log_time) : log_time;
  has_messages_ = true;
  Add(record);
  if (chunk_.size() >= kMcapChunkBytes) CloseChunk();
}

// Chunk: message_start_time, message_end_time, uncompressed_size, uncompressed_crc (0),
// compression, records (uint64 length + bytes).
void McapData::CloseChunk() {
  std::string records = chunk_;
  const char* name = "";
  if (compression_ == McapCompression::kLz4) records = Lz4Frame(chunk_, false), name = "lz4";
  if (compression_ == McapCompression::kZstd) records = ZstdFrame(chunk_), name = "zstd";
  file_ += McapRecord(0x06, Le(start_) + Le(end_) + Le<std::uint64_t>(chunk_.size()) +
                                Le<std::uint32_t>(0) + Str(name) +
                                Le<std::uint64_t>(records.size()) + records);
  chunk_.clear();
  has_messages_ = false;
}

// Data End (data_section_crc 0), Footer (summary_start 0, summary_offset_start 0,
// summary_crc 0), magic.
std::string McapData::Finish() {
  if (!chunk_.empty()) CloseChunk();
  file_ += McapRecord(0x0F, Le<std::uint32_t>(0));
  file_ += McapRecord(0x02, Le<std::uint64_t>(0) + Le<std::uint64_t>(0) + Le<std::uint32_t>(0));
  return file_ + kMcapMagic;
}

}  // namespace

void WriteRos1Bag(const std::string& path, const std::vector<TestTopic>& topics,
                  const std::vector<TestMessage>& messages, BagCompression compression,
                  std::size_t chunk_bytes) {
  BagWriter bag(topics, compression, chunk_bytes);
  for (const TestMessage& message : messages) bag.Add(message);
  WriteFile(path, bag.Finish());
}

// Schema: id, name, encoding, data (uint32 length + bytes). Channel: id, schema_id, topic,
// message_encoding, metadata (map: uint32 byte length + entries). Message: channel_id, sequence,
// log_time, publish_time, data (the rest of the record).
void WriteMcap(const std::string& path, const std::vector<TestTopic>& topics,
               const std::vector<TestMessage>& messages, bool chunked,
               McapCompression compression) {
  McapData mcap(chunked, compression);
  std::map<std::string, std::uint16_t> schema_ids;
  for (std::size_t i = 0; i < topics.size(); ++i) {
    const TestTopic& topic = topics[i];
    const auto id = static_cast<std::uint16_t>(schema_ids.size() + 1);
    if (schema_ids.emplace(topic.ros2_type, id).second) {
      mcap.Add(McapRecord(
          0x03, Le(id) + Str(topic.ros2_type) + Str("ros2msg") + Str(topic.ros2_definition)));
    }
    mcap.Add(McapRecord(0x04, Le<std::uint16_t>(i + 1) + Le(schema_ids.at(topic.ros2_type)) +
                                  Str(topic.topic) + Str("cdr") + Le<std::uint32_t>(0)));
  }
  std::vector<std::uint32_t> sequence(topics.size());
  for (const TestMessage& message : messages) {
    const std::uint64_t ns = Nanoseconds(message.time_s);
    mcap.AddMessage(
        McapRecord(0x05, Le<std::uint16_t>(message.topic + 1) + Le(++sequence.at(message.topic)) +
                             Le(ns) + Le(ns) + message.cdr),
        ns);
  }
  WriteFile(path, mcap.Finish());
}

TestTopic UInt16MultiArrayTopic(const std::string& topic) {
  return MultiArrayTopic(topic, "UInt16MultiArray",
                         "uint16[]            data        # array of data\n");
}

TestTopic Float32MultiArrayTopic(const std::string& topic) {
  return MultiArrayTopic(topic, "Float32MultiArray",
                         "float32[]         data          # array of data\n");
}

TestTopic TwistStampedTopic(const std::string& topic) {
  return {topic, "geometry_msgs/TwistStamped",
          Ros1FullText(kRos1TwistStamped, {{"std_msgs/Header", kRos1Header},
                                           {"geometry_msgs/Twist", kRos1Twist},
                                           {"geometry_msgs/Vector3", kRos1Vector3}}),
          "geometry_msgs/msg/TwistStamped",
          Ros2FullText(kRos2TwistStamped, {{"geometry_msgs/Twist", kRos2Twist},
                                           {"geometry_msgs/Vector3", kRos2Vector3},
                                           {"std_msgs/Header", kRos2Header},
                                           {"builtin_interfaces/Time", kRos2Time}})};
}

TestMessage UInt16MultiArrayMessage(int topic, double time_s,
                                    const std::vector<std::uint16_t>& data) {
  return MultiArrayMessage(topic, time_s, data);
}

TestMessage Float32MultiArrayMessage(int topic, double time_s, const std::vector<float>& data) {
  return MultiArrayMessage(topic, time_s, data);
}

TestMessage TwistStampedMessage(int topic, double time_s, double stamp_s,
                                const std::string& frame_id, const std::array<double, 3>& linear,
                                const std::array<double, 3>& angular) {
  const auto [sec, nsec] = SplitTime(stamp_s);
  Serialiser ros1(false), cdr(true);
  for (Serialiser* s : {&ros1, &cdr}) {
    if (!s->cdr()) s->Put<std::uint32_t>(0);  // ROS 1 header.seq
    // stamp: ROS 1 time = uint32 sec, ROS 2 Time = int32 sec (the same bytes here); nanoseconds.
    s->Put(static_cast<std::uint32_t>(sec));
    s->Put(nsec);
    s->PutString(frame_id);
    for (double v : linear) s->Put(v);
    for (double v : angular) s->Put(v);
  }
  return {topic, time_s, ros1.bytes(), cdr.bytes()};
}

}  // namespace uuvplan::testing
