// Replays a case on the GPU: one frame at a time, in order, each a function of the
// case and its frame index. Builds only the passes and targets the case needs.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "api/frame_record.h"
#include "api/render_options.h"
#include "spec/case_spec.h"

namespace taa {

class Device;
class ReferenceCache;
namespace scene {
struct Scene;  // api/scene_loading.h builds it; only the renderer looks inside
}
namespace vk {
class Context;
}

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
  // The shaders whose SPIR-V a reference frame's key holds (ReferencePass::setShaders); empty
  // when the case renders no reference.
  std::vector<std::string> referenceShaders() const;

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
