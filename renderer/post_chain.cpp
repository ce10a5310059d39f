#include "post_chain.h"

#include <stdexcept>

#include "passes/cas.h"
#include "passes/fxaa.h"
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

}  // namespace

struct PostChain::Passes {
  std::unique_ptr<MotionBlurPass> motionBlur;
  std::unique_ptr<SharpenPass> sharpen;
  std::unique_ptr<CasPass> cas;
  std::unique_ptr<FxaaPass> fxaa;
  vk::Image blurred;      // motion blur output, read by the resolve
  vk::Image sharpened;    // sharpen or CAS output
  vk::Image antialiased;  // FXAA output
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
  if (plan.sharpen) p_->sharpen = std::make_unique<SharpenPass>(ctx, post.sharpen_amount);
  if (plan.cas) p_->cas = std::make_unique<CasPass>(ctx, post.sharpen_amount);
  if (plan.sharpen || plan.cas)
    p_->sharpened = makePostImage(ctx, plan.cas ? "cas" : "sharpen", afterSize);
  if (plan.fxaa) {
    p_->fxaa = std::make_unique<FxaaPass>(ctx);
    p_->antialiased = makePostImage(ctx, "fxaa", afterSize);
  }
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
  if (p_->sharpen) {
    timer.begin(cmd, "sharpen");
    p_->sharpen->record(cmd, *current, p_->sharpened, size);
    timer.end(cmd);
    current = &p_->sharpened;
  } else if (p_->cas) {
    timer.begin(cmd, "cas");
    p_->cas->record(cmd, *current, p_->sharpened, size);
    timer.end(cmd);
    current = &p_->sharpened;
  }
  if (p_->fxaa) {
    timer.begin(cmd, "fxaa");
    p_->fxaa->record(cmd, *current, p_->antialiased, size);
    timer.end(cmd);
    current = &p_->antialiased;
  }
  return *current;
}

std::vector<std::string> PostChain::describe() const {
  std::vector<std::string> out;
  if (p_->motionBlur) out.push_back(p_->motionBlur->describe());
  if (p_->sharpen) out.push_back(p_->sharpen->describe());
  if (p_->cas) out.push_back(p_->cas->describe());
  if (p_->fxaa) out.push_back(p_->fxaa->describe());
  for (const vk::Image* image : {&p_->blurred, &p_->sharpened, &p_->antialiased})
    if (*image) out.push_back(describeImage(*image));
  return out;
}

}  // namespace taa
