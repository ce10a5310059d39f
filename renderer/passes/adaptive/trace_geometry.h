// The scene as the adaptive tracer sees it: world-space triangles in BVH leaf order,
// their shading attributes and the BVH nodes, ready to upload. The static world is
// built once; moving triangles (movers, animated or deformed glTF nodes) are re-posed
// and their BVH rebuilt every frame
// (a few hundred triangles: cheaper than a second level of instancing in the shader).
#pragma once

#include <cstdint>
#include <vector>

#include "common/shared.h"
#include "frame/draw_list.h"
#include "scene/bvh.h"
#include "scene/scene.h"

namespace taa {

struct TraceGeometry {
  std::vector<gpu::BvhNode> nodes;  // child and leaf indices already offset by the bases given
  std::vector<gpu::TraceTriangle> triangles;
  std::vector<gpu::TraceShading> shading;
};

// World-space triangles of the draws whose geometry moves (`movers` true: movers, the
// world's animated nodes, skinned and morphed meshes, see DrawList::dynamic) or of the rest,
// in a fixed order (instance, mesh, primitive, index) whatever order the draws came in.
// `shading` and `materials` (optional) receive what each triangle is shaded with.
void collectTriangles(const scene::Scene& scene, const DrawList& draws, bool movers,
                      std::vector<scene::Triangle>& triangles,
                      std::vector<gpu::TraceShading>* shading, std::vector<uint32_t>* materials);

// Builds the BVH of those triangles; node and triangle indices start at the bases, so
// parts can be concatenated into one buffer each.
TraceGeometry buildTraceGeometry(const scene::Scene& scene, const DrawList& draws, bool movers,
                                 uint32_t nodeBase, uint32_t triangleBase);

}  // namespace taa
