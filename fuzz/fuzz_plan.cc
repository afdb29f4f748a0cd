// libFuzzer target: the plan readers of `simulate --plan` on fuzzed bytes (plan.json;
// fuzz_input.h): io::ReadScheduleJson, and io::CombinedTrialOfJson for a coupled schedule.
#include "fuzz_input.h"
#include "uuvplan/io/combined_design_json.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/coupled_model.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "plan.json");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] {
    const nlohmann::json root = uuvplan::io::LoadJson(path);
    if (uuvplan::io::IsCombinedScheduleJson(root, uuvplan::model::kCoupledModelName)) {
      const auto coupled = uuvplan::model::CoupledHorizontalModel(uuvplan::model::Vehicle{});
      uuvplan::io::CombinedTrialOfJson(root, path, coupled);
    } else {
      uuvplan::io::ReadScheduleJson(path);
    }
  });
  return 0;
}
