// libFuzzer target: io::ReadTruth on fuzzed bytes (fuzzed_truth.yaml; fuzz_input.h).
#include "fuzz_input.h"
#include "uuvplan/io/truth_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "fuzzed_truth.yaml");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] { uuvplan::io::ReadTruth(path); });
  return 0;
}
