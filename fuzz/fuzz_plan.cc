// libFuzzer target: the plan readers of `simulate --plan` on fuzzed bytes (plan.json;
// fuzz_input.h): io::ReadScheduleJson, and io::CoupledTrialOfJson for a coupled schedule.
#include "fuzz_input.h"
#include "uuvplan/io/coupled_design_json.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/io/schedule_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "plan.json");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] {
    const nlohmann::json root = uuvplan::io::LoadJson(path);
    if (uuvplan::io::IsCoupledScheduleJson(root)) {
      uuvplan::io::CoupledTrialOfJson(root, path);
    } else {
      uuvplan::io::ReadScheduleJson(path);
    }
  });
  return 0;
}
