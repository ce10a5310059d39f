// Adaptive ray tracing on lavapipe: traced pixels reproduce the raster, unmarked
// pixels are the resolve's output bit for bit, the marked share follows the
// threshold, and the cases render identically on one and two lavapipe threads.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "common/shared.h"
#include "support/case_problems.h"
#include "support/gpu.h"
#include "support/process.h"

namespace taa {
namespace {

double statOf(const FrameRecord& r, const std::string& name) {
  for (const auto& [k, v] : r.stats)
    if (k == name) return v;
  ADD_FAILURE() << "frame " << r.frame << " has no stat " << name;
  return -1.0;
}

float tonemapped(float c) {
  return c / (1.0f + c);
}

struct Agreement {
  double mean = 0.0;       // mean of the largest per-channel tonemapped difference
  double overShare = 0.0;  // share of pixels differing by more than 2/255 tonemapped
};

Agreement agreement(const Image& a, const Image& b) {
  Agreement out;
  size_t over = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      float worst = 0.0f;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(tonemapped(a.at(x, y, c)) - tonemapped(b.at(x, y, c))));
      out.mean += worst;
      over += worst > 2.0f / 255.0f ? 1 : 0;
    }
  out.mean /= double(a.pixelCount());
  out.overShare = double(over) / double(a.pixelCount());
  return out;
}

// Every pixel traced with one ray through its centre, no jitter: the last frame then
// holds the traced image, and "current" the raster's image of the same pixel centres.
// `scene` is the case's scene (and movers) as JSON members.
Agreement tracedAgainstRaster(const std::string& scene, bool rayLod, int frames = 1) {
  const auto spec = test::caseFromJson("{" + scene + R"(,
      "jitter": {"pattern": "none"}, "taa": {"mode": "adaptive"},
      "adaptive": {"trace_all": true, "samples": 1, "ray_lod": )" +
                                       (rayLod ? "true" : "false") + R"(},
      "script": {"frames": )" + std::to_string(frames) + "}}");
  RenderOptions o;
  o.captures |= {Capture::Current};
  const auto records = test::renderCaseWith(spec, o, {frames - 1});
  const FrameRecord& last = records.back();
  EXPECT_DOUBLE_EQ(statOf(last, "traced_share"), 1.0);
  return agreement(last.color, test::capturedImage(last, Capture::Current));
}

std::string builtin(const std::string& name) { return R"("scene": {"builtin": ")" + name + R"("})"; }

TEST(AdaptiveTrace, TracedPixelsEqualTheRasterAtPixelCentres) {
  // Tolerance: rays and raster agree to float rounding inside surfaces; what differs
  // is silhouette pixels whose centre lies within rounding of an edge, and texels of
  // high-contrast textures where the raster's LOD (one derivative per 2x2 quad) and
  // the ray's (per pixel) fall on either side of a mip blend, or the interpolated uv
  // lands within rounding of a checker edge. Measured on lavapipe: checkerboard 2.8%
  // of pixels over 2/255 (mean 0.0007), the other scenes 0.1% or less.
  // A still scene's first frame is as good as any (every pixel is traced; the same
  // numbers at 1 and 4 frames); the movers' BVH is rebuilt every frame from the posed
  // triangles, so they run to frame 3.
  struct Scene {
    const char* name;
    std::string json;
    int frames;
  };
  const Scene scenes[] = {
      {"checkerboard", builtin("checkerboard"), 1},
      {"foliage", builtin("foliage"), 1},  // alpha-tested cards: masked texels continue the ray
      {"fence", builtin("fence"), 1},
      {"wires", builtin("wires"), 1},
      // alpha-tested leaf, blended pane ("over" along the ray), opaque floor
      {"alpha_modes", R"("scene": {"gltf": "scenes/alpha_modes.gltf"})", 1},
      {"movers", builtin("checkerboard") + R"(, "movers": [
         {"shape": "cube", "start": [-1.5, 0.5, 1], "end": [1.5, 0.5, 1], "speed": 2,
          "rotation_speed_deg": 90},
         {"shape": "sphere", "start": [0, 1, 2], "end": [0, 1, -2], "speed": 3}])", 4},
  };
  for (const auto& [name, scene, frames] : scenes) {
    const Agreement a = tracedAgainstRaster(scene, true, frames);
    EXPECT_LT(a.overShare, 0.05) << name;
    EXPECT_LT(a.mean, 0.002) << name;
    std::printf("[ traced vs raster ] %-12s mean %.5f, over 2/255: %.4f of pixels\n", name, a.mean,
                a.overShare);
  }
}

TEST(AdaptiveTrace, RayDifferentialLodMatchesTheRasterWhereMipZeroDoesNot) {
  const Agreement lod = tracedAgainstRaster(builtin("checkerboard"), true);
  const Agreement mip0 = tracedAgainstRaster(builtin("checkerboard"), false);
  std::printf("[ ray lod ] mean %.5f (over %.4f) vs mip 0: %.5f (over %.4f)\n", lod.mean,
              lod.overShare, mip0.mean, mip0.overShare);
  EXPECT_LT(lod.mean * 4.0, mip0.mean);
  EXPECT_LT(lod.overShare * 4.0, mip0.overShare);
}

