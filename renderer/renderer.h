// Replays a case on the GPU: one frame at a time, in order, each a function of the
// case and its frame index. Builds only the passes and targets the case needs.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "frame_record.h"
#include "scene/scene.h"
#include "spec/case_spec.h"

namespace taa {

class Device;
class ReferenceCache;
namespace vk {
class Context;
}

struct RenderOptions {
  // Render the supersampled reference beside every frame whose images are read back
  // (costs reference.samples extra scene renders per such frame).
  bool reference = false;
  // Read back, beside the output, buffers the harness's invariants examine: the
  // resolve's input colour ("current"), the ids and the velocity targets.
  bool captureCurrent = false;
  bool captureIds = false;
  bool captureVelocity = false;
  // Adaptive mode: read back the resolve's output before tracing ("taa_resolve") and
  // the segmentation mask ("segmentation").
  bool captureAdaptive = false;
  // TSCMAA only: read back the CMAA image ("cmaa") and the edge mask ("tscmaa_mask",
  // TSCMAA_EDGE_* and TSCMAA_TAA bits as floats), both at output size.
  bool captureTscmaa = false;
  // Read back and hash the output of every frame, not only of those whose images are read:
  // goldens record each frame's pixel hash, so a frame no golden image covers is still
  // checked. Sets FrameRecord::color and colorSha256 for every frame; aux buffers, captures
  // and the reference still come only with readImages.
  bool hashEveryFrame = false;
  // Reference frames shared across the renderers of a run (passes/reference_cache.h), used
  // when both are set: `referenceKey` names everything the case gives the reference pass
  // (the harness's run::referenceKey), the renderer adds each frame's own inputs.
  ReferenceCache* referenceCache = nullptr;
  std::string referenceKey;
};

class Renderer {
 public:
  Renderer(vk::Context& ctx, const spec::CaseSpec& spec, const scene::Scene& scene, RenderOptions options = {});
  // The harness's way in (device.h): no Vulkan type in its signature.
  Renderer(Device& device, const spec::CaseSpec& spec, const scene::Scene& scene,
           RenderOptions options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The passes and buffers this case allocated, one line each.
  const std::vector<std::string>& log() const;

  // Renders frame `frame`; frames must come in order from 0. Images are read back
  // when `readImages` is set (the frame is written or checked).
  FrameRecord renderFrame(int frame, bool readImages);

 private:
  struct State;
  std::unique_ptr<State> s_;
};

// Renders the whole sequence, handing each frame to `sink` (images only for
// spec.output.frames). `progress`, when set, is called before each frame.
void renderSequence(Renderer& renderer, const spec::CaseSpec& spec, const std::function<void(FrameRecord&)>& sink,
                    const std::function<void(int)>& progress = {});

}  // namespace taa
