#include "frame/prev_gbuffer.h"

#include "vk/barrier.h"

namespace taa {

namespace {

vk::Image copyOf(vk::Context& ctx, const vk::Image& source, const char* name) {
  vk::ImageDesc d = source.desc();
  d.name = name;
  d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  return vk::Image(ctx, d);
}

void copy(VkCommandBuffer cmd, vk::Image& from, vk::Image& to) {
  if (!to) return;
  vk::BarrierBatch().use(from, vk::Use::TransferSrc).use(to, vk::Use::TransferDst).flush(cmd);
  VkImageCopy region{};
  region.srcSubresource = {from.aspect(), 0, 0, 1};
  region.dstSubresource = {to.aspect(), 0, 0, 1};
  region.extent = {from.desc().width, from.desc().height, 1};
  vkCmdCopyImage(cmd, from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  to.use(cmd, vk::Use::SampledCompute);
}

}  // namespace

PrevGBuffer::PrevGBuffer(vk::Context& ctx, const GBufferNeeds& needs, const GBufferTargets& t) {
  if (needs.prevDepth) depth = copyOf(ctx, t.depth, "prev_depth");
  if (needs.prevNormal) normal = copyOf(ctx, t.normal, "prev_normal");
  if (needs.prevIds) ids = copyOf(ctx, t.ids, "prev_ids");
  if (needs.prevVelocity) velocity = copyOf(ctx, t.velocity, "prev_velocity");
}

void PrevGBuffer::capture(VkCommandBuffer cmd, GBufferTargets& t) {
  copy(cmd, t.depth, depth);
  copy(cmd, t.normal, normal);
  copy(cmd, t.ids, ids);
  copy(cmd, t.velocity, velocity);
}

std::vector<std::string> PrevGBuffer::describe() const {
  std::vector<std::string> out;
  for (const vk::Image* i : {&depth, &normal, &ids, &velocity})
    if (*i) out.push_back(i->desc().name + " " + std::to_string(i->bytes() / 1024) + " KiB");
  return out;
}

}  // namespace taa
