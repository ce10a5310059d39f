// The supersampled reference is an opaque image, as the frames it stands beside are:
// `taa-harness render --reference` writes it as EXR, alpha included, and the invariants and
// metrics read only its RGB, so a wrong alpha would reach users' files with no case noticing.
#include <gtest/gtest.h>

#include "support/gpu.h"

namespace taa {
namespace {

TEST(ReferenceOpaque, TheAccumulatedReferenceHasAlphaOne) {
  const auto spec = test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 24, "height": 16},
    "script": {"frames": 1},
    "reference": {"samples": 3}
  })");
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const auto records = test::renderCaseWith(spec, o, {0});
  const Image& reference = test::capturedImage(records[0], Capture::Reference);
  ASSERT_EQ(reference.channels, 4);
  int off = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) off += reference.at(x, y, 3) != 1.0f;
  EXPECT_EQ(off, 0) << "reference pixels whose alpha is not 1, e.g. " << reference.at(0, 0, 3);
  EXPECT_EQ(records[0].color.at(0, 0, 3), 1.0f);  // the frame it is compared with
}

}  // namespace
}  // namespace taa
