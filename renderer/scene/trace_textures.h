// Which textures the adaptive tracer binds: its shader indexes a fixed array of
// TRACE_MAX_TEXTURES samplers, one slot per distinct texture the materials' traced maps
// (base colour, emission, occlusion) sample. The case check (build_scene.cpp) and the
// trace pass read the same table, so a scene with more is refused before anything runs.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace taa::scene {

struct TraceTextureSlots {
  std::vector<int> textures;  // the scene texture of each slot (-1: the white texture)
  // Per material, the slot of its base colour, emissive and occlusion texture (a material
  // without the map gets its base colour's slot, which its shading never reads for it).
  std::vector<int> base, emissive, occlusion;
};

TraceTextureSlots traceTextureSlots(const Scene& scene);

}  // namespace taa::scene
