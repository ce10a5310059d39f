// Reading a completed frame's images back into its FrameRecord: the output, the
// reference, the aux buffers the case asks for and the captures the harness needs.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <utility>
#include <vector>

#include "frame_record.h"
#include "passes/adaptive/adaptive.h"
#include "passes/gbuffer.h"
#include "passes/reference.h"
#include "passes/tscmaa.h"
#include "renderer.h"

namespace taa {

struct FrameSources {
  vk::Image* output = nullptr;  // the final image, valid in its top-left outputSize
  glm::ivec2 outputSize{0};
  glm::ivec2 renderSize{0};
  vk::Image* resolveInput = nullptr;  // the resolve's input colour (last eye)
  GBufferTargets* targets = nullptr;
  TscmaaPass* tscmaa = nullptr;
  ReferencePass* reference = nullptr;
  AdaptivePass* adaptive = nullptr;
};

// The output alone, with its hash (RenderOptions::hashEveryFrame); readFrameImages does this too.
void readFrameColor(vk::Context& ctx, const FrameSources& src, FrameRecord& record);

void readFrameImages(vk::Context& ctx, const spec::CaseSpec& spec, const RenderOptions& options,
                     const FrameSources& src, FrameRecord& record);

// "tscmaa_edges" and "tscmaa_taa_pixels" summed over the eyes.
std::vector<std::pair<std::string, double>> tscmaaCounters(const std::vector<TscmaaCounts>& counts);

}  // namespace taa
