#include <algorithm>
#include <cmath>
#include <utility>

#include "core/image_io.h"
#include "invariants/history_box.h"
#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

Image noisyCurrent(int frame) {
  Image img = rgba(0, 0, 0);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      setRgb(img, x, y, noise(x, y, frame, 1), noise(x, y, frame, 2), 2.0f * noise(x, y, frame, 3));
  return img;
}

// A convex combination of the 3x3 taps lies in the box in any linear space; rounding it to
// half floats, as the resolve's output is stored, must stay within the tolerance.
Image neighbourhoodMean(const Image& cur) {
  Image out = cur;
  for (int y = 0; y < cur.height; ++y)
    for (int x = 0; x < cur.width; ++x)
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        int n = 0;
        for (int j = std::max(y - 1, 0); j <= std::min(y + 1, cur.height - 1); ++j)
          for (int i = std::max(x - 1, 0); i <= std::min(x + 1, cur.width - 1); ++i)
            sum += cur.at(i, j, c), ++n;
        out.at(x, y, c) = halfRound(float(sum / n));
      }
  return out;
}

std::vector<Frame> boundedSequence(int frames) {
  std::vector<Frame> seq;
  for (int f = 0; f < frames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.reset = f == 0;
    fr.current = noisyCurrent(f);
    fr.output = neighbourhoodMean(fr.current);
    seq.push_back(std::move(fr));
  }
  return seq;
}

// Makes output pixel (x, y) brighter than every tap of its (edge-clamped) 3x3 box in every
// channel: outside the box in RGB and, through Y, in YCoCg.
void brightenPastTheBox(Frame& f, int x, int y) {
  float hi[3] = {0, 0, 0};
  for (int j = std::max(y - 1, 0); j <= std::min(y + 1, kH - 1); ++j)
    for (int i = std::max(x - 1, 0); i <= std::min(x + 1, kW - 1); ++i)
      for (int c = 0; c < 3; ++c) hi[c] = std::max(hi[c], f.current.at(i, j, c));
  setRgb(f.output, x, y, hi[0] + 0.1f, hi[1] + 0.1f, hi[2] + 0.1f);
}

spec::CheckedCase rgbCase() {
  auto s = staticCase();
  s.taa.color_space = spec::ColorSpace::Rgb;
  return s;
}

}  // namespace

TEST(InvariantHistoryBounded, ConvexBlendPassesInBothSpaces) {
  const auto seq = boundedSequence(4);
  for (auto s : {staticCase(), rgbCase()}) {
    const auto o = runAll("history_bounded", s, seq);
    EXPECT_TRUE(o.passed) << o.detail;
    EXPECT_EQ(valueOf(o, "pixels_over"), 0.0);
    EXPECT_EQ(valueOf(o, "frames_checked"), 3.0);  // frame 0 has no history
  }
}

TEST(InvariantHistoryBounded, PixelOutsideTheBoxFailsWithItsLocation) {
  auto seq = boundedSequence(4);
  brightenPastTheBox(seq[2], 5, 4);
  for (auto s : {staticCase(), rgbCase()}) {
    const auto o = runAll("history_bounded", s, seq);
    EXPECT_FALSE(o.passed);
    EXPECT_EQ(valueOf(o, "pixels_over"), 1.0);
    EXPECT_EQ(valueOf(o, "frame"), 2.0);
    EXPECT_EQ(valueOf(o, "x"), 5.0);
    EXPECT_EQ(valueOf(o, "y"), 4.0);
    EXPECT_TRUE(contains(o.detail, "at frame 2 (5, 4)")) << o.detail;
  }
}

// Alpha is no colour: a huge or NaN alpha neither widens the tolerance of a pixel outside the
// box nor puts a pixel inside it out.
TEST(InvariantHistoryBounded, TheOutputsAlphaPlaysNoPart) {
  auto seq = boundedSequence(4);
  brightenPastTheBox(seq[2], 5, 4);
  seq[2].output.at(5, 4, 3) = 1e6f;
  seq[2].output.at(1, 1, 3) = std::nanf("");
  for (auto s : {staticCase(), rgbCase()}) {
    const auto o = runAll("history_bounded", s, seq);
    EXPECT_FALSE(o.passed) << o.detail;
    EXPECT_EQ(valueOf(o, "pixels_over"), 1.0) << o.detail;
    EXPECT_EQ(valueOf(o, "x"), 5.0);
  }
}

