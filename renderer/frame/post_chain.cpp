#include "frame/post_chain.h"

#include <stdexcept>

#include "passes/adaptive/adaptive.h"
#include "passes/cas.h"
#include "passes/fxaa.h"
#include "passes/image_pass.h"
#include "passes/motion_blur.h"
#include "passes/post_filter.h"
#include "passes/sharpen.h"
#include "script/stereo.h"

namespace taa {

namespace {

std::string describeImage(const vk::Image& image) {
  return "buffer " + image.desc().name + " " + std::to_string(image.desc().width) + "x" +
         std::to_string(image.desc().height) + " (" + std::to_string(image.bytes() / 1024) +
         " KiB)";
}

// Each table lists its passes in the order they run: when a case enables each, and how it
// is built. A new pass is one line in one of them; the chain allocates the outputs (named
// after the pass), times the passes and logs them.
template <typename Pass>
struct PassEntry {
  const char* name;
  bool (*enabled)(const PassPlan& plan);
  std::unique_ptr<Pass> (*make)(const PassContext& c);
};

// Before the resolve, once per eye, at render size.
const PassEntry<BeforeResolvePass> kBeforeResolve[] = {
    {"motion_blur", [](const PassPlan& p) { return p.motionBlur; },
     [](const PassContext& c) -> std::unique_ptr<BeforeResolvePass> {
       MotionBlurSettings s;
       s.samples = c.spec.post.motion_blur_samples;
       s.scale = c.spec.post.motion_blur_scale;
       s.velocityInAlpha = c.spec.taa.velocity_in_alpha;
       return std::make_unique<MotionBlurPass>(c.ctx, s);
     }},
};

// Following the resolve, on its output, with its outputs and the scene; they time
// themselves (one pass may run several dispatches).
const PassEntry<ResolveFollower> kFollowResolve[] = {
    {"adaptive", [](const PassPlan& p) { return p.adaptive; },
     [](const PassContext& c) -> std::unique_ptr<ResolveFollower> {
       return std::make_unique<AdaptivePass>(c.ctx, c.spec, c.scene, c.firstFrame,
                                             c.options.captures);
     }},
};

// After the resolve (and its followers), image to image.
const PassEntry<ImagePass> kAfterResolve[] = {
    {"sharpen", [](const PassPlan& p) { return p.sharpen; },
     [](const PassContext& c) -> std::unique_ptr<ImagePass> {
       return std::make_unique<SharpenPass>(c.ctx, c.spec.post.sharpen_amount);
     }},
    {"cas", [](const PassPlan& p) { return p.cas; },
     [](const PassContext& c) -> std::unique_ptr<ImagePass> {
       return std::make_unique<CasPass>(c.ctx, c.spec.post.sharpen_amount);
     }},
    {"fxaa", [](const PassPlan& p) { return p.fxaa; },
     [](const PassContext& c) -> std::unique_ptr<ImagePass> {
       return std::make_unique<FxaaPass>(c.ctx);
     }},
};

}  // namespace

struct PostChain::Passes {
  template <typename Pass>
  struct Step {
    const char* name;
    std::unique_ptr<Pass> pass;
    vk::Image output;  // none for followers: they write into the resolve's output
  };
  std::vector<Step<BeforeResolvePass>> before;
  std::vector<Step<ResolveFollower>> follow;
  std::vector<Step<ImagePass>> after;
};

PostChain::PostChain(const PassContext& c, const PassPlan& plan, glm::ivec2 maxRenderSize)
    : p_(std::make_unique<Passes>()) {
  for (const auto& e : kBeforeResolve)
    if (e.enabled(plan))
      p_->before.push_back({e.name, e.make(c), makePostImage(c.ctx, e.name, maxRenderSize)});
  for (const auto& e : kFollowResolve)
    if (e.enabled(plan)) p_->follow.push_back({e.name, e.make(c), vk::Image()});
  // After the resolve the input is its output (output size); without a resolve it is
  // the render-size colour, allocated at the largest render size.
  const glm::ivec2 afterSize = plan.taa ? outputSize(c.spec) : maxRenderSize;
  for (const auto& e : kAfterResolve)
    if (e.enabled(plan))
      p_->after.push_back({e.name, e.make(c), makePostImage(c.ctx, e.name, afterSize)});
}

PostChain::~PostChain() = default;

vk::Image& PostChain::beforeResolve(const FrameView& eye, vk::Image& color) {
  vk::Image* current = &color;
  for (auto& step : p_->before) {
    eye.timer->begin(eye.cmd, step.name);
    step.pass->record(eye, *current, step.output);
    eye.timer->end(eye.cmd);
    current = &step.output;
  }
  return *current;
}

vk::Image& PostChain::followResolve(const FrameView& frame, ResolveStage& resolve,
                                    vk::Image& resolveInput) {
  vk::Image* current = &resolve.output();
  for (auto& step : p_->follow)
    current = &step.pass->record(frame, resolve, resolveInput, *current);
  return *current;
}

vk::Image& PostChain::afterResolve(const FrameView& frame, vk::Image& input, glm::ivec2 size) {
  vk::Image* current = &input;
  for (auto& step : p_->after) {
    frame.timer->begin(frame.cmd, step.name);
    step.pass->record(frame.cmd, *current, step.output, size);
    frame.timer->end(frame.cmd);
    current = &step.output;
  }
  return *current;
}

vk::Image* PostChain::debugView() {
  vk::Image* view = nullptr;
  for (auto& step : p_->follow)
    if (vk::Image* v = step.pass->debugView()) view = v;
  return view;
}

std::vector<StageCapture> PostChain::captures() {
  std::vector<StageCapture> out;
  for (auto& step : p_->follow)
    for (auto& c : step.pass->captures()) out.push_back(std::move(c));
  return out;
}

std::vector<std::pair<std::string, double>> PostChain::stats() const {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& step : p_->follow)
    for (auto& s : step.pass->stats()) out.push_back(std::move(s));
  return out;
}

GBufferNeeds PostChain::needs() const {
  GBufferNeeds n;
  for (const auto& step : p_->before) n |= step.pass->needs();
  for (const auto& step : p_->follow) n |= step.pass->needs();
  return n;
}

std::vector<std::string> PostChain::describe() const {
  std::vector<std::string> out;
  for (const auto& step : p_->before) out.push_back(step.pass->describe());
  for (const auto& step : p_->follow)
    for (auto& line : step.pass->describe()) out.push_back(std::move(line));
  for (const auto& step : p_->after) out.push_back(step.pass->describe());
  for (const auto& step : p_->before) out.push_back(describeImage(step.output));
  for (const auto& step : p_->after) out.push_back(describeImage(step.output));
  return out;
}

}  // namespace taa
