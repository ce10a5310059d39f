#include "post_chain.h"

namespace taa {

struct PostChain::Passes {};

PostChain::PostChain(vk::Context&, const spec::CaseSpec&, const PassPlan&, glm::ivec2)
    : p_(std::make_unique<Passes>()) {}

PostChain::~PostChain() = default;

vk::Image& PostChain::beforeResolve(VkCommandBuffer, vk::GpuTimer&, const script::FrameState&,
                                    GBufferTargets& targets) {
  return targets.color;
}

vk::Image& PostChain::afterResolve(VkCommandBuffer, vk::GpuTimer&, const script::FrameState&, vk::Image& input,
                                   glm::ivec2) {
  return input;
}

std::vector<std::string> PostChain::describe() const { return {}; }

}  // namespace taa
