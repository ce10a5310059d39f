// What a pipeline's layout needs, read from the shader's own SPIR-V: its descriptor
// bindings (set, binding, type, array size), its push-constant block size and its
// workgroup size. Layouts derived this way cannot drift from the shader, so a pass states
// only the shader it runs; the C++ never types a binding list by hand.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/errors.h"

namespace taa::vk {

// A module the layer cannot build a pipeline from: malformed SPIR-V, a resource it cannot
// bind, a set other than 0, a stage that is not compute where one is, stages that disagree.
// The shaders the harness ships are checked by its tests, so only a user's shader
// (taa.shader) meets it: bad input, naming the shader.
class ShaderInterfaceError : public InputError {
 public:
  using InputError::InputError;
};

struct ReflectedBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t count = 1;  // array elements
  VkShaderStageFlags stages = 0;
  uint32_t bytes = 0;  // uniform and storage buffers: the block's size (saturates at 2^32 - 1)
};

struct ShaderInterface {
  VkShaderStageFlags stages = 0;
  std::string entryPoint = "main";          // the module's one entry point
  std::vector<ReflectedBinding> bindings;  // sorted by set, then binding
  uint32_t pushConstantBytes = 0;
  // Compute only: the workgroup size, and per dimension the specialization-constant id
  // that overrides it (local_size_x_id or a specialized WorkgroupSize), -1 for none.
  std::array<uint32_t, 3> localSize{1, 1, 1};
  std::array<int32_t, 3> localSizeSpecId{-1, -1, -1};

  // The binding at (set, binding), or null.
  const ReflectedBinding* find(uint32_t set, uint32_t binding) const;
};

// Parses one module. Throws ShaderInterfaceError naming `name` on a malformed module or on
// a resource the layer cannot bind (runtime arrays, more than one entry point).
ShaderInterface reflectSpirv(const std::vector<uint32_t>& words, const std::string& name);

// The interface of a pipeline made of several stages: a binding both stages declare
// must agree on type and count; push constants span the larger block.
ShaderInterface mergeInterfaces(const ShaderInterface& a, const ShaderInterface& b,
                                const std::string& name);

const char* descriptorTypeName(VkDescriptorType type);

}  // namespace taa::vk
