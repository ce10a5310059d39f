// Everything the harness learns about one rendered frame. The renderer fills it;
// the harness never sees a Vulkan object.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <utility>
#include <vector>

#include "api/captures.h"
#include "core/image.h"

namespace taa {

struct NamedImage {
  std::string name;  // "depth", "velocity", "normal", "material_id", "reference", ...
  Image image;
};

struct FrameRecord {
  int frame = 0;
  bool hasImages = false;  // colour and aux images are read back only for requested frames
  // The final output, linear HDR RGBA at output size, and the SHA-256 of its half-float pixel
  // bytes (core/image_io.h): with the images, or for every frame under hashEveryFrame.
  Image color;
  std::string colorSha256;
  std::vector<NamedImage> aux;
  bool hasReference = false;  // set when the run computes the supersampled ground truth
  Image reference;            // output size, float32 average of reference.samples renders
  std::vector<std::pair<std::string, double>> gpuMs;  // per pass, from timestamp queries
  // Per-frame figures a pass reports, read back every frame (adaptive mode:
  // "traced_share" and "fxaa_share", fractions of the output's pixels; TSCMAA:
  // "tscmaa_edges" and "tscmaa_taa_pixels", pixel counts).
  std::vector<std::pair<std::string, double>> stats;
  glm::ivec2 renderSize{0};
  bool cameraCut = false;
  bool historyReset = false;

  // A captured image of this frame (api/captures.h), or null when it was not read back.
  const Image* capture(Capture c) const {
    if (c == Capture::Reference) return hasReference ? &reference : nullptr;
    for (const auto& a : aux)
      if (a.name == captureName(c)) return &a.image;
    return nullptr;
  }
};

}  // namespace taa
