// The stress pass's push constants, built on the CPU: each listed pixel in its slot, the count
// and the value, and nothing past the count (the shader reads only `count` pixels, but a slot
// filled from past the list's end would be a read outside it).
#include <gtest/gtest.h>

#include "passes/inject.h"

namespace taa {
namespace {

TEST(InjectPush, EachPixelInItsSlotAndNothingPastTheCount) {
  spec::InjectSpec inject;
  // Eight pixels' room whose last five are dropped: their values stay in the vector's storage,
  // where a loop running one past the count would find them.
  inject.pixels.reserve(8);
  for (int i = 0; i < 8; ++i) inject.pixels.push_back(glm::vec2(100 + i, 200 + i));
  inject.pixels.resize(3);
  inject.value = spec::InjectValue::PosInf;
  const gpu::InjectPush push = makeInjectPush(inject);
  EXPECT_EQ(push.pixels[0], glm::vec4(100, 200, 101, 201));
  EXPECT_EQ(push.pixels[1], glm::vec4(102, 202, 0, 0));
  EXPECT_EQ(push.pixels[2], glm::vec4(0));
  EXPECT_EQ(push.pixels[3], glm::vec4(0));
  EXPECT_EQ(push.params.x, 3.0f);
  EXPECT_EQ(push.params.y, float(INJECT_POS_INF));
}

}  // namespace
}  // namespace taa
