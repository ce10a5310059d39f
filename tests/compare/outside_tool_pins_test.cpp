// Our metrics pinned to figures computed by other people's tools on stored image pairs, so that a
// change to FLIP's defaults or to a metric's definition fails here even when our own second
// implementation (flip_double.cpp, the Python references) moves with it. Where the figures came
// from, with the tools' versions and the commands, is tests/compare/pinned/PROVENANCE.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "compare/compare_files.h"
#include "core/image_io.h"

namespace {

using taa::compare::CompareOutcome;
using taa::compare::CompareRequest;

const std::string kPinned = std::string(TAA_SOURCE_DIR) + "/tests/compare/pinned/";

// What NVIDIA's FLIP tool (v1.6) prints for one pair: pooled values to six decimals. Its minimum
// is not pinned: where the colour difference is near 0, FLIP's pow(colour, 1 - feature) turns a
// difference in the seventh digit of the colour into one in the fifth (the two implementations'
// smallest values differ by up to 1.6e-5 on these pairs, while their means agree to 3e-7).
struct FlipToolFigures {
  double mean, weightedMedian, firstWeightedQuartile, thirdWeightedQuartile, max;
};

// HDR-FLIP adds the exposure range the tool chose (four decimals).
struct HdrFlipToolFigures {
  double startExposure, stopExposure;
  int exposures;
  FlipToolFigures flip;
};

// What OpenImageIO's idiff (2.4.7.1) prints: six significant digits.
struct IdiffFigures {
  double meanError, rmsError, peakSnr, maxError;
};

struct PinnedPair {
  const char* name;  // files NAME_reference.{png,exr} and NAME_taa.{png,exr}
  FlipToolFigures ldrFlip;
  HdrFlipToolFigures hdrFlip;
  IdiffFigures idiffPng, idiffExr;
};

const PinnedPair kPairs[] = {
    {"fence",
     {0.025903, 0.069699, 0.024689, 0.108539, 0.273352},
     {1.8260, 2.4278, 2, {0.041931, 0.146017, 0.090220, 0.207861, 0.457985}},
     {0.00906156, 0.0241554, 32.3397, 0.262745},
     {0.0101595, 0.0260045, 31.699, 0.272339}},
    {"open_area",
     {0.044016, 0.071180, 0.035989, 0.141512, 0.424318},
     {0.9289, 2.5301, 2, {0.068287, 0.136565, 0.062312, 0.245393, 0.639837}},
     {0.00770748, 0.0236553, 32.5214, 0.380392},
     {0.0113262, 0.033086, 33.4835, 0.529419}},
    {"wires",
     {0.013608, 0.017494, 0.009981, 0.069116, 0.267379},
     {1.8260, 2.7339, 2, {0.014209, 0.036780, 0.010278, 0.112819, 0.455112}},
     {0.00138046, 0.00799538, 41.9432, 0.301961},
     {0.00240572, 0.0126523, 37.9566, 0.222168}},
};

CompareOutcome compare(const PinnedPair& pair, const char* extension, bool hdr) {
  CompareRequest request;
  request.referencePath = kPinned + pair.name + "_reference." + extension;
  request.testPath = kPinned + pair.name + "_taa." + extension;
  request.hdr = hdr;
  return taa::compare::compareFiles(request);
}

double value(const CompareOutcome& outcome, const std::string& metric) {
  for (const auto& [name, v] : outcome.values)
    if (name == metric) return v;
  ADD_FAILURE() << "no metric " << metric;
  return std::nan("");
}

// The FLIP tool's weighted percentile (its pooling of an error map): the values sorted ascending,
// the first whose running sum exceeds `p` times the total. It weighs each pixel by its own error,
// so it says where the visible error lies; our p50/p95/p99 are plain nearest-rank percentiles.
double weightedPercentile(const taa::Image& map, double p) {
  std::vector<float> v(map.data.begin(), map.data.end());
  std::sort(v.begin(), v.end());
  double total = 0.0;
  for (float x : v) total += x;
  double running = 0.0;
  for (float x : v) {
    running += x;
    if (running > p * total) return x;
  }
  return v.empty() ? 0.0 : v.back();
}

// Printed to six decimals: half a unit of rounding, and the tool sums in float.
constexpr double kFlipTolerance = 1.5e-6;
// A weighted percentile is one pixel's value, not a mean: the implementations' per-pixel values
// differ by a few 1e-6 (2.2e-6 at most on these pairs).
constexpr double kFlipPixelTolerance = 5e-6;

void expectFlipMatches(const CompareOutcome& outcome, const FlipToolFigures& tool,
                       const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_NEAR(value(outcome, "flip_mean"), tool.mean, kFlipTolerance);
  EXPECT_NEAR(value(outcome, "flip_max"), tool.max, kFlipTolerance);
  const auto& map = outcome.flipMap;
  ASSERT_FALSE(map.data.empty());
  EXPECT_NEAR(weightedPercentile(map, 0.5), tool.weightedMedian, kFlipPixelTolerance);
  EXPECT_NEAR(weightedPercentile(map, 0.25), tool.firstWeightedQuartile, kFlipPixelTolerance);
  EXPECT_NEAR(weightedPercentile(map, 0.75), tool.thirdWeightedQuartile, kFlipPixelTolerance);
}

// idiff prints six significant digits.
void expectNearRelative(double ours, double theirs, const char* what) {
  EXPECT_NEAR(ours, theirs, 6e-6 * std::fabs(theirs)) << what;
}

void expectLinearMatches(const CompareOutcome& outcome, const IdiffFigures& idiff) {
  expectNearRelative(value(outcome, "mean_abs"), idiff.meanError, "mean_abs against idiff's mean error");
  expectNearRelative(value(outcome, "rmse"), idiff.rmsError, "rmse against idiff's RMS error");
  expectNearRelative(value(outcome, "max_abs"), idiff.maxError, "max_abs against idiff's max error");
}

double largestSample(const std::string& path) {
  const taa::Image img = taa::readImage(path);
  return double(*std::max_element(img.data.begin(), img.data.end()));
}

}  // namespace

