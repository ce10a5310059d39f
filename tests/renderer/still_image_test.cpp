// debug.image (still-image temporal upsampling): the still pass samples the image where a
// rasteriser would (the pixel centre minus the jitter), nearest or bilinear; the reference
// is the image itself; the upsampled output converges towards it. Also the two debug rows
// of section 11: debug.channels and adaptive.fxaa_debug_border.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/shared.h"
#include "compare/metrics.h"
#include "core/image_io.h"
#include "support/gpu.h"

namespace taa {
namespace {

const char* kStillPath = "scenes/still_zone_plate.png";

spec::CaseSpec stillCase(const std::string& members) {
  return test::caseFromJson(std::string(R"({"scene": {"builtin": "quad"}, "debug": {"image": ")") +
                                kStillPath + R"(", "image_sampling": "nearest"}, )" + members + "}",
                            "still_image");
}

Image stillSource() {
  return readImage(std::filesystem::path(TAA_SOURCE_DIR) / "cases" / kStillPath);
}

TEST(StillImage, NearestAtFullSizeWithoutJitterIsTheImageAndSoIsTheReference) {
  const auto spec = stillCase(
      R"("jitter": {"pattern": "none"}, "taa": {"mode": "off"}, "script": {"frames": 1}, "reference": {"samples": 4})");
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const auto records = test::renderCaseWith(spec, o, {0});
  const Image src = stillSource();
  const Image& frame = records[0].color;
  const Image& reference = test::capturedImage(records[0], Capture::Reference);
  ASSERT_EQ(frame.width, src.width);
  ASSERT_EQ(frame.height, src.height);
  float worstFrame = 0.0f, worstReference = 0.0f;
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x)
      for (int c = 0; c < 3; ++c) {
        worstFrame = std::max(worstFrame, std::abs(frame.at(x, y, c) - src.at(x, y, c)));
        worstReference =
            std::max(worstReference, std::abs(reference.at(x, y, c) - src.at(x, y, c)));
      }
  EXPECT_LT(worstFrame, 1e-3f) << "RGBA16F rounding only";
  EXPECT_LT(worstReference, 1e-3f) << "through the RGBA16F colour target, then averaged";
}

TEST(StillImage, BilinearSamplesTheJitteredCentre) {
  // Jitter (+0.25, 0): pixel x sees the image at x + 0.25 in texel space, i.e. 3/4 of
  // texel x and 1/4 of texel x - 1.
  auto spec =
      stillCase(R"("jitter": {"pattern": "manual", "points": [[0.25, 0]]}, "taa": {"mode": "off"},
    "script": {"frames": 1})");
  spec.debug.image_sampling = spec::ImageSampling::Bilinear;
  const Image frame = test::renderCase(spec, {0})[0].color;
  const Image src = stillSource();
  float worst = 0.0f;
  for (int y = 0; y < src.height; ++y)
    for (int x = 1; x < src.width; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(frame.at(x, y, c) -
                                         (0.75f * src.at(x, y, c) + 0.25f * src.at(x - 1, y, c))));
  EXPECT_LT(worst, 2e-3f);
}

TEST(StillImage, TemporalUpsamplingConvergesTowardsTheImage) {
  // Half resolution, Halton 16: frame 0 is a bilinear upscale of a quarter of the texels;
  // accumulation recovers part of the detail (the clip against the 3x3 neighbourhood of
  // the half-resolution frame limits it). Measured on lavapipe, RMSE at frame 0 -> 31: see
  // the printed figures (bilinear 0.134 -> 0.090, ratio 0.67).
  for (const char* sampling : {"nearest", "bilinear"}) {
    auto spec =
        stillCase(R"("render": {"upsample": 2}, "jitter": {"pattern": "halton", "length": 16},
      "script": {"frames": 32})");
    ASSERT_TRUE(spec::enumFromString(sampling, spec.debug.image_sampling));
    const auto records = test::renderCase(spec, {0, 31});
    const Image src = stillSource();
    Image rgb(src.width, src.height, 4, 1.0f);  // RGBA like the output; alpha is not compared
    for (int y = 0; y < src.height; ++y)
      for (int x = 0; x < src.width; ++x)
        for (int c = 0; c < 3; ++c) rgb.at(x, y, c) = src.at(x, y, c);
    const auto first = compare::computeMetrics(records.front().color, rgb).rmse;
    const auto last = compare::computeMetrics(records.back().color, rgb).rmse;
    std::printf("still image %s: RMSE frame 0 %.4f, frame 31 %.4f, ratio %.3f\n", sampling, first,
                last, last / first);
    EXPECT_LT(last, 0.75 * first) << sampling;
  }
}

TEST(DebugChannels, HiddenChannelsReadZeroAndAlphaOne) {
  const auto velocityView = [](const std::string& channels) {
    return test::renderCase(test::caseFromJson(R"({"scene": {"builtin": "checkerboard"},
      "camera": {"strafe": {"speed": 2.0}}, "debug": {"output": "velocity")" +
                                               channels + R"(},
      "script": {"frames": 2}, "output": {"frames": [1]}})"),
                            {1})[1]
        .color;
  };
  const Image all = velocityView("");
  const Image green = velocityView(R"(, "channels": ["g"])");
  const Image redBlue = velocityView(R"(, "channels": ["r", "b"])");
  double redSum = 0.0;
  for (int y = 0; y < all.height; ++y)
    for (int x = 0; x < all.width; ++x) {
      redSum += all.at(x, y, 0);
      EXPECT_EQ(green.at(x, y, 0), 0.0f);
      EXPECT_EQ(green.at(x, y, 1), all.at(x, y, 1));
      EXPECT_EQ(green.at(x, y, 2), 0.0f);
      EXPECT_EQ(redBlue.at(x, y, 0), all.at(x, y, 0));
      EXPECT_EQ(redBlue.at(x, y, 1), 0.0f);
    }
  EXPECT_GT(redSum, 0.0) << "the velocity view has a red channel to hide";
}

TEST(FxaaDebugBorder, TheBorderIsAlwaysMarkedForFxaa) {
  const auto mask = [](int border) {
    auto spec = test::caseFromJson(R"({"scene": {"builtin": "wires"}, "taa": {"mode": "adaptive"},
      "script": {"frames": 3}, "output": {"frames": [2]}})");
    spec.adaptive.fxaa_debug_border = border;
    RenderOptions o;
    o.captures |= {Capture::Resolved, Capture::Segmentation};
    return test::capturedImage(test::renderCaseWith(spec, o, {2})[2], Capture::Segmentation);
  };
  const Image plain = mask(0), framed = mask(6);
  int plainFxaaBorder = 0, changedInside = 0;
  for (int y = 0; y < framed.height; ++y)
    for (int x = 0; x < framed.width; ++x) {
      const bool border = x < 6 || y < 6 || x >= framed.width - 6 || y >= framed.height - 6;
      if (border) {
        EXPECT_EQ(uint32_t(framed.at(x, y)), ADAPTIVE_MASK_FXAA) << x << "," << y;
        plainFxaaBorder += uint32_t(plain.at(x, y)) == ADAPTIVE_MASK_FXAA ? 1 : 0;
      } else {
        changedInside += framed.at(x, y) != plain.at(x, y) ? 1 : 0;
      }
    }
  EXPECT_EQ(changedInside, 0);
  EXPECT_LT(plainFxaaBorder, 100)
      << "a static camera leaves the border in history without the setting";
}

}  // namespace
}  // namespace taa
