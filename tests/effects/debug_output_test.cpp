// Debug views: the velocity view encodes the G-buffer velocity, the rejection mask marks
// rejected history, the clamp distance shows how far rectification moved the history.
#include <gtest/gtest.h>

#include <cmath>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

TEST(EffectDebugOutput, VelocityViewEncodesTheGBufferVelocity) {
  const char* moving = R"({
    "scene": {"builtin": "checkerboard"},
    "camera": {"strafe": {"speed": 2.0}, "rotate": {"yaw_deg_per_s": 20}},
    "movers": [{"shape": "sphere", "start": [-2, 0.6, 2], "end": [2, 0.6, 2], "speed": 4}],
    "render": {"width": 128, "height": 72},
    "script": {"frames": 4},
    "taa": {"velocity_sampling": "pixel"},
    "debug": {"output": "velocity", "scale": 0.25}
  })";
  RenderOptions o;
  o.captures |= {Capture::Velocity};
  const auto& run = renderOnce(moving, "{}", {3}, o);
  const Image& view = run[3].color;
  const Image& v = test::capturedImage(run[3], Capture::Velocity);
  double worst = 0.0, largest = 0.0;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x)
      for (int c = 0; c < 2; ++c) {
        const double expected = v.at(x, y, c) * 0.25 * 0.5 + 0.5;
        worst = std::max(worst, std::fabs(view.at(x, y, c) - expected));
        largest = std::max(largest, std::fabs(double(v.at(x, y, c))));
      }
  report("largest |velocity| component (px)", largest);
  report("largest |view - (v * scale / 2 + 0.5)|", worst);
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 1e-3);  // the view is stored as half floats
}

TEST(EffectDebugOutput, RejectionMaskIsOneOnTheRevealedBorderAndZeroInside) {
  const char* pan = R"({
    "scene": {"builtin": "checkerboard"},
    "camera": {"rotate": {"yaw_deg_per_s": 120}},
    "render": {"width": 160, "height": 90},
    "script": {"frames": 6},
    "debug": {"output": "rejection"}
  })";
  RenderOptions o;
  o.captures |= {Capture::Velocity};
  const auto& run = renderOnce(pan, "{}", {5}, o);
  const Image& mask = run[5].color;
  const Image& v = test::capturedImage(run[5], Capture::Velocity);
  int border = 0, inside = 0, wrong = 0;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      // Turning also moves the sky vertically near the top and bottom edges.
      const float prevX = x + 0.5f - v.at(x, y, 0), prevY = y + 0.5f - v.at(x, y, 1);
      if (prevX < -1.5f) {
        ++border;
        wrong += mask.at(x, y, 0) != 1.0f;
      } else if (prevX > 2.0f && prevX < mask.width - 2.0f && prevY > 2.0f &&
                 prevY < mask.height - 2.0f) {
        ++inside;
        wrong += mask.at(x, y, 0) != 0.0f;
      }
    }
  report("revealed border pixels", border);
  report("interior pixels", inside);
  EXPECT_GT(border, 150);
  EXPECT_GT(inside, 10000);
  EXPECT_EQ(wrong, 0);
}

TEST(EffectDebugOutput, ClampDistanceIsZeroWhenConvergedAndPositiveWhereAMoverPassed) {
  const char* still = R"({
    "scene": {"builtin": "checkerboard"},
    "jitter": {"pattern": "none"},
    "render": {"width": 128, "height": 72},
    "script": {"frames": 8},
    "debug": {"output": "clamp_distance"}
  })";
  // Clamping moves a history that already is the current frame by its rounding at most. (Clip
  // pulls toward the box centre along the whole offset, so a rounding-sized excursion across a
  // box that is flat in one working channel moves it visibly: reported, not asserted.)
  const auto& converged = renderOnce(still, R"({"taa": {"rectify": "clamp"}})", {7});
  const double most = test::maxAbs(converged[7].color, Image(128, 72, 4, 0.0f));
  report("largest clamp distance, static converged scene, clamp", most);
  EXPECT_LT(most, 1e-3);
  const auto& clipped = renderOnce(still, "{}", {7});
  report("largest clamp distance, static converged scene, clip",
         test::maxAbs(clipped[7].color, Image(128, 72, 4, 0.0f)));

  const char* mover = R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 160, "height": 90},
    "script": {"frames": 12},
    "movers": [{"shape": "cube", "start": [-3, 0.5, 2], "end": [3, 0.5, 2], "speed": 12, "repeat": "once"}],
    "debug": {"output": "clamp_distance"}
  })";
  RenderOptions o;
  o.captures |= {Capture::Ids};
  const auto& run = renderOnce(mover, "{}", {10, 11}, o);
  // Pixels the cube covered last frame and has just left: their history is the cube.
  const test::Mask left = test::vacatedMask(run, 10, 11);
  const Image& d = run[11].color;
  const Image zero(d.width, d.height, 4, 0.0f);
  const double onTrail = test::meanAbs(d, zero, left);
  report("mean clamp distance where the cube just left", onTrail);
  report("pixels the cube just left", test::count(left));
  EXPECT_GT(test::count(left), 30);
  EXPECT_GT(onTrail, 0.1);
}

}  // namespace
}  // namespace taa
