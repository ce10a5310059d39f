#include "scene/trace_textures.h"

#include <map>

namespace taa::scene {

TraceTextureSlots traceTextureSlots(const Scene& scene) {
  TraceTextureSlots out;
  std::map<int, int> slots;  // scene texture -> slot
  auto slot = [&](int texture) {
    const auto [it, added] = slots.emplace(texture, int(out.textures.size()));
    if (added) out.textures.push_back(texture);
    return it->second;
  };
  for (const Material& m : scene.materials) {
    const int base = slot(m.baseColorTexture);
    out.base.push_back(base);
    out.emissive.push_back(m.emissiveTexture >= 0 ? slot(m.emissiveTexture) : base);
    out.occlusion.push_back(m.occlusionTexture >= 0 ? slot(m.occlusionTexture) : base);
  }
  return out;
}

}  // namespace taa::scene
