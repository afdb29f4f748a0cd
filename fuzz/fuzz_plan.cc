// libFuzzer target: io::ReadScheduleJson on fuzzed bytes (plan.json; fuzz_input.h).
#include "fuzz_input.h"
#include "uuvplan/io/schedule_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "plan.json");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] { uuvplan::io::ReadScheduleJson(path); });
  return 0;
}
