// libFuzzer target for a user's HLSL resolve: the compile and the SPIR-V check; see
// fuzz_inputs.h and ci/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  taa::fuzz::compileHlsl(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
