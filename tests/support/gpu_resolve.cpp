#include "support/gpu_resolve.h"

#include <stdexcept>

#include "core/image_io.h"
#include "frame/pass_plan.h"
#include "passes/taa_resolve.h"
#include "script/frame_state.h"
#include "support/gpu.h"
#include "vk/timestamps.h"

namespace taa::test {

namespace {

// What a trip through a half-float target leaves of `image`.
Image roundToHalf(Image image) {
  for (float& v : image.data) v = halfBitsToFloat(floatToHalfBits(v));
  return image;
}

void runFrame(TaaResolvePass& pass, const script::FrameState& state, const ResolveInputs& in) {
  vk::GpuTimer timer(gpu());
  VkCommandBuffer cmd = gpu().beginCommands();
  pass.record(cmd, timer, state, 0, in);
  gpu().submitAndWait(cmd);
}

}  // namespace

GpuResolveResult gpuResolve(const spec::CaseSpec& spec, const SyntheticResolve& in) {
  script::FrameState seed = script::frameState(spec, 0);
  script::FrameState frame = script::frameState(spec, 1);
  if (!seed.resetHistory || frame.resetHistory)
    throw std::invalid_argument("gpuResolve: frame 1 of the case must keep the history");
  const glm::ivec2 render = frame.renderSize;
  if (in.current.width != render.x || in.current.height != render.y ||
      in.history.width != spec.render.width || in.history.height != spec.render.height)
    throw std::invalid_argument("gpuResolve: image sizes do not match the case");
  seed.jitter = frame.jitter = glm::vec2(0.0f);

  Image velocity(render.x, render.y, 2);
  for (size_t p = 0; p < velocity.pixelCount(); ++p) {
    velocity.data[2 * p] = in.velocityPx.x;
    velocity.data[2 * p + 1] = in.velocityPx.y;
  }
  Image depth(render.x, render.y, 1, in.depth);
  vk::Image historyInput = uploadFloatImage(in.history, VK_FORMAT_R16G16B16A16_SFLOAT, "seed");
  vk::Image color = uploadFloatImage(in.current, VK_FORMAT_R16G16B16A16_SFLOAT, "current");
  vk::Image velocityImage = uploadFloatImage(velocity, VK_FORMAT_R16G16_SFLOAT, "velocity");
  vk::Image depthImage = uploadFloatImage(depth, VK_FORMAT_R32_SFLOAT, "depth");

  const PassPlan plan = planPasses(spec);
  TaaResolvePass pass(gpu(), spec, plan);
  ResolveInputs inputs;
  inputs[ResolveInput::Depth] = &depthImage;
  inputs[ResolveInput::Velocity] = &velocityImage;
  inputs[ResolveInput::Color] = &historyInput;
  runFrame(pass, seed, inputs);
  GpuResolveResult out;
  out.history = downloadImage(pass.output());
  inputs[ResolveInput::Color] = &color;
  runFrame(pass, frame, inputs);
  out.output = downloadImage(pass.output());
  out.current = roundToHalf(in.current);
  const Image v = roundToHalf(velocity);
  if (v.data.size() < 2) throw std::logic_error("gpuResolve: the velocity image has no pixel");
  out.velocityPx = {v.data.at(0), v.data.at(1)};
  return out;
}

}  // namespace taa::test
