// Reading a completed frame's images back into its FrameRecord: the output, the
// reference, the aux buffers the case asks for and the captures the harness needs.
// Every copy is recorded into the frame's own command buffer, behind one barrier, into
// one staging ring reused frame after frame; after the frame's wait they are decoded.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <utility>
#include <vector>

#include "api/frame_record.h"
#include "api/renderer.h"
#include "passes/gbuffer.h"
#include "passes/reference.h"
#include "passes/resolve_stage.h"
#include "vk/staging_ring.h"

namespace taa {

struct FrameSources {
  vk::Image* output = nullptr;  // the final image, valid in its top-left outputSize
  glm::ivec2 outputSize{0};
  glm::ivec2 renderSize{0};
  vk::Image* resolveInput = nullptr;  // the resolve's input colour (last eye)
  GBufferTargets* targets = nullptr;
  ReferencePass* reference = nullptr;
  // The resolve's and its followers' (ResolveStage::captures, PostChain::captures).
  std::vector<StageCapture> captures;
};

class FrameReadback {
 public:
  explicit FrameReadback(vk::Context& ctx) : ring_(ctx) {}

  // Records the copies of the output alone (`images` false: RenderOptions::hashEveryFrame)
  // or of the output and every image the case and options ask for.
  void record(VkCommandBuffer cmd, const spec::CaseSpec& spec, const RenderOptions& options,
              const FrameSources& src, bool images);
  // After the frame's commands completed: decodes what record() copied into `record`.
  void finish(FrameRecord& record);

  const vk::StagingRing& ring() const { return ring_; }

 private:
  enum class Kind { Output, Reference, Aux, Bits };
  struct Pending {
    Kind kind;
    std::string name;
    vk::StagingRing::Slot slot;
    VkFormat format;
    int stride;  // the image's width in texels
    glm::ivec2 size;
  };
  void add(Kind kind, std::string name, vk::Image& image, glm::ivec2 size);

  vk::StagingRing ring_;
  std::vector<std::pair<vk::Image*, Pending>> wanted_;
  std::vector<Pending> pending_;
  bool images_ = false;
};

}  // namespace taa
