// Which G-buffer targets a pass reads, beyond colour: this frame's depth, velocity, normals
// and ids, and last frame's copies. Depth is rendered every frame whatever the passes read
// (the raster test needs it); `depth` says whether a pass samples it (seed 001's resolve
// with the speed in alpha reads colour only). The pass plan
// allocates the union over the passes a case runs (pass_plan.cpp), so a pass states what
// it reads as a value: a resolve from its input table rows (passes/resolve_inputs.h), a
// user's resolve from its shader's bindings.
#pragma once

namespace taa {

// The images, in the order of GBufferNeeds' members (designated initializers follow it).
#define TAA_GBUFFER_IMAGES(X) \
  X(velocity) X(normal) X(ids) X(prevDepth) X(prevNormal) X(prevIds) X(prevVelocity) X(depth)

struct GBufferNeeds {
#define TAA_GBUFFER_NEED_MEMBER(n) bool n = false;
  TAA_GBUFFER_IMAGES(TAA_GBUFFER_NEED_MEMBER)
#undef TAA_GBUFFER_NEED_MEMBER

  constexpr GBufferNeeds& operator|=(const GBufferNeeds& o) {
#define TAA_GBUFFER_NEED_UNION(n) n = n || o.n;
    TAA_GBUFFER_IMAGES(TAA_GBUFFER_NEED_UNION)
#undef TAA_GBUFFER_NEED_UNION
    return *this;
  }
  friend constexpr GBufferNeeds operator|(GBufferNeeds a, const GBufferNeeds& b) {
    return a |= b;
  }
  friend constexpr bool operator==(const GBufferNeeds&, const GBufferNeeds&) = default;
};

}  // namespace taa
