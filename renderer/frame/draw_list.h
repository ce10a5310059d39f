// What the G-buffer pass draws this frame: per-instance transforms (current and
// previous, for velocity) and the draws, opaque first, blended back to front.
// Pure CPU work, a function of the scene and the frame state.
//
// A draw covers a run of consecutive instances of one primitive (an instanced draw): a scene
// of many nodes sharing a mesh costs the driver one draw, not one per node. Instances are
// rasterised in index order, so a run draws exactly what its draws one by one would.
#pragma once

#include <cstdint>
#include <vector>

#include "common/shared.h"
#include "scene/scene.h"
#include "script/frame_state.h"

namespace taa {

struct Draw {
  uint32_t instance = 0;  // the first instance (firstInstance: the shaders' gl_InstanceIndex)
  uint32_t instanceCount = 1;
  int mesh = 0;
  int primitive = 0;
  // Deformed (skinned or morphed) draws read DrawList::deformed, from this vertex on
  // for the primitive's first vertex; -1: the scene's own vertices.
  int32_t deformedVertex = -1;
  // The instance's transform has a negative determinant: glTF then winds its front faces
  // clockwise, so the raster's front face and the tracer's triangle order flip with it.
  bool mirrored = false;
};

struct DrawList {
  std::vector<gpu::InstanceData> instances;
  std::vector<uint8_t> dynamic;  // per instance: its geometry moves (mover, animated or deformed)
  std::vector<Draw> opaque;  // opaque and alpha-tested
  std::vector<Draw> blended;  // sorted far to near
  // This frame's deformed vertices (model space, in the instance's frame) and their
  // positions at frame - 1, which the G-buffer's velocity comes from.
  std::vector<scene::Vertex> deformed;
  std::vector<glm::vec4> deformedPrev;
};

// Vertices DrawList::deformed holds for every frame of this scene (the sum over
// deformed mesh draws of their vertex counts).
size_t deformedVertexCount(const scene::Scene& scene);

DrawList buildDrawList(const scene::Scene& scene, const script::FrameState& state);

// The draws of `draws`, one instance each, in the same order (what consumers that work per
// instance rather than per draw read: the tracer's triangles, the reference's cache key).
std::vector<Draw> singleInstanceDraws(const std::vector<Draw>& draws);

}  // namespace taa
