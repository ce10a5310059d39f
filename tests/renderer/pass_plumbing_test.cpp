// The plumbing every pass records through: batched barriers, the staging ring of
// readbacks and descriptor pushes checked against the reflected layout.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "common/shared.h"
#include "support/gpu.h"
#include "vk/barrier.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/staging_ring.h"

namespace taa {
namespace {

vk::Image plumbingImage(const char* name, uint32_t width, uint32_t height) {
  vk::ImageDesc d;
  d.name = name;
  d.width = width;
  d.height = height;
  d.format = VK_FORMAT_R32_SFLOAT;
  d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
            VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  return vk::Image(test::gpu(), d);
}

void clearTo(VkCommandBuffer cmd, vk::Image& image, float value) {
  image.use(cmd, vk::Use::TransferDst);
  VkClearColorValue c{};
  c.float32[0] = value;
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &c, 1, &range);
}

TEST(PassPlumbing, RepeatedReadsNeedNoBarrierWritesAlwaysDo) {
  vk::Image image = plumbingImage("plumbing", 4, 4);
  EXPECT_TRUE(image.transition(vk::Use::SampledCompute).has_value()) << "from undefined";
  EXPECT_FALSE(image.transition(vk::Use::SampledCompute).has_value()) << "read after the same read";
  // Another reading stage needs one: a later write's barrier must cover both stages.
  EXPECT_TRUE(image.transition(vk::Use::SampledGraphics).has_value());
  EXPECT_TRUE(image.transition(vk::Use::StorageWrite).has_value());
  EXPECT_TRUE(image.transition(vk::Use::StorageWrite).has_value()) << "write after write";
  EXPECT_EQ(image.lastUse(), vk::Use::StorageWrite);
}

TEST(PassPlumbing, OneTransitionPointTakesEachImageOnce) {
  vk::Image a = plumbingImage("a", 4, 4), b = plumbingImage("b", 4, 4);
  vk::BarrierBatch batch;
  batch.use(a, vk::Use::SampledCompute).use(b, vk::Use::StorageWrite);
  batch.use(a, vk::Use::SampledCompute);  // the same image bound twice for reading: kept once
  EXPECT_EQ(batch.pending(), 2u);
  EXPECT_THROW(batch.use(b, vk::Use::SampledCompute), std::logic_error)
      << "one barrier call cannot order two transitions of one image";
  VkCommandBuffer cmd = test::gpu().beginCommands();
  batch.flush(cmd);
  EXPECT_EQ(batch.pending(), 0u);
  test::gpu().submitAndWait(cmd);
}

TEST(PassPlumbing, StagingRingIsReusedAcrossFrames) {
  vk::Context& ctx = test::gpu();
  vk::Image a = plumbingImage("ring_a", 16, 8), b = plumbingImage("ring_b", 32, 8);
  // Deliberately small: the first frame outgrows it, later frames fit what it settled at.
  vk::StagingRing ring(ctx, 64);
  for (int frame = 0; frame < 3; ++frame) {
    VkCommandBuffer cmd = ctx.beginCommands();
    clearTo(cmd, a, 1.5f + float(frame));
    clearTo(cmd, b, -2.0f - float(frame));
    vk::BarrierBatch().use(a, vk::Use::TransferSrc).use(b, vk::Use::TransferSrc).flush(cmd);
    ring.reset();
    const auto slotA = ring.copyImage(cmd, a);
    const auto slotB = ring.copyImage(cmd, b);
    ring.finishCopies(cmd);
    ctx.submitAndWait(cmd);
    float first = 0.0f, last = 0.0f;
    std::memcpy(&first, ring.data(slotA), 4);
    std::memcpy(&last, ring.data(slotB) + slotB.bytes - 4, 4);
    EXPECT_EQ(first, 1.5f + float(frame));
    EXPECT_EQ(last, -2.0f - float(frame));
    EXPECT_EQ(slotA.bytes, 16u * 8u * 4u);
    EXPECT_EQ(slotB.bytes, 32u * 8u * 4u);
  }
  // 64 bytes, two growths in the first frame, the one buffer the second frame's reset
  // settled into, and none since. That one holds the first frame's three together: a ring
  // that kept them apart would have grown again in the second frame, to 2048.
  EXPECT_EQ(ring.buffersCreated(), 4);
  EXPECT_EQ(ring.capacity(), VkDeviceSize(64 + 16 * 8 * 4 + 32 * 8 * 4));
  // A copy of an image not made ready for it is a bug of the caller.
  VkCommandBuffer cmd = ctx.beginCommands();
  clearTo(cmd, a, 0.0f);
  EXPECT_THROW(ring.copyImage(cmd, a), std::logic_error);
  ctx.submitAndWait(cmd);
}

TEST(PassPlumbing, DescriptorPushesAreCheckedAgainstTheShader) {
  vk::Context& ctx = test::gpu();
  const vk::Pipeline sharpen = vk::createComputePipeline(ctx, "sharpen.comp");
  EXPECT_EQ(sharpen.interface().pushConstantBytes, sizeof(gpu::PostPush));
  vk::Image image = plumbingImage("push_check", 4, 4);
  VkCommandBuffer cmd = ctx.beginCommands();
  // The input is sampled: a storage image there is refused before anything is recorded.
  EXPECT_THROW(vk::Bindings().storage(POST_BINDING_INPUT, image.view()).push(ctx, cmd, sharpen),
               std::logic_error);
  // The shader has no mask binding.
  EXPECT_THROW(vk::Bindings().storage(POST_BINDING_MASK, image.view()).push(ctx, cmd, sharpen),
               std::logic_error);
  const gpu::PostPush push{};
  EXPECT_THROW(sharpen.pushConstants(cmd, &push, sizeof(push) + 16), std::logic_error);
  ctx.submitAndWait(cmd);
}

}  // namespace
}  // namespace taa
