#include "post_chain.h"

#include <stdexcept>

#include "passes/cas.h"
#include "passes/fxaa.h"
#include "passes/image_pass.h"
#include "passes/motion_blur.h"
#include "passes/post_filter.h"
#include "passes/sharpen.h"
#include "stereo.h"

namespace taa {

namespace {

std::string describeImage(const vk::Image& image) {
  return "buffer " + image.desc().name + " " + std::to_string(image.desc().width) + "x" +
         std::to_string(image.desc().height) + " (" + std::to_string(image.bytes() / 1024) +
         " KiB)";
}

// The passes after the resolve, in the order they run: when a case enables each, and how
// it is built from the case. A new image pass is one line here (its output, named after
// it, is allocated by the chain).
struct AfterResolvePass {
  const char* name;
  bool (*enabled)(const PassPlan& plan);
  std::unique_ptr<ImagePass> (*make)(vk::Context& ctx, const spec::CaseSpec& spec);
};

const AfterResolvePass kAfterResolve[] = {
    {"sharpen", [](const PassPlan& p) { return p.sharpen; },
     [](vk::Context& c, const spec::CaseSpec& s) -> std::unique_ptr<ImagePass> {
       return std::make_unique<SharpenPass>(c, s.post.sharpen_amount);
     }},
    {"cas", [](const PassPlan& p) { return p.cas; },
     [](vk::Context& c, const spec::CaseSpec& s) -> std::unique_ptr<ImagePass> {
       return std::make_unique<CasPass>(c, s.post.sharpen_amount);
     }},
    {"fxaa", [](const PassPlan& p) { return p.fxaa; },
     [](vk::Context& c, const spec::CaseSpec&) -> std::unique_ptr<ImagePass> {
       return std::make_unique<FxaaPass>(c);
     }},
};

}  // namespace

struct PostChain::Passes {
  std::unique_ptr<MotionBlurPass> motionBlur;
  vk::Image blurred;  // motion blur output, read by the resolve
  struct Step {
    const char* name;
    std::unique_ptr<ImagePass> pass;
    vk::Image output;
  };
  std::vector<Step> after;
};

PostChain::PostChain(vk::Context& ctx, const spec::CaseSpec& spec, const PassPlan& plan,
                     glm::ivec2 maxRenderSize)
    : p_(std::make_unique<Passes>()) {
  const auto& post = spec.post;
  if (plan.motionBlur) {
    MotionBlurSettings s;
    s.samples = post.motion_blur_samples;
    s.scale = post.motion_blur_scale;
    s.velocityInAlpha = spec.taa.velocity_in_alpha;
    p_->motionBlur = std::make_unique<MotionBlurPass>(ctx, s);
    p_->blurred = makePostImage(ctx, "motion_blur", maxRenderSize);
  }
  // After the resolve the input is its output (output size); without a resolve it is
  // the render-size colour, allocated at the largest render size.
  const glm::ivec2 afterSize = plan.taa ? outputSize(spec) : maxRenderSize;
  for (const AfterResolvePass& a : kAfterResolve)
    if (a.enabled(plan))
      p_->after.push_back({a.name, a.make(ctx, spec), makePostImage(ctx, a.name, afterSize)});
}

PostChain::~PostChain() = default;

vk::Image& PostChain::beforeResolve(VkCommandBuffer cmd, vk::GpuTimer& timer,
                                    const script::FrameState& state, GBufferTargets& targets) {
  if (!p_->motionBlur) return targets.color;
  timer.begin(cmd, "motion_blur");
  p_->motionBlur->record(cmd, targets.color, targets.velocity, targets.depth, p_->blurred,
                         state.renderSize);
  timer.end(cmd);
  return p_->blurred;
}

vk::Image& PostChain::afterResolve(VkCommandBuffer cmd, vk::GpuTimer& timer,
                                   const script::FrameState&, vk::Image& input, glm::ivec2 size) {
  vk::Image* current = &input;
  for (auto& step : p_->after) {
    timer.begin(cmd, step.name);
    step.pass->record(cmd, *current, step.output, size);
    timer.end(cmd);
    current = &step.output;
  }
  return *current;
}

GBufferNeeds PostChain::needs() const {
  GBufferNeeds n;
  n.velocity = p_->motionBlur != nullptr;  // it blurs along each pixel's velocity
  return n;
}

std::vector<std::string> PostChain::describe() const {
  std::vector<std::string> out;
  if (p_->motionBlur) out.push_back(p_->motionBlur->describe());
  for (const auto& step : p_->after) out.push_back(step.pass->describe());
  if (p_->blurred) out.push_back(describeImage(p_->blurred));
  for (const auto& step : p_->after) out.push_back(describeImage(step.output));
  return out;
}

}  // namespace taa
