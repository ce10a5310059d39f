// Which G-buffer targets a pass reads, beyond colour: this frame's depth, velocity, normals
// and ids, and last frame's copies. Depth is rendered every frame whatever the passes read
// (the raster test needs it); `depth` says whether a pass samples it (seed 001's resolve
// with the speed in alpha reads colour only). The pass plan
// allocates the union over the passes a case runs (pass_plan.cpp), so a pass states what
// it reads as a value: a user's resolve reports it from its shader's bindings.
#pragma once

namespace taa {

struct GBufferNeeds {
  bool velocity = false;
  bool normal = false;
  bool ids = false;
  bool prevDepth = false;
  bool prevNormal = false;
  bool prevIds = false;
  bool prevVelocity = false;
  bool depth = false;

  constexpr GBufferNeeds& operator|=(const GBufferNeeds& o) {
    velocity = velocity || o.velocity;
    normal = normal || o.normal;
    ids = ids || o.ids;
    prevDepth = prevDepth || o.prevDepth;
    prevNormal = prevNormal || o.prevNormal;
    prevIds = prevIds || o.prevIds;
    prevVelocity = prevVelocity || o.prevVelocity;
    depth = depth || o.depth;
    return *this;
  }
  friend constexpr GBufferNeeds operator|(GBufferNeeds a, const GBufferNeeds& b) { return a |= b; }
  friend constexpr bool operator==(const GBufferNeeds&, const GBufferNeeds&) = default;
};

}  // namespace taa
