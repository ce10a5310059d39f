// new-case frames a glTF scene on its bounds over one loop of its longest animation: posing it at
// one frame must reach as far as posing it at every frame through the loop's last instant.
// cases/scenes/animated.gltf's spinner moves linearly over 0 to 2 s.
#include <gtest/gtest.h>

#include <filesystem>

#include "api/scene_loading.h"

namespace taa::posed_bounds_test {

TEST(PosedBounds, OneFrameCoversTheWholeLoopToItsLastInstant) {
  const auto file = std::filesystem::path(TAA_SOURCE_DIR) / "cases/scenes/animated.gltf";
  const SceneBounds loop = gltfPosedBounds(file, 1, 30);
  const SceneBounds every = gltfPosedBounds(file, 2 * 30 + 1, 30);  // frame 60 is t = 2 s
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(loop.lo[i], every.lo[i]) << "axis " << i;
    EXPECT_EQ(loop.hi[i], every.hi[i]) << "axis " << i;
  }
}

}  // namespace taa::posed_bounds_test
