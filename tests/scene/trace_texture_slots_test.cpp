// The tracer binds each scene texture once, however many materials share it: its texture
// array has a fixed number of slots (TRACE_MAX_TEXTURES), so a duplicate takes one a scene
// with many textures needs.
#include <gtest/gtest.h>

#include "scene/scene.h"
#include "scene/trace_textures.h"

namespace taa::scene::trace_texture_slots_test {
namespace {

TEST(TraceTextureSlots, ASharedTextureTakesOneSlot) {
  Scene s;
  for (int base : {4, 4, 7, 4}) {
    Material m;
    m.baseColorTexture = base;
    s.materials.push_back(m);
  }
  s.materials[1].emissiveTexture = 7;
  const TraceTextureSlots t = traceTextureSlots(s);
  EXPECT_EQ(t.textures, (std::vector<int>{4, 7}));
  EXPECT_EQ(t.base, (std::vector<int>{0, 0, 1, 0}));
  EXPECT_EQ(t.emissive, (std::vector<int>{0, 1, 1, 0}));  // none: the base colour's slot
  EXPECT_EQ(t.occlusion, (std::vector<int>{0, 0, 1, 0}));
}

}  // namespace
}  // namespace taa::scene::trace_texture_slots_test