const char* kWiresMoving = R"({"scene": {"builtin": "wires"},
  "camera": {"strafe": {"speed": 1.0, "distance": 0.6}},
  "taa": {"mode": "adaptive"}, "script": {"frames": 6}})";

TEST(AdaptiveUnmarked, UnmarkedPixelsAreTheResolveOutputBitForBit) {
  const auto spec = test::caseFromJson(kWiresMoving);
  RenderOptions o;
  o.captures |= {Capture::Resolved, Capture::Segmentation};
  const auto frames = test::renderCaseWith(spec, o, {0, 1, 2, 3, 4, 5});
  for (const auto& f : frames) {
    const Image& resolved = test::capturedImage(f, Capture::Resolved);
    const Image& mask = test::capturedImage(f, Capture::Segmentation);
    ASSERT_TRUE(resolved.sameShape(f.color));
    size_t unmarked = 0, differing = 0, changedMarked = 0;
    for (int y = 0; y < f.color.height; ++y)
      for (int x = 0; x < f.color.width; ++x) {
        const bool same = sameRgbBits(f.color, resolved, x, y);
        if (uint32_t(mask.at(x, y)) == ADAPTIVE_MASK_NONE) {
          ++unmarked;
          differing += same ? 0 : 1;
        } else {
          changedMarked += same ? 0 : 1;
        }
      }
    EXPECT_EQ(differing, 0u) << "frame " << f.frame;
    // Frame 0 has no history: every pixel is traced or FXAA'd.
    if (f.frame == 0)
      EXPECT_EQ(unmarked, 0u);
    else
      EXPECT_GT(unmarked, f.color.pixelCount() / 2) << "frame " << f.frame;
    EXPECT_GT(changedMarked, 0u) << "frame " << f.frame << ": tracing changed nothing";
  }
}

TEST(AdaptiveUnmarked, TheResolveIsThePlainFullResolve) {
  // Frame 0 has no history, so the adaptive run's resolve output (before tracing) is
  // the plain full-mode output of the same frame, bit for bit: the rejection output
  // added for adaptive mode changes nothing else.
  auto adaptive = test::caseFromJson(kWiresMoving);
  auto plain = test::caseFromJson(R"({"scene": {"builtin": "wires"},
    "camera": {"strafe": {"speed": 1.0, "distance": 0.6}}, "taa": {"mode": "full"}, "script": {"frames": 1}})");
  adaptive.script.frames = 1;
  RenderOptions o;
  o.captures |= {Capture::Resolved, Capture::Segmentation};
  const auto a = test::renderCaseWith(adaptive, o, {0});
  const auto p = test::renderCase(plain, {0});
  const Image& resolved = test::capturedImage(a[0], Capture::Resolved);
  EXPECT_TRUE(sameBits(resolved, p[0].color));
}

// One ray a traced pixel: how many it gets does not move the marks (these tests' shares are
// the same at the default 4), and the marks are what they measure.
double tracedShare(const std::string& extra) {
  const auto spec = test::caseFromJson(R"({"scene": {"builtin": "checkerboard"},
    "camera": {"strafe": {"speed": 1.0, "distance": 0.3}}, "taa": {"mode": "adaptive"},
    "adaptive": {"samples": 1, )" + extra + R"(}, "script": {"frames": 3}})");
  const auto frames = test::renderCase(spec, {2});
  return statOf(frames.back(), "traced_share");
}

TEST(AdaptiveSegmentation, MarkedShareFollowsTheThreshold) {
  double previous = 2.0, atQuarter = -1.0;
  for (const char* threshold : {"0.02", "0.1", "0.25", "0.6", "1.5"}) {
    const double share =
        tracedShare(std::string(R"("history_count": 0, "threshold": )") + threshold);
    if (std::string(threshold) == "0.25") atQuarter = share;
    std::printf("[ traced share ] threshold %s: %.4f\n", threshold, share);
    EXPECT_GT(share, 0.0) << threshold;
    EXPECT_LT(share, 1.0) << threshold;
    EXPECT_LT(share, previous) << threshold;
    previous = share;
  }
  EXPECT_DOUBLE_EQ(tracedShare(R"("trace_all": true)"), 1.0);
  // The history count keeps pixels marked after the camera moved on.
  EXPECT_GT(tracedShare(R"("history_count": 8, "threshold": 0.25)"), atQuarter);
}

// Each derivative term marks pixels by itself: with every weight 0 nothing is traced, and any
// one weight alone traces some pixels (the settings audit's scene cannot show the material
// weight: the other terms already mark its pixels there).
TEST(AdaptiveSegmentation, EachWeightMarksPixelsByItself) {
  const std::string none =
      R"("history_count": 0, "weight_normal": 0, "weight_depth": 0, "weight_material": 0, "weight_luminance": 0)";
  EXPECT_EQ(tracedShare(none), 0.0);
  for (const char* weight :
       {"weight_normal", "weight_depth", "weight_material", "weight_luminance"}) {
    std::string alone = none;
    alone.replace(alone.find(std::string(weight) + "\": 0") + std::string(weight).size() + 3, 1,
                  "1");
    const double share = tracedShare(alone);
    std::printf("[ traced share ] %s alone: %.4f\n", weight, share);
    EXPECT_GT(share, 0.0) << weight;
  }
}

