// libFuzzer target for the SPIR-V cache's entry reader; see fuzz_inputs.h and ci/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)taa::fuzz::readSpirvCacheEntry(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
