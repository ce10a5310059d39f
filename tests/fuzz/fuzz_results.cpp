// libFuzzer target for the results-file readers (merge, coverage --results, run --verdict-from)
// the golden manifest reader and the Vulkan driver manifest check, on the same bytes;
// see fuzz_inputs.h and ci/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  taa::fuzz::readFolderJson(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
