// libFuzzer target: io::ReadCampaign on fuzzed bytes (campaign.yaml; fuzz_input.h).
#include "fuzz_input.h"
#include "uuvplan/io/campaign_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = uuvplan::fuzz::WriteInput(data, size, "campaign.yaml");
  uuvplan::fuzz::ExpectOnlyInputErrors([&] { uuvplan::io::ReadCampaign(path); });
  return 0;
}
