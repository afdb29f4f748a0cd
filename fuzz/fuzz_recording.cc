// libFuzzer target: io::ReadRecording (ROS bag or MCAP) on fuzzed bytes, then io::FieldValues
// of every topic for fields of the common message shapes (fuzz_input.h).
#include "fuzz_input.h"
#include "uuvplan/io/recording.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace io = uuvplan::io;
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "recording.bag");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] {
    std::vector<std::string> topics;
    for (const auto& topic : io::ReadRecording(path, {}).topics) topics.push_back(topic.first);
    const io::Recording recording = io::ReadRecording(path, topics);
    for (const std::string& topic : topics) {
      for (const char* field : {"data[1]", "header.stamp", "twist.linear.y"}) {
        uuvplan::fuzz::ExpectOnlyInputErrors(
            [&] { io::FieldValues(recording, topic, {field}, "fuzz"); });
      }
    }
  });
  return 0;
}
