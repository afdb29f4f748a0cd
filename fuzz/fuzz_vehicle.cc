// libFuzzer target: io::ReadVehicle on fuzzed bytes (fuzzed_vehicle.yaml; fuzz_input.h).
#include "fuzz_input.h"
#include "uuvplan/io/vehicle_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "fuzzed_vehicle.yaml");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] { uuvplan::io::ReadVehicle(path); });
  return 0;
}
