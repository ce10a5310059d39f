// The shipped HLSL twins (examples/user_taa/cases/*.hlsl, written against taa_user.hlsli)
// render what their GLSL examples render, frame by frame over the whole script: the minimal
// clamp bit for bit; the variance clip within a few steps of the rgba16f output on a tiny
// share of the samples (measured on lavapipe: at most 4 steps, on 0.46% of the samples over 24
// frames, the feedback loop carrying a first-frame step forward): HLSL needs spirv-opt's legalization, whose simplification turns the GLSL's
// a * b + c into fma(a, b, c) and m / 9 into m * (1 / 9), rounding differently.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <numeric>

#include "case/case_loader.h"
#include "support/gpu.h"

namespace {

namespace fs = std::filesystem;

// One step of a half float at v: the spacing of rgba16f values around it.
double halfStep(double v) {
  const double a = std::max(std::fabs(v), 6.103515625e-05);  // below: subnormal, fixed spacing
  return std::ldexp(1.0, int(std::floor(std::log2(a))) - 10);
}

struct TwinDifference {
  int framesIdentical = 0, frames = 0;
  double worstSteps = 0.0;  // largest difference, in half-float steps of the GLSL value
  double differingShare = 0.0;
};

TwinDifference compareTwins(const std::string& name) {
  const fs::path dir = fs::path(TAA_SOURCE_DIR) / "examples" / "user_taa" / "cases";
  setenv("TAA_SHADER_CACHE", (fs::path(TAA_TEST_OUT) / "hlsl_twin_cache").c_str(), 1);
  const auto glsl = taa::cases::loadCase(dir / (name + ".json"));
  const auto hlsl = taa::cases::loadCase(dir / (name + "_hlsl.json"));
  std::vector<int> all(size_t(glsl.spec.script.frames));
  std::iota(all.begin(), all.end(), 0);
  const auto a = taa::test::renderCase(glsl.spec, all);
  const auto b = taa::test::renderCase(hlsl.spec, all);
  TwinDifference d;
  size_t differing = 0, samples = 0;
  for (size_t f = 0; f < a.size() && f < b.size(); ++f) {
    ++d.frames;
    d.framesIdentical += a[f].colorSha256 == b[f].colorSha256;
    const auto& x = a[f].color.data;
    const auto& y = b[f].color.data;
    EXPECT_EQ(x.size(), y.size());
    for (size_t i = 0; i < x.size() && i < y.size(); ++i) {
      ++samples;
      if (x[i] == y[i]) continue;
      ++differing;
      d.worstSteps = std::max(d.worstSteps, std::fabs(double(x[i]) - double(y[i])) / halfStep(x[i]));
    }
  }
  d.differingShare = samples ? double(differing) / double(samples) : 1.0;
  return d;
}

TEST(HlslTwinTest, MinimalClampTwinIsBitIdentical) {
  const TwinDifference d = compareTwins("minimal_clamp");
  EXPECT_EQ(d.frames, 24);
  EXPECT_EQ(d.framesIdentical, d.frames);
  EXPECT_EQ(d.worstSteps, 0.0);
}

TEST(HlslTwinTest, VarianceClipTwinIsWithinAFewHalfFloatSteps) {
  const TwinDifference d = compareTwins("variance_clip");
  EXPECT_EQ(d.frames, 24);
  // Twice the measured figures: a twin that computed anything differently (a sign, a tap, a
  // weight) differs by far more, on far more samples.
  EXPECT_LE(d.worstSteps, 8.0) << "largest difference in half-float steps";
  EXPECT_LT(d.differingShare, 0.01) << "share of samples that differ at all";
  std::cout << "variance_clip twin: worst " << d.worstSteps << " half-float steps, "
            << 100.0 * d.differingShare << "% of samples differ, " << d.framesIdentical << "/"
            << d.frames << " frames identical\n";
  // Frame 0 has no history: the same texel fetches on both sides.
  EXPECT_GE(d.framesIdentical, 1);
}

}  // namespace
