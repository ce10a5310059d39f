// A user's SPIR-V, checked before any driver sees it: SPIRV-Tools' validator (spirv-val's
// library) for the module as a whole, then the interface a resolve may have (one GLCompute
// entry point whose only inputs are thread ids, and no outputs). glslang emits what the source
// asks for; lavapipe crashes on some of what that is (a pixel shader's inputs in a compute
// stage, OpKill from a compute `discard`), so nothing of the user's runs unchecked.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace taa::user {

// Empty, or why `words` may not run, starting with `name` and ending with the fix.
std::string userSpirvProblem(const std::vector<uint32_t>& words, const std::string& name);

}  // namespace taa::user