// The image's first and last rows and columns are checked too (their boxes are clamped 2x3 or
// 3x2 neighbourhoods).
TEST(InvariantHistoryBounded, APixelOnEachEdgeIsChecked) {
  for (const auto& [x, y] : {std::pair{0, 4}, {kW - 1, 4}, {5, 0}, {5, kH - 1}}) {
    auto seq = boundedSequence(3);
    brightenPastTheBox(seq[1], x, y);
    const auto o = runAll("history_bounded", rgbCase(), seq);
    EXPECT_FALSE(o.passed) << x << ", " << y;
    EXPECT_EQ(valueOf(o, "x"), double(x));
    EXPECT_EQ(valueOf(o, "y"), double(y));
  }
}

TEST(InvariantHistoryBounded, ResetFramesAreNotChecked) {
  auto seq = boundedSequence(3);
  seq[0].output.at(1, 1, 0) = 50.0f;  // frame 0 resets: no history to bound
  EXPECT_TRUE(runAll("history_bounded", rgbCase(), seq).passed);
}

// The box corner (max r, max g, max b) is what clamping produces; half rounding may push it
// out by half an ulp, never by 1%.
TEST(InvariantHistoryBounded, ToleranceCoversHalfRoundingOnly) {
  for (float scale : {1.0f + 0x1p-11f, 1.01f}) {
    auto seq = boundedSequence(2);
    const Image& cur = seq[1].current;
    float hi[3] = {0, 0, 0};
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i)
        for (int c = 0; c < 3; ++c) hi[c] = std::max(hi[c], cur.at(i, j, c));
    setRgb(seq[1].output, 1, 1, hi[0] * scale, hi[1], hi[2]);
    EXPECT_EQ(runAll("history_bounded", rgbCase(), seq).passed, scale < 1.001f) << scale;
  }
}

TEST(InvariantHistoryBounded, NonFiniteOutputIsOutside) {
  auto seq = boundedSequence(2);
  seq[1].output.at(3, 3, 2) = std::nanf("");
  EXPECT_FALSE(runAll("history_bounded", staticCase(), seq).passed);
}

// Red and yellow neighbours: the YCoCg box corner (0.25, 0.5, 0.25) is RGB (0.5, 0.5, -0.5),
// which the resolve stores clamped as (0.5, 0.5, 0), 0.25 outside the box in Cg. That is
// legitimate; a colour no clamp explains is not.
TEST(InvariantHistoryBounded, YCoCgAcceptsOnlyNegativesClampedToZero) {
  auto check = [](float r, float g, float b) {
    Frame f0, f1;
    f0.frame = 0, f0.reset = true, f1.frame = 1;
    f1.current = rgba(1, 0, 0);
    for (int y = 0; y < kH; ++y)
      for (int x = kW / 2; x < kW; ++x) setRgb(f1.current, x, y, 1, 1, 0);
    f1.output = f1.current;
    setRgb(f1.output, kW / 2, 5, r, g, b);
    f0.current = f0.output = f1.current;
    return runAll("history_bounded", staticCase(), {f0, f1});
  };
  EXPECT_TRUE(check(0.5f, 0.5f, 0.0f).passed) << check(0.5f, 0.5f, 0.0f).detail;
  EXPECT_FALSE(check(0.5f, 0.5f, 0.3f).passed);  // chroma off the box, nothing clamped
  EXPECT_FALSE(check(0.2f, 0.9f, 0.0f).passed);  // zero blue, but no negative blue fits
}

// Grey and yellow neighbours: the box corner h = RGB (0.7, 0.2, -0.3). Karis blends
// max(h, 0) = (0.7, 0.2, 0) with the grey centre: (0.45, 0.2, 0.1), 0.0375 outside the box
// and no channel zero. Only Karis explains it; a plain blend clamps at the end instead.
TEST(InvariantHistoryBounded, KarisAcceptsItsLiftedNegativeHistory) {
  Frame f0, f1;
  f0.frame = 0, f0.reset = true, f1.frame = 1;
  f1.current = rgba(0.2f, 0.2f, 0.2f);
  for (int y = 0; y < kH; ++y)
    for (int x = kW / 2; x < kW; ++x) setRgb(f1.current, x, y, 1, 1, 0);
  f1.output = f1.current;
  setRgb(f1.output, kW / 2 - 1, 5, 0.45f, 0.2f, 0.1f);
  f0.current = f0.output = f1.current;
  auto s = staticCase();
  const auto plain = runAll("history_bounded", s, {f0, f1});
  EXPECT_FALSE(plain.passed);
  EXPECT_NEAR(valueOf(plain, "max_excess"), 0.0375, 1e-4);
  s.taa.tonemap_weighting = spec::ToneWeight::Karis;
  const auto karis = runAll("history_bounded", s, {f0, f1});
  EXPECT_TRUE(karis.passed) << karis.detail;
  setRgb(f1.output, kW / 2 - 1, 5, 0.45f, 0.9f, 0.1f);  // no lift explains this green
  EXPECT_FALSE(runAll("history_bounded", s, {f0, f1}).passed);
}

