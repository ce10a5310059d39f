// Stereo TSCMAA (tscmaa.eyes 2): both eyes side by side, apart by the parallax their
// separation gives at the scene's depth, each as deterministic as one eye.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/post_test_util.h"
#include "renderer/tscmaa_test_util.h"

namespace taa {
namespace {

// A 1 x 1 quad at z = 0 seen head-on from 4 units away.
const char* kStereoQuad =
    R"("scene": {"builtin": "quad"}, "script": {"frames": 3}, "jitter": {"pattern": "none"},
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0]})";

// Midpoint (eye-local x) between the first and the last pixel of row y that differ
// clearly from the sky at the eye's left border: the quad's centre, to half a pixel.
double quadCentre(const Image& img, int eyeOffset, int eyeWidth, int y) {
  int first = -1, last = -1;
  for (int x = 0; x < eyeWidth; ++x) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
      d += std::fabs(img.at(eyeOffset + x, y, c) - img.at(eyeOffset, y, c));
    if (d < 0.15) continue;
    if (first < 0) first = x;
    last = x;
  }
  return first < 0 ? -1.0 : 0.5 * (first + last + 1);
}

TEST(TscmaaStereo, EyesSitSideBySideApartByTheParallax) {
  const float separation = 0.5f, distance = 4.0f;
  const auto spec = tscmaatest::tscmaaCase(R"("eyes": 2, "eye_separation": 0.5)", kStereoQuad, 320, 180);
  const auto frames = tscmaatest::renderAll(spec);
  const Image& out = frames.back().color;
  ASSERT_EQ(out.width, 640);
  ASSERT_EQ(out.height, 180);
  const double left = quadCentre(out, 0, 320, 90), right = quadCentre(out, 320, 320, 90);
  ASSERT_GT(left, 0.0);
  ASSERT_GT(right, 0.0);
  // Parallel eyes: the left eye sees the quad right of centre by P00 * (sep / 2) / z in
  // NDC, the right eye as far left; in pixels, NDC * width / 2.
  const auto state = script::frameState(spec, 0);
  const double p00 = state.camera.projection[0][0];
  const double expected = p00 * separation / distance * 320.0 / 2.0;
  EXPECT_NEAR(left - right, expected, 1.5) << "left " << left << " right " << right;
  EXPECT_NEAR(0.5 * (left + right), 160.0, 1.0);
}

TEST(TscmaaStereo, EachEyeIsDeterministicAndKeepsItsOwnHistory) {
  const auto spec =
      tscmaatest::tscmaaCase(R"("eyes": 2, "eye_separation": 0.2)",
                             R"("scene": {"builtin": "fence"}, "script": {"frames": 4},
                                              "camera": {"strafe": {"speed": 0.6, "distance": 0.4}})");
  const auto a = tscmaatest::renderAll(spec);
  const auto b = tscmaatest::renderAll(spec);
  for (size_t f = 0; f < a.size(); ++f) {
    EXPECT_EQ(a[f].colorSha256, b[f].colorSha256) << f;
    EXPECT_EQ(a[f].color.width, 2 * spec.render.width);
  }
  // The eyes see different images (parallax), so their halves differ.
  const Image& out = a.back().color;
  int differing = 0;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < spec.render.width; ++x)
      differing += std::fabs(out.at(x, y) - out.at(x + spec.render.width, y)) > 1e-3f;
  EXPECT_GT(differing, out.height * spec.render.width / 50);
  // Edge counts add up over the eyes.
  EXPECT_GT(tscmaatest::counter(a.back(), "tscmaa_edges"), 0.0);
}

}  // namespace
}  // namespace taa
