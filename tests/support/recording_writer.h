// Test support that writes recordings: ROS bag 2.0 files (ROS 1) and MCAP files (ROS 2 profile)
// holding std_msgs/UInt16MultiArray, std_msgs/Float32MultiArray and geometry_msgs/TwistStamped
// messages, written from the format specifications alone, so that the tests can check the
// recording readers against files made independently of them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace uuvplan::testing {

// A recorded topic: name, type ("std_msgs/UInt16MultiArray" style for ROS 1; the writer of MCAP
// uses the ROS 2 name "std_msgs/msg/UInt16MultiArray") and the message definition text of each.
struct TestTopic {
  std::string topic;
  std::string ros1_type;  // e.g. "std_msgs/Float32MultiArray"
  // Full text as rosbag stores it (genmsg): the main .msg, then one section per dependency,
  // "====...\nMSG: pkg/Type\n" + its .msg.
  std::string ros1_definition;
  std::string ros2_type;        // e.g. "std_msgs/msg/Float32MultiArray"
  std::string ros2_definition;  // ros2msg schema text as rosbag2's MCAP writer stores it
};

struct TestMessage {
  int topic = 0;        // index into the topics
  double time_s = 0.0;  // recorder (log) time, s since the Unix epoch
  std::string ros1;     // the message serialised as ROS 1 (little endian, no alignment)
  // The message serialised as CDR (XCDR1, little endian, with the 4-byte encapsulation header
  // 00 01 00 00).
  std::string cdr;
};

enum class BagCompression { kNone, kBz2, kLz4 };

// ROS bag format 2.0 (http://wiki.ros.org/Bags/Format/2.0): "#ROSBAG V2.0\n", the bag header
// record (op=0x03, index_pos, conn_count, chunk_count; its data padded with spaces so that
// header_len + data_len = 4096, as rosbag does), then chunks (op=0x05, compression=none|bz2|lz4,
// size=uncompressed size) each holding connection records (op=0x07, conn, topic; data =
// header-format fields topic, type, md5sum, message_definition) before their first message and
// message data records (op=0x02, conn, time = uint32 sec + uint32 nsec), a chunk closed once
// its uncompressed records reach `chunk_bytes`; after each chunk its index data records (op=0x04,
// ver=1, conn, count; data = (time, offset) pairs); then at index_pos the connection records
// again and one chunk info record per chunk (op=0x06, ver=1, chunk_pos, start_time, end_time,
// count; data = (conn, count) pairs). Connection ids are given in order of first message, as
// rosbag does; a topic without messages has no connection. Messages are written in the order
// given. bz2 = BZ2_bzBuffToBuffCompress block 9; lz4 = an LZ4 frame (LZ4F_compressFrame) with
// roslz4's settings (independent blocks of up to 1 MiB, content checksum).
void WriteRos1Bag(const std::string& path, const std::vector<TestTopic>& topics,
                  const std::vector<TestMessage>& messages, BagCompression compression,
                  std::size_t chunk_bytes = 768 * 1024);

enum class McapCompression { kNone, kLz4, kZstd };

// MCAP (https://mcap.dev/spec): magic "\x89MCAP0\r\n", Header (op 0x01: profile "ros2",
// library), Schema (0x03: id, name = ros2_type, encoding "ros2msg", data = ros2_definition; one
// per distinct type, ids from 1) and Channel (0x04: id = topic index + 1, schema_id, topic,
// message_encoding "cdr", metadata {}) records of every topic first, then Messages (0x05:
// channel_id, sequence (from 1 per channel), log_time = publish_time in ns, data = cdr) in the
// order given; all of them inside Chunk records (0x06, compression "", "lz4" (an LZ4 frame) or
// "zstd" (a zstd frame),
// uncompressed_crc 0, closed once 768 KiB of records are reached) when `chunked`, else at top
// level (`compression` unused); Data End (0x0F, crc 0), Footer (0x02, summary_start 0,
// summary_offset_start 0, crc 0) and the closing magic. Little endian everywhere; strings =
// uint32 length + bytes.
void WriteMcap(const std::string& path, const std::vector<TestTopic>& topics,
               const std::vector<TestMessage>& messages, bool chunked, McapCompression compression);

// The three message types the import tests use, each with both definitions filled in (the real
// .msg texts of ROS 1 Noetic and ROS 2 Rolling, trailing spaces dropped).
TestTopic UInt16MultiArrayTopic(const std::string& topic);   // layout + uint16[] data
TestTopic Float32MultiArrayTopic(const std::string& topic);  // layout + float32[] data
TestTopic TwistStampedTopic(const std::string& topic);       // Header + Twist

// Serialised messages (both encodings) of those types; the MultiArray layout is empty (no dims,
// data_offset 0).
TestMessage UInt16MultiArrayMessage(int topic, double time_s,
                                    const std::vector<std::uint16_t>& data);
TestMessage Float32MultiArrayMessage(int topic, double time_s, const std::vector<float>& data);
// header.stamp = stamp_s (ROS 1: seq uint32 = 0, time, frame_id string; ROS 2:
// builtin_interfaces/Time int32 sec + uint32 nanosec, frame_id), twist.linear/angular xyz.
TestMessage TwistStampedMessage(int topic, double time_s, double stamp_s,
                                const std::string& frame_id, const std::array<double, 3>& linear,
                                const std::array<double, 3>& angular);

}  // namespace uuvplan::testing
