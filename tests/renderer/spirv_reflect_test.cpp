// The reflection unit read against our own shaders' SPIR-V: every layout the renderer
// builds comes from it, so each expectation here is one the C++ used to type by hand
// (shaders/common/shared.h names the bindings).
#include "vk/spirv_reflect.h"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

#include "common/shared.h"
#include "passes/resolve_inputs.h"
#include "vk/pipeline.h"

namespace taa::vk {
namespace {

ShaderInterface reflectShader(const std::string& name) {
  return reflectSpirv(loadSpirv(name), name);
}

VkDescriptorType typeAt(const ShaderInterface& s, uint32_t binding) {
  const ReflectedBinding* b = s.find(0, binding);
  return b ? b->type : VK_DESCRIPTOR_TYPE_MAX_ENUM;
}

TEST(SpirvReflect, ResolveBindingsAreTheSharedHeaderOnes) {
  const ShaderInterface s = reflectShader("taa_resolve.comp");
  EXPECT_EQ(s.stages, VkShaderStageFlags(VK_SHADER_STAGE_COMPUTE_BIT));
  // The uniforms, three outputs and one sampler per row of the input table.
  std::map<uint32_t, VkDescriptorType> want = {
      {TAA_BINDING_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
      {TAA_BINDING_HISTORY_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
      {TAA_BINDING_DEBUG_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
      {TAA_BINDING_REJECT_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
  for (const ResolveInputInfo& i : kResolveInputs)
    want[i.binding] = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  ASSERT_EQ(s.bindings.size(), want.size());
  for (const ReflectedBinding& b : s.bindings) {
    ASSERT_TRUE(want.count(b.binding)) << "binding " << b.binding;
    EXPECT_EQ(b.type, want[b.binding]) << "binding " << b.binding;
    EXPECT_EQ(b.count, 1u);
    EXPECT_EQ(b.set, 0u);
  }
  EXPECT_EQ(s.pushConstantBytes, 0u);
  EXPECT_EQ(s.localSize, (std::array<uint32_t, 3>{8, 8, 1}));
  EXPECT_EQ(s.localSizeSpecId, (std::array<int32_t, 3>{-1, -1, -1}));
}

TEST(SpirvReflect, PushConstantBlocksHaveTheirCppSize) {
  EXPECT_EQ(reflectShader("motion_blur.comp").pushConstantBytes, sizeof(gpu::PostPush));
  EXPECT_EQ(reflectShader("sharpen.comp").pushConstantBytes, sizeof(gpu::PostPush));
  EXPECT_EQ(reflectShader("inject.comp").pushConstantBytes, sizeof(gpu::InjectPush));
  // ivec2 size, uint mode, float invCount, int offsetX: std430 packs them in 20 bytes.
  EXPECT_EQ(reflectShader("reference_accumulate.comp").pushConstantBytes, 20u);
  EXPECT_EQ(reflectShader("inject.comp").localSize, (std::array<uint32_t, 3>{8, 1, 1}));
}

TEST(SpirvReflect, StorageBuffersArraysAndOptionalBindings) {
  const ShaderInterface trace = reflectShader("adaptive_trace.comp");
  const ReflectedBinding* textures = trace.find(0, TRACE_BINDING_TEXTURES);
  ASSERT_NE(textures, nullptr);
  EXPECT_EQ(textures->type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  EXPECT_EQ(textures->count, uint32_t(TRACE_MAX_TEXTURES));
  EXPECT_EQ(typeAt(trace, TRACE_BINDING_NODES), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_EQ(typeAt(trace, TRACE_BINDING_PARAMS), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  EXPECT_EQ(typeAt(trace, TRACE_BINDING_OUT), VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);

  // TSCMAA's steps declare only what each uses: no placeholder bindings.
  const ShaderInterface edges = reflectShader("tscmaa_edges.comp");
  EXPECT_EQ(typeAt(edges, TSCMAA_BINDING_EDGE_LIST), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_EQ(edges.find(0, TSCMAA_BINDING_HISTORY), nullptr);
  EXPECT_EQ(reflectShader("tscmaa_cmaa.comp").localSize[0], uint32_t(TSCMAA_LIST_GROUP));

  // FXAA has the mask binding the other post filters lack.
  EXPECT_EQ(typeAt(reflectShader("fxaa.comp"), POST_BINDING_MASK),
            VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  EXPECT_EQ(reflectShader("cas.comp").find(0, POST_BINDING_MASK), nullptr);
}

TEST(SpirvReflect, GraphicsStagesMerge) {
  const ShaderInterface vert = reflectShader("gbuffer.vert");
  const ShaderInterface frag = reflectShader("gbuffer.frag.0");
  EXPECT_EQ(vert.stages, VkShaderStageFlags(VK_SHADER_STAGE_VERTEX_BIT));
  EXPECT_EQ(frag.stages, VkShaderStageFlags(VK_SHADER_STAGE_FRAGMENT_BIT));
  const ShaderInterface both = mergeInterfaces(vert, frag, "gbuffer");
  EXPECT_EQ(both.stages,
            VkShaderStageFlags(VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT));
  EXPECT_EQ(both.pushConstantBytes, sizeof(gpu::DrawPush));
  EXPECT_EQ(typeAt(both, GBUF_BINDING_FRAME), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  EXPECT_EQ(typeAt(both, GBUF_BINDING_INSTANCES), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_EQ(typeAt(both, GBUF_BINDING_PREV_POSITIONS), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  const ReflectedBinding* texture = both.find(0, GBUF_BINDING_TEXTURE);
  ASSERT_NE(texture, nullptr);
  EXPECT_EQ(texture->type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  EXPECT_TRUE(texture->stages & VK_SHADER_STAGE_FRAGMENT_BIT);

  // Two stages that disagree on a binding's type are refused, naming the pipeline.
  ShaderInterface clash = frag;
  clash.bindings.front().type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  try {
    mergeInterfaces(vert, clash, "clashing");
    ADD_FAILURE() << "a type clash was merged";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("clashing"), std::string::npos) << e.what();
  }
}

// A hand-assembled compute module whose WorkgroupSize is built from a specialization
// constant (SpecId 7) and two plain constants, as local_size_x_id = 7 compiles.
std::vector<uint32_t> specializedWorkgroupModule() {
  auto op = [](uint32_t words, uint32_t opcode) { return (words << 16) | opcode; };
  return {0x07230203u, 0x00010000u, 0,  20,          0,  op(2, 17), 1,  // OpCapability Shader
          op(3, 14),   0,           1,                       // OpMemoryModel Logical GLSL450
          op(5, 15),   5,           1,  0x6e69616du, 0,      // OpEntryPoint GLCompute %1 "main"
          op(6, 16),   1,           17, 4,           2,  1,  // OpExecutionMode %1 LocalSize 4 2 1
          op(4, 71),   10,          1,  7,                   // OpDecorate %10 SpecId 7
          op(4, 71),   13,          11, 25,                  // OpDecorate %13 BuiltIn WorkgroupSize
          op(4, 21),   2,           32, 0,                   // %2 = OpTypeInt 32 0
          op(4, 23),   3,           2,  3,                   // %3 = OpTypeVector %2 3
          op(4, 50),   2,           10, 4,                   // %10 = OpSpecConstant %2 4
          op(4, 43),   2,           11, 2,                   // %11 = OpConstant %2 2
          op(4, 43),   2,           12, 1,                   // %12 = OpConstant %2 1
          op(6, 51),   3,           13, 10,          11, 12};  // %13 = OpSpecConstantComposite
}

TEST(SpirvReflect, SpecializedWorkgroupSize) {
  const ShaderInterface s = reflectSpirv(specializedWorkgroupModule(), "handmade");
  EXPECT_EQ(s.localSize, (std::array<uint32_t, 3>{4, 2, 1}));
  EXPECT_EQ(s.localSizeSpecId, (std::array<int32_t, 3>{7, -1, -1}));
  EXPECT_TRUE(s.bindings.empty());
  SpecConstants spec;
  spec.set(7u, 16u);
  EXPECT_EQ(spec.value(7), std::optional<uint32_t>(16u));
  EXPECT_EQ(spec.value(8), std::nullopt);
}

TEST(SpirvReflect, MalformedModulesAreRefusedByName) {
  auto refused = [](std::vector<uint32_t> words) {
    try {
      reflectSpirv(words, "broken.comp");
    } catch (const std::runtime_error& e) {
      return std::string(e.what()).find("broken.comp") != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refused({}));
  EXPECT_TRUE(refused({0xdeadbeefu, 0x00010000u, 0, 20, 0}));
  auto truncated = specializedWorkgroupModule();
  truncated.resize(truncated.size() - 2);  // the last instruction runs past the end
  EXPECT_TRUE(refused(truncated));
  auto noEntry = specializedWorkgroupModule();
  noEntry[10] = (5u << 16) | 8u;  // the entry point becomes an unknown, ignored opcode
  EXPECT_TRUE(refused(noEntry));
}

}  // namespace
}  // namespace taa::vk
