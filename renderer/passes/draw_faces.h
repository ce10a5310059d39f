// Which faces of a draw the raster keeps, as glTF defines them: a single-sided material's
// back faces are culled, a double-sided one's are drawn (gbuffer.frag lights them with the
// flipped normal), and an instance whose transform mirrors (negative determinant) has its
// front faces wound clockwise. Pipelines built with GraphicsDesc::dynamicFaces take both
// from here, per draw; the G-buffer, its blended pass and the shadow casters share it.
#pragma once

#include <vulkan/vulkan.h>

namespace taa {

class DrawFaces {
 public:
  // Records what a draw needs where it differs from the last recorded state. A fresh
  // DrawFaces records both on its first call: use one per pipeline bind, since binding a
  // pipeline whose faces are static in between leaves the dynamic state undefined.
  void apply(VkCommandBuffer cmd, bool doubleSided, bool mirrored) {
    const VkCullModeFlags cull = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    const VkFrontFace front =
        mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
    if (!recorded_ || cull != cull_) vkCmdSetCullMode(cmd, cull);
    if (!recorded_ || front != front_) vkCmdSetFrontFace(cmd, front);
    cull_ = cull;
    front_ = front;
    recorded_ = true;
  }

 private:
  bool recorded_ = false;
  VkCullModeFlags cull_ = VK_CULL_MODE_NONE;
  VkFrontFace front_ = VK_FRONT_FACE_COUNTER_CLOCKWISE;
};

}  // namespace taa