// A repo case cut to its first `frames` frames (its last two written), for checks that hold
// on every frame alike: the command stream repeats from the third frame on, so a thread-count
// difference or a validation error shows there as in frame 23, at a fraction of the render
// (the thread-count check renders six: every frame of both cases traces 9-20% of its pixels).
// The case cut to `frames` frames (its last two written); a cut case has no goldens of its own.
std::string shortenedCase(const std::string& caseName, int frames) {
  std::ifstream in(std::string(TAA_SOURCE_DIR) + "/cases/" + caseName + ".json");
  auto j = nlohmann::json::parse(in);
  if (j["script"]["frames"].get<int>() > frames) {
    j["script"]["frames"] = frames;
    j["output"]["frames"] = {frames - 2, frames - 1};
  }
  j["checks"]["golden"] = false;
  const std::string dir = std::string(TAA_TEST_OUT) + "/adaptive-short-" + std::to_string(frames);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + caseName + ".json";
  std::ofstream(path) << j.dump(1);
  return path;
}

std::vector<std::string> renderedHashes(const std::string& caseName, const std::string& env) {
  const std::string out =
      std::string(TAA_TEST_OUT) + "/adaptive-determinism-" + env.substr(env.find('=') + 1);
  const auto r = test::runHarness("render " + shortenedCase(caseName, 6) + " --out " + out, env);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::vector<std::string> found;
  const std::regex line("frame \\d+ sha256 ([0-9a-f]{64})");
  for (std::sregex_iterator it(r.output.begin(), r.output.end(), line), end; it != end; ++it)
    found.push_back((*it)[1]);
  return found;
}

TEST(AdaptiveDeterminism, OneAndTwoLavapipeThreadsGiveIdenticalFrames) {
  for (const char* name : {"adaptive_wires", "adaptive_mask_debug"}) {
    const auto one = renderedHashes(name, "LP_NUM_THREADS=1");
    const auto two = renderedHashes(name, "LP_NUM_THREADS=2");
    ASSERT_FALSE(one.empty()) << name;
    EXPECT_EQ(one, two) << name;
  }
}

// `run`, not `render`: adaptive_wires's adaptive_unmarked invariant captures the resolve before
// the trace, a copy with barriers of its own that `render` leaves out.
TEST(AdaptiveCases, RunCleanUnderValidation) {
  for (const char* name : {"adaptive_wires", "adaptive_mask_debug"}) {
    const auto r =
        test::runHarness("run " + shortenedCase(name, 4) + " --out " + TAA_TEST_OUT +
                         "/adaptive-validate --validate");
    EXPECT_EQ(r.exitCode, 0) << name << "\n" << r.output;
    EXPECT_EQ(r.output.find("VUID"), std::string::npos) << name << "\n" << r.output;
  }
}


bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const auto& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST(AdaptiveSpec, KeysNeedAdaptiveModeAndAnUnresampledOutput) {
  EXPECT_TRUE(test::caseProblems(R"({"taa": {"mode": "adaptive"}, "adaptive": {"samples": 8}})").empty());
  EXPECT_TRUE(mentions(test::caseProblems(R"({"adaptive": {"samples": 8}})"), "adaptive.samples"));
  EXPECT_TRUE(mentions(test::caseProblems(R"({"taa": {"mode": "full"}, "adaptive": {"ray_lod": false}})"),
                       "taa.mode is adaptive"));
  EXPECT_TRUE(mentions(test::caseProblems(R"({"taa": {"mode": "adaptive"}, "render": {"upsample": 2}})"),
                       "taa.mode"));
  EXPECT_TRUE(mentions(test::caseProblems(R"({"debug": {"output": "segmentation"}})"), "debug.output"));
  EXPECT_TRUE(
      test::caseProblems(R"({"taa": {"mode": "adaptive"}, "debug": {"output": "segmentation"}})").empty());
  EXPECT_TRUE(mentions(
      test::caseProblems(
          R"({"taa": {"mode": "adaptive"}, "adaptive": {"trace_all": true, "threshold": 1}})"),
      "adaptive.threshold"));
  EXPECT_TRUE(mentions(test::caseProblems(R"({"taa": {"mode": "adaptive"}, "adaptive": {"samples": 17}})"),
                       "samples"));
  EXPECT_TRUE(
      test::caseProblems(
          R"({"taa": {"mode": "adaptive"}, "checks": {"invariants": ["adaptive_unmarked"]}})")
          .empty());
  EXPECT_TRUE(
      mentions(test::caseProblems(R"({"checks": {"invariants": ["adaptive_unmarked"]}})"), "adaptive"));
}

}  // namespace
}  // namespace taa
