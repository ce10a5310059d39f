// CMAA as TSCMAA runs it (taa_share 0: the output is the CMAA image): it brings
// rasterised edges closer to the supersampled reference and leaves every pixel off the
// edge list exactly as it was.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/post_test_util.h"
#include "renderer/tscmaa_test_util.h"

namespace taa {
namespace {

using tscmaatest::aux;

// Geometric edges (texture edges are already filtered, and CMAA would only soften
// them further); no jitter, as the reference is the un-jittered frame.
const char* kScene = R"("scene": {"builtin": "fence"}, "script": {"frames": 1},
  "jitter": {"pattern": "none"}, "reference": {"samples": 16})";

// RMSE over the pixels on the edge list, where CMAA may act.
double edgeRmse(const Image& a, const Image& b, const Image& mask) {
  double sum = 0.0;
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if ((uint32_t(mask.at(x, y)) & TSCMAA_EDGES) == 0u) continue;
      for (int c = 0; c < 3; ++c) {
        const double d = std::min(a.at(x, y, c), 4.0f) - std::min(b.at(x, y, c), 4.0f);
        sum += d * d;
      }
      ++n;
    }
  return n ? std::sqrt(sum / (3.0 * n)) : 0.0;
}

RenderOptions captures(bool reference) {
  RenderOptions o;
  if (reference) o.captures |= {Capture::Reference};
  o.captures |= {Capture::Current};
  o.captures |= {Capture::Cmaa, Capture::EdgeMask};
  return o;
}

// A half plane bounded by a line of slope `slope` through the image centre: bright
// above the line, dark below, either point-sampled at pixel centres (what a rasteriser
// gives) or averaged over 16 x 16 sub-samples (the reference).
Image halfPlane(int w, int h, float slope, int samples) {
  Image img(w, h, 4, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float covered = 0.0f;
      for (int j = 0; j < samples; ++j)
        for (int i = 0; i < samples; ++i) {
          const float sx = float(x) + (float(i) + 0.5f) / float(samples);
          const float sy = float(y) + (float(j) + 0.5f) / float(samples);
          covered += sy < 0.5f * float(h) + slope * (sx - 0.5f * float(w)) ? 1.0f : 0.0f;
        }
      const float v = 0.05f + 0.85f * covered / float(samples * samples);
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = v;
    }
  return img;
}

double rmse(const Image& a, const Image& b) {
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const double d = double(a.at(x, y)) - double(b.at(x, y));
      sum += d * d;
    }
  return std::sqrt(sum / double(a.pixelCount()));
}

TEST(CmaaGpu, AntialiasesARasterisedEdgeTowardItsCoverage) {
  for (const float slope : {0.1f, 0.25f, -0.4f, 0.7f, 3.0f, -6.0f}) {
    const Image aliased = posttest::roundedToHalf(halfPlane(96, 64, slope, 1));
    const Image reference = halfPlane(96, 64, slope, 16);
    const auto spec = tscmaatest::tscmaaCase(R"("taa_share": 0)", "", 96, 64);
    const auto r = tscmaatest::runSynthetic(spec, aliased);
    const double before = rmse(aliased, reference), after = rmse(r.cmaa, reference);
    EXPECT_LT(after, 0.75 * before) << "slope " << slope << ": " << before << " -> " << after;
  }
}

TEST(CmaaGpu, BringsEdgesCloserToTheSupersampledReference) {
  const auto spec = tscmaatest::tscmaaCase(R"("taa_share": 0)", kScene, 320, 180);
  const auto r = tscmaatest::renderAll(spec, captures(true)).back();
  const Image& mask = aux(r, "tscmaa_mask");
  const double before = edgeRmse(aux(r, "current"), r.reference, mask);
  const double after = edgeRmse(r.color, r.reference, mask);
  RecordProperty("rmse_before", std::to_string(before));
  RecordProperty("rmse_after", std::to_string(after));
  EXPECT_LT(after, 0.9 * before) << "before " << before << " after " << after;
}

TEST(CmaaGpu, LeavesPixelsOffTheEdgeListUnchanged) {
  const auto spec = tscmaatest::tscmaaCase(R"("taa_share": 0)", kScene, 320, 180);
  const auto r = tscmaatest::renderAll(spec, captures(false)).back();
  const Image &mask = aux(r, "tscmaa_mask"), &current = aux(r, "current"), &cmaa = aux(r, "cmaa");
  int edgePixels = 0, changed = 0;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      const bool edge = (uint32_t(mask.at(x, y)) & TSCMAA_EDGES) != 0u;
      edgePixels += edge;
      if (!edge)
        ASSERT_TRUE(sameRgbBits(cmaa, current, x, y)) << x << "," << y;
      else
        changed += !sameRgbBits(cmaa, current, x, y);
    }
  EXPECT_GT(edgePixels, 500);
  EXPECT_GT(changed, edgePixels / 4) << changed << " of " << edgePixels;
  EXPECT_EQ(tscmaatest::counter(r, "tscmaa_edges"), double(edgePixels));
}

TEST(CmaaGpu, BlurrinessBlendsSimpleShapesMore) {
  auto deviation = [](float blurriness) {
    const auto spec = tscmaatest::tscmaaCase(
        R"("taa_share": 0, "blurriness": )" + std::to_string(blurriness), kScene, 320, 180);
    const auto r = tscmaatest::renderAll(spec, captures(false)).back();
    const Image &current = aux(r, "current"), &cmaa = aux(r, "cmaa");
    double sum = 0.0;
    for (size_t i = 0; i < cmaa.data.size(); ++i)
      sum += std::fabs(double(cmaa.data[i]) - current.data[i]);
    return sum;
  };
  const double soft = deviation(0.5f), softer = deviation(2.0f);
  EXPECT_GT(softer, soft * 1.05) << soft << " vs " << softer;
}

}  // namespace
}  // namespace taa
