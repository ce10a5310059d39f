// libFuzzer target for the PNG and OpenEXR readers; see fuzz_inputs.h and ci/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  taa::fuzz::readImageBytes(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