// Every RGB channel goes negative somewhere in this YCoCg box, but no colour in it has all
// three negative (its Y >= 0.125), so a lift raised two channels at most. Lowering all three
// of (1, 0.5, 0.5) would bring it to 0.0417 of the box; the best pair leaves 0.0625.
TEST(InvariantHistoryBounded, ALiftRaisesTwoChannelsAtMost) {
  const box::Box b{{0.125, 0.0625, -0.5}, {0.25, 0.4375, 0.25}};
  const double o[3] = {1.0, 0.5, 0.5};
  EXPECT_NEAR(box::liftedExcess(o, b, box::Lift::NegativeChannels), 0.0625, 1e-4);
}

// shrink_chroma lets the box's chroma reach an eighth of the luma extent around the current
// pixel, even where the neighbourhood has no chroma spread at all.
TEST(InvariantHistoryBounded, ShrinkChromaWidensTheChromaExtent) {
  Frame f0, f1;
  f0.frame = 0, f0.reset = true, f1.frame = 1;
  f1.current = rgba(0.2f, 0.2f, 0.2f);
  setRgb(f1.current, 6, 6, 1.0f, 1.0f, 1.0f);  // luma extent 0.8 around (6..8, 5..7)
  f1.output = f1.current;
  // Y 0.2 as around it, Cg 0, Co = (r - b) / 2 = 0.08 <= 0.8 / 8 = 0.1.
  setRgb(f1.output, 7, 6, 0.28f, 0.2f, 0.12f);
  f0.current = f0.output = f1.current;
  auto s = staticCase();
  EXPECT_FALSE(runAll("history_bounded", s, {f0, f1}).passed);
  s.taa.shrink_chroma = true;
  const auto o = runAll("history_bounded", s, {f0, f1});
  EXPECT_TRUE(o.passed) << o.detail;
}

TEST(InvariantHistoryBounded, MissingCurrentFails) {
  auto seq = boundedSequence(2);
  seq[1].current = Image();
  const auto o = runAll("history_bounded", staticCase(), seq);
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "no current image")) << o.detail;
}

TEST(InvariantHistoryBounded, InapplicableWhereTheBoxDoesNotBoundTheOutput) {
  EXPECT_EQ(inapplicable("history_bounded", staticCase()), "");
  auto karis = staticCase();
  karis.taa.tonemap_weighting = spec::ToneWeight::Karis;
  EXPECT_EQ(inapplicable("history_bounded", karis), "");
  auto expectReason = [](auto mutate, const std::string& part) {
    auto s = staticCase();
    mutate(s);
    const auto why = inapplicable("history_bounded", s);
    EXPECT_TRUE(contains(why, part)) << "'" << why << "' lacks '" << part << "'";
  };
  expectReason([](auto& s) { s.taa.rectify = spec::Rectify::None; },
               "history_bounded checks the clamp/clip box, but taa.rectify is none; remove it from "
               "checks.invariants or enable taa.rectify");
  expectReason([](auto& s) { s.taa.mode = spec::TaaMode::Basic; }, "taa.mode is basic");
  expectReason([](auto& s) { s.taa.mode = spec::TaaMode::Off; }, "taa.mode is off");
  expectReason([](auto& s) { s.taa.tonemap_weighting = spec::ToneWeight::InverseLuma; },
               "taa.tonemap_weighting is inverse_luma");
  expectReason([](auto& s) { s.taa.tonemap_weighting = spec::ToneWeight::Log; },
               "taa.tonemap_weighting is log");
  expectReason([](auto& s) { s.post.sharpen = spec::Sharpen::Cas; }, "post.sharpen is cas");
  expectReason([](auto& s) { s.post.fxaa = true; }, "post.fxaa");
  expectReason([](auto& s) { s.render.upsample = 2.0f; }, "render.upsample is 2");
  expectReason(
      [](auto& s) {
        s.render.scale_schedule.push_back({4, 0.5f});
      },
      "render.scale_schedule");
  expectReason([](auto& s) { s.debug.output = spec::DebugOutput::Velocity; },
               "debug.output is velocity");
}
