// libFuzzer target: io::ReadPool on fuzzed bytes (fuzzed_pool.yaml; fuzz_input.h).
#include "fuzz_input.h"
#include "uuvplan/io/pool_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "fuzzed_pool.yaml");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] { uuvplan::io::ReadPool(path); });
  return 0;
}
