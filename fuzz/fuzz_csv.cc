// libFuzzer target: io::ReadTrialLog on fuzzed bytes (log.csv; fuzz_input.h).
#include "fuzz_input.h"
#include "uuvplan/io/trial_log_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "log.csv");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] { uuvplan::io::ReadTrialLog(path); });
  return 0;
}
