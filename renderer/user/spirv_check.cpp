#include "user/spirv_check.h"

#include <map>
#include <set>
#include <spirv-tools/libspirv.hpp>

namespace taa::user {

namespace {

// SPIR-V opcodes, storage classes and built-ins read here (SPIR-V specification, section 3).
constexpr uint32_t kOpEntryPoint = 15, kOpVariable = 59, kOpDecorate = 71;
constexpr uint32_t kDecoBuiltIn = 11, kDecoLocation = 30;
constexpr uint32_t kStorageInput = 1, kStorageOutput = 3, kModelGLCompute = 5;

// The thread ids a compute stage has: NumWorkgroups, WorkgroupId, LocalInvocationId,
// GlobalInvocationId, LocalInvocationIndex, SubgroupSize, NumSubgroups, SubgroupId,
// SubgroupLocalInvocationId.
bool computeBuiltIn(uint32_t b) {
  static const std::set<uint32_t> ids = {24, 26, 27, 28, 29, 36, 38, 40, 41};
  return ids.count(b) > 0;
}

std::string interfaceProblem(const std::vector<uint32_t>& w, const std::string& name) {
  std::map<uint32_t, uint32_t> builtIn;
  std::set<uint32_t> located;
  std::vector<std::pair<uint32_t, uint32_t>> io;  // variable, storage class
  size_t entries = 0;
  uint32_t model = kModelGLCompute;
  for (size_t i = 5; i < w.size();) {
    const uint32_t count = w[i] >> 16, op = w[i] & 0xffffu;
    if (count == 0 || i + count > w.size()) return name + ": its SPIR-V is truncated";
    if (op == kOpEntryPoint && count >= 3) {
      ++entries;
      model = w[i + 1];
    }
    if (op == kOpDecorate && count >= 4 && w[i + 2] == kDecoBuiltIn) builtIn[w[i + 1]] = w[i + 3];
    if (op == kOpDecorate && count >= 3 && w[i + 2] == kDecoLocation) located.insert(w[i + 1]);
    if (op == kOpVariable && count >= 4 &&
        (w[i + 3] == kStorageInput || w[i + 3] == kStorageOutput))
      io.emplace_back(w[i + 2], w[i + 3]);
    i += count;
  }
  if (entries != 1 || model != kModelGLCompute)
    return name + ": its SPIR-V has " + std::to_string(entries) +
           " entry points or another stage than compute; a resolve is one compute shader";
  for (const auto& [id, storage] : io) {
    if (storage == kStorageOutput)
      return name +
             ": its entry point has an output (a return value or out parameter), which "
             "a compute shader does not have; return void and write taa_output";
    const auto b = builtIn.find(id);
    if (b == builtIn.end() || !computeBuiltIn(b->second))
      return name + ": its entry point takes an input that is not a compute thread id (" +
             (b == builtIn.end()
                  ? std::string(located.count(id) ? "a user semantic or none" : "no built-in")
                  : "built-in " + std::to_string(b->second)) +
             "); take only SV_DispatchThreadID, SV_GroupID, SV_GroupThreadID or SV_GroupIndex";
  }
  return "";
}

}  // namespace

std::string userSpirvProblem(const std::vector<uint32_t>& words, const std::string& name) {
  if (words.size() < 5 || words[0] != 0x07230203u) return name + ": its SPIR-V has no header";
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
  std::string first;
  tools.SetMessageConsumer(
      [&](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
        if (first.empty() && level <= SPV_MSG_ERROR) first = message;
      });
  spvtools::ValidatorOptions options;
  if (!tools.Validate(words.data(), words.size(), options))
    return name + ": its SPIR-V is not valid for Vulkan 1.2 (spirv-val: " +
           (first.empty() ? std::string("no reason given") : first.substr(0, 400)) +
           "); the source compiles to something no driver may run (a pixel shader's "
           "`discard` in a compute shader?), change it";
  return interfaceProblem(words, name);
}

}  // namespace taa::user