TEST(OutsideToolPins, LdrFlipOfDisplayPairsIsNvidiasFlipTool) {
  for (const auto& pair : kPairs) expectFlipMatches(compare(pair, "png", false), pair.ldrFlip, pair.name);
}

TEST(OutsideToolPins, HdrFlipOfLinearPairsIsNvidiasFlipTool) {
  for (const auto& pair : kPairs) {
    const CompareOutcome outcome = compare(pair, "exr", true);
    SCOPED_TRACE(pair.name);
    EXPECT_EQ(outcome.flipKind, "hdr");
    EXPECT_NEAR(outcome.startExposure, pair.hdrFlip.startExposure, 5e-5);
    EXPECT_NEAR(outcome.stopExposure, pair.hdrFlip.stopExposure, 5e-5);
    EXPECT_EQ(outcome.exposures, pair.hdrFlip.exposures);
    expectFlipMatches(outcome, pair.hdrFlip.flip, std::string(pair.name) + " HDR");
  }
}

TEST(OutsideToolPins, LinearMetricsAreIdiffs) {
  for (const auto& pair : kPairs) {
    SCOPED_TRACE(pair.name);
    const CompareOutcome png = compare(pair, "png", false);
    expectLinearMatches(png, pair.idiffPng);
    expectNearRelative(value(png, "psnr"), pair.idiffPng.peakSnr, "psnr of 8-bit samples (peak 1)");
    expectLinearMatches(compare(pair, "exr", false), pair.idiffExr);
  }
}

// Our PSNR takes a fixed peak of 1.0 (nominal white; README, "Metrics") so that HDR frames compare
// on one scale; idiff takes the larger of 1 and the largest sample of the two images. The open-area
// pair's sky reaches 1.5625, so there the two differ by exactly 20 log10(1.5625) dB.
TEST(OutsideToolPins, PsnrIsIdiffsWithAFixedPeakOfOne) {
  for (const auto& pair : kPairs) {
    SCOPED_TRACE(pair.name);
    const std::string base = kPinned + pair.name;
    const double peak = std::max({1.0, largestSample(base + "_reference.exr"), largestSample(base + "_taa.exr")});
    const double ours = value(compare(pair, "exr", false), "psnr");
    EXPECT_NEAR(ours + 20.0 * std::log10(peak), pair.idiffExr.peakSnr, 5e-4);
    if (std::string(pair.name) == "open_area") EXPECT_DOUBLE_EQ(peak, 1.5625);
    else EXPECT_DOUBLE_EQ(peak, 1.0);
  }
}
