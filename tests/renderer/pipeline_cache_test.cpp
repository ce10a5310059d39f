// One pipeline per context and set of inputs (vk/pipeline_cache.h): a second request with the
// same shader, constants and state gets the compiled one; any difference makes another.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "support/gpu.h"
#include "vk/pipeline.h"
#include "vk/pipeline_cache.h"

namespace taa {
namespace {

TEST(PipelineCache, SameComputeInputsShareOnePipeline) {
  auto& ctx = test::gpu();
  const auto before = ctx.pipelines().stats();
  const auto spec = vk::SpecConstants().set(0, 1u).setFloat(1, 0.5f);
  const vk::Pipeline a = vk::createComputePipeline(ctx, "sharpen.comp", spec);
  const vk::Pipeline b = vk::createComputePipeline(ctx, "sharpen.comp", spec);
  EXPECT_EQ(a.handle(), b.handle());
  EXPECT_EQ(ctx.pipelines().stats().reused, before.reused + 1);
  const vk::Pipeline other = vk::createComputePipeline(ctx, "sharpen.comp", vk::SpecConstants().set(0, 2u).setFloat(1, 0.5f));
  EXPECT_NE(other.handle(), a.handle());
  const vk::Pipeline otherId = vk::createComputePipeline(ctx, "sharpen.comp", vk::SpecConstants().set(2, 1u).setFloat(1, 0.5f));
  EXPECT_NE(otherId.handle(), a.handle());
  const vk::Pipeline otherShader = vk::createComputePipeline(ctx, "cas.comp", spec);
  EXPECT_NE(otherShader.handle(), a.handle());
  // The same SPIR-V under another name is another pipeline (names are what messages show).
  const auto words = vk::loadSpirv("sharpen.comp");
  EXPECT_EQ(vk::createComputePipelineFromSpirv(ctx, "sharpen.comp", words, spec).handle(), a.handle());
  EXPECT_NE(vk::createComputePipelineFromSpirv(ctx, "mine.comp", words, spec).handle(), a.handle());
}

TEST(PipelineCache, EveryGraphicsFieldIsInTheKey) {
  vk::GraphicsDesc d;
  d.vertexShader = "gbuffer.vert";
  d.fragmentShader = "gbuffer.frag.0";
  d.colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT};
  d.depthFormat = VK_FORMAT_D32_SFLOAT;
  const auto vert = vk::loadSpirv(d.vertexShader), frag = vk::loadSpirv(d.fragmentShader);
  const std::string base = vk::graphicsPipelineKey("gbuffer", d, vert, frag);
  // One change per field of GraphicsDesc (its static_assert keeps this list complete).
  const std::vector<std::pair<const char*, std::function<void(vk::GraphicsDesc&)>>> changes = {
      {"vertexShader", [](auto& g) { g.vertexShader = "sky.vert"; }},
      {"fragmentShader", [](auto& g) { g.fragmentShader = "gbuffer.frag.1"; }},
      {"spec", [](auto& g) { g.spec.set(0, 1u); }},
      {"vertexInput", [](auto& g) { g.vertexInput = false; }},
      {"colorFormats", [](auto& g) { g.colorFormats.push_back(VK_FORMAT_R16G16_SFLOAT); }},
      {"colorFormats[0]", [](auto& g) { g.colorFormats[0] = VK_FORMAT_R32G32B32A32_SFLOAT; }},
      {"depthFormat", [](auto& g) { g.depthFormat = VK_FORMAT_UNDEFINED; }},
      {"depthTest", [](auto& g) { g.depthTest = false; }},
      {"depthWrite", [](auto& g) { g.depthWrite = false; }},
      {"depthCompare", [](auto& g) { g.depthCompare = VK_COMPARE_OP_EQUAL; }},
      {"cullMode", [](auto& g) { g.cullMode = VK_CULL_MODE_NONE; }},
      {"blendFirstAttachment", [](auto& g) { g.blendFirstAttachment = true; }},
      {"samples", [](auto& g) { g.samples = 4; }},
  };
  for (const auto& [field, change] : changes) {
    vk::GraphicsDesc c = d;
    change(c);
    EXPECT_NE(vk::graphicsPipelineKey("gbuffer", c, vk::loadSpirv(c.vertexShader),
                                      vk::loadSpirv(c.fragmentShader)),
              base)
        << field;
  }
  EXPECT_NE(vk::graphicsPipelineKey("sky", d, vert, frag), base);
  EXPECT_EQ(vk::graphicsPipelineKey("gbuffer", d, vert, frag), base);
}

TEST(PipelineCache, KeepsAtMostItsUnusedPipelinesAndEveryHeldOne) {
  vk::PipelineCache cache(2);
  int made = 0;
  auto make = [&] {
    ++made;
    return std::make_shared<const vk::PipelineObjects>();
  };
  const auto held = cache.get("held", make);
  for (const char* k : {"a", "b", "c", "d"}) cache.get(k, make);
  // "held", "d" (held by its caller while it was kept, so not counted unused then) and the two
  // most recent unused ones before it; "a" went.
  EXPECT_EQ(cache.size(), 4u);
  cache.get("held", make);
  cache.get("d", make);
  EXPECT_EQ(made, 5);
  cache.get("a", make);  // dropped: made again
  EXPECT_EQ(made, 6);
  EXPECT_EQ(cache.stats().created, 6u);
  EXPECT_EQ(cache.stats().reused, 2u);
}

}  // namespace
}  // namespace taa
