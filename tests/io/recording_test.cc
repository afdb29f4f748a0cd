// The message decoder of recordings (io::FieldValues) on messages built byte by byte: ROS 2
// definitions with constants, defaults and bounded types; CDR alignment after a string; ROS 1
// byte (int8); messages stored out of time order; paths that name no number; definitions that
// contain themselves or nest past any use, and types without fields, refused or decoded fast.
#include "uuvplan/io/recording.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "support/recording_writer.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {
namespace {

using ::testing::HasSubstr;

template <typename T>
void Append(std::string* bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes->append(raw, sizeof(T));
}

// One topic of messages `messages` at times 0, 1, 2... (or `times`).
Recording OneTopic(const std::string& type, const std::string& definition, MessageEncoding encoding,
                   std::vector<std::string> messages, std::vector<double> times = {}) {
  Recording r;
  r.path = "test.mcap";
  r.epoch_s = 1700000000;
  RecordedTopic& t = r.topics["/t"];
  t.type = type;
  t.definition = definition;
  t.encoding = encoding;
  t.messages = std::move(messages);
  for (std::size_t i = 0; i < t.messages.size(); ++i) {
    t.times.push_back(times.empty() ? double(i) : times[i]);
  }
  return r;
}

std::string FaultOf(const Recording& r, const std::string& field) {
  try {
    FieldValues(r, "/t", {field}, "map.yaml");
  } catch (const model::InputError& e) {
    return e.what();
  }
  return "";
}

// ROS 2: a constant, a bounded sequence, a bounded string with a default holding '=', then a
// float64 that CDR aligns to 8 after the string (XCDR1).
TEST(RecordingFields, Ros2BoundedTypesConstantsAndDefaultsDecodeInPlace) {
  const std::string definition =
      "int32 LIMIT=5      # a constant, no field\n"
      "int32[<=5] pad\n"
      "string<=10 name \"a=b\"\n"
      "float64 v 1.5\n";
  std::string cdr("\x00\x01\x00\x00", 4);
  Append<std::uint32_t>(&cdr, 2);  // pad: 2 items
  Append<std::int32_t>(&cdr, 7);
  Append<std::int32_t>(&cdr, 8);
  Append<std::uint32_t>(&cdr, 4);  // name: "abc" and its NUL
  cdr += std::string("abc\0", 4);
  cdr += std::string(4, '\0');  // to the next multiple of 8 after the header
  Append<double>(&cdr, 0.25);
  const Recording r = OneTopic("test_msgs/msg/Bounded", definition, MessageEncoding::kCdr, {cdr});
  const auto values = FieldValues(r, "/t", {"v", "pad[1]"}, "map.yaml");
  EXPECT_EQ(values[0][0], 0.25);
  EXPECT_EQ(values[1][0], 8.0);
}

TEST(RecordingFields, Ros1ByteIsSigned) {
  std::string ros1;
  Append<std::int8_t>(&ros1, -3);
  Append<std::uint8_t>(&ros1, 200);
  const Recording r =
      OneTopic("test_msgs/Bytes", "byte b\nchar c\n", MessageEncoding::kRos1, {ros1});
  const auto values = FieldValues(r, "/t", {"b", "c"}, "map.yaml");
  EXPECT_EQ(values[0][0], -3.0);   // ROS 1 byte: int8 (wiki.ros.org/msg)
  EXPECT_EQ(values[1][0], 200.0);  // ROS 1 char: uint8
}

TEST(RecordingFields, MessagesStoredOutOfOrderComeInTimeOrder) {
  // An MCAP need not store messages in log-time order (mcap.dev/spec, "Message").
  const std::vector<testing::TestTopic> topics = {testing::Float32MultiArrayTopic("/t")};
  std::vector<testing::TestMessage> messages;
  for (double t : {2.0, 0.0, 1.0}) {
    messages.push_back(testing::Float32MultiArrayMessage(0, 1.7e9 + t, {float(t)}));
  }
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("uuvplan-order-" + std::to_string(getpid()) + ".mcap"))
                               .string();
  testing::WriteMcap(path, topics, messages, false, testing::McapCompression::kNone);
  const Recording r = ReadRecording(path, {"/t"});
  std::filesystem::remove(path);
  const std::vector<double>& times = r.topics.at("/t").times;  // s after the epoch
  ASSERT_EQ(times.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(double(r.epoch_s) + times[i], 1.7e9 + i);
  EXPECT_EQ(FieldValues(r, "/t", {"data[0]"}, "map.yaml")[0], (std::vector<double>{0, 1, 2}));
}

TEST(RecordingFields, APathThatNamesNoNumberIsRefusedWithTheFieldsThereAre) {
  std::string ros1;
  for (int i = 0; i < 3; ++i) Append<double>(&ros1, i);
  const Recording r =
      OneTopic("test_msgs/Fixed", "float64[3] data\n", MessageEncoding::kRos1, {ros1});
  EXPECT_THAT(FaultOf(r, "data[x]"), HasSubstr("'data[x]' is not name[index] with a whole index"));
  EXPECT_THAT(FaultOf(r, "data[01]"), HasSubstr("with a whole index"));
  EXPECT_THAT(FaultOf(r, "data[3]"), HasSubstr("'data' holds 3 items"));
  EXPECT_THAT(FaultOf(r, "data"), HasSubstr("'data' needs [index]; the numeric fields of "
                                            "test_msgs/Fixed are data[i]"));
  EXPECT_EQ(FaultOf(r, "data[2]"), "");
}

TEST(RecordingFields, ATypeThatContainsItselfIsRefused) {
  const Recording r = OneTopic("a/A", "B b\n===\nMSG: a/B\nA a\n", MessageEncoding::kRos1, {""});
  EXPECT_THAT(FaultOf(r, "b"), HasSubstr("without cycles"));
}

// 40 types each holding two of the next: 2^40 paths, but each type is sized once.
TEST(RecordingFields, ADeepDiamondOfTypesIsSizedOnce) {
  std::string definition = "T0 a\nT0 b\n";
  for (int i = 0; i < 40; ++i) {
    definition += "===\nMSG: p/T" + std::to_string(i) + "\n";
    definition += i < 39 ? "T" + std::to_string(i + 1) + " a\nT" + std::to_string(i + 1) + " b\n"
                         : "float64 x\n";
  }
  const Recording r = OneTopic("p/Root", definition, MessageEncoding::kRos1, {""});
  const auto start = std::chrono::steady_clock::now();
  // The message is far too short for 2^41 float64: refused at once, not walked.
  EXPECT_THAT(
      FaultOf(r,
              "a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.x"),
      HasSubstr("expected a message of at least"));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

// An array of a type without fields takes no bytes: 2^32 of them are not walked one by one.
TEST(RecordingFields, ArraysOfEmptyTypesTakeNoTime) {
  std::string ros1;
  Append<std::uint32_t>(&ros1, 0xffffffffu);  // items of E
  Append<double>(&ros1, 4.5);
  const Recording r =
      OneTopic("p/M", "E[] many\nfloat64 x\n===\nMSG: p/E\n", MessageEncoding::kRos1, {ros1});
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(FieldValues(r, "/t", {"x"}, "map.yaml")[0][0], 4.5);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

}  // namespace
}  // namespace uuvplan::io
