// render.msaa: the raster pass draws several coverage samples per pixel and resolves them
// into the single-sample targets. Edges move toward their supersampled coverage, pixels
// away from silhouettes keep their single-sample value (one shading per pixel), the resolved
// ids stay ids of real objects, and a count the device lacks or the deferred path is
// refused as bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "api/device_error.h"
#include "support/case_problems.h"
#include "support/effects.h"
#include "support/process.h"
#include "vk/context.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::renderOnce;
using test::report;

// Fine structures without any temporal or post filter, so the raster pass alone decides
// the edges: what MSAA changes is all the difference.
const char* kMsaaFence = R"({
  "scene": {"builtin": "fence"},
  "camera": {"strafe": {"speed": 1.2, "distance": 0.6}},
  "render": {"width": 160, "height": 90},
  "jitter": {"pattern": "none"},
  "taa": {"mode": "off"},
  "script": {"frames": 4},
  "reference": {"samples": 64},
  "output": {"aux": ["depth"]}
})";

// The sample counts the device offers for colour and depth attachments alike.
VkSampleCountFlags offeredCounts() {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(test::gpu().physical(), &props);
  return props.limits.framebufferColorSampleCounts & props.limits.framebufferDepthSampleCounts;
}

// The largest count above 1 that the device offers (every Vulkan device offers 4).
int largestOffered() {
  for (int n : {8, 4, 2})
    if (offeredCounts() & VkSampleCountFlags(n)) return n;
  return 1;
}

std::string msaaPatch(int samples) {
  return R"({"render": {"msaa": )" + std::to_string(samples) + "}}";
}

// Pixels at least `radius` away from any silhouette: a change of object or material id, or
// a jump in depth (a fence slat over another slat of the same mesh). Every sample of such a
// pixel sees the same surface, so MSAA has nothing to resolve there.
test::Mask interiorMask(const Image& ids, const Image& depth, int radius) {
  const test::Mask edge = test::maskWhere(ids.width, ids.height, [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = std::clamp(x + dx, 0, ids.width - 1);
        const int ny = std::clamp(y + dy, 0, ids.height - 1);
        if (ids.at(nx, ny, 0) != ids.at(x, y, 0)) return true;
        const float a = depth.at(nx, ny, 0), b = depth.at(x, y, 0);
        if (std::fabs(a - b) > 0.02f * std::max(a, b)) return true;
      }
    return false;
  });
  return test::maskNot(test::dilate(edge, ids.width, ids.height, radius));
}

TEST(EffectMsaa, EdgesMoveTowardTheReferenceAndInteriorsKeepTheirValues) {
  const int n = largestOffered();
  ASSERT_GE(n, 4) << "Vulkan requires 4 samples for colour and depth attachments";
  RenderOptions o;
  o.captures |= {Capture::Reference};
  o.captures |= {Capture::Ids};
  const auto& one = renderOnce(kMsaaFence, "{}", {3}, o);
  RenderOptions ids;
  ids.captures |= {Capture::Ids};
  const auto& many = renderOnce(kMsaaFence, msaaPatch(n), {3}, ids);
  const Image& ref = one[3].reference;
  const double e1 = test::rmse(one[3].color, ref), eN = test::rmse(many[3].color, ref);
  report("rmse vs 64-sample reference, frame 3, 1 sample", e1);
  report("rmse vs 64-sample reference, frame 3, " + std::to_string(n) + " samples", eN);
  EXPECT_LT(eN, 0.75 * e1);

  const test::Mask interior =
      interiorMask(test::capturedImage(one[3], Capture::Ids), test::auxImage(one[3], "depth"), 1);
  report("interior pixels compared", test::count(interior));
  report("interior pixels that differ at all",
         test::differing(one[3].color, many[3].color, 0.0, interior));
  report("largest interior difference", test::maxAbs(one[3].color, many[3].color, interior));
  ASSERT_GT(test::count(interior), 4000);
  // Shading runs once per pixel at its centre, so an interior pixel keeps its single-sample
  // value; only where two triangles of one surface share the pixel are two such shadings
  // averaged (a 2x2 quad's derivatives differ slightly between them).
  EXPECT_LE(test::differing(one[3].color, many[3].color, 0.0, interior),
            test::count(interior) / 50);
  EXPECT_LE(test::maxAbs(one[3].color, many[3].color, interior), 0.03);
  // And the edges did change: MSAA is not a no-op.
  EXPECT_GT(test::differing(one[3].color, many[3].color, 1e-3, test::maskNot(interior)), 300);
}

// A mover over a rough floor with anti-ghosting, which reads velocity and ids: the resolved
// ids are sample 0's (never a blend of two ids), so every id in the frame is one the
// single-sample pass also produced.
const char* kMsaaMover = R"({
  "scene": {"builtin": "rough_floor"},
  "movers": [{"shape": "sphere", "start": [-2, 0.7, 1.5], "end": [2, 0.7, 1.5], "speed": 2}],
  "render": {"width": 96, "height": 54},
  "taa": {"anti_ghosting": true},
  "output": {"aux": ["material_id", "velocity"]},
  "script": {"frames": 6}
})";

TEST(EffectMsaa, ResolvedIdsAreIdsOfRealSurfaces) {
  const int n = largestOffered();
  const auto& one = renderOnce(kMsaaMover, "{}", {5});
  const auto& many = renderOnce(kMsaaMover, msaaPatch(n), {5});
  const Image& ids1 = test::capturedImage(one[5], Capture::Ids);
  const Image& idsN = test::capturedImage(many[5], Capture::Ids);
  std::vector<float> known(ids1.data.begin(), ids1.data.end());
  std::sort(known.begin(), known.end());
  int foreign = 0;
  for (float v : idsN.data) foreign += !std::binary_search(known.begin(), known.end(), v);
  EXPECT_EQ(foreign, 0);
  // The mover's silhouette moved toward its coverage: the output differs near it only.
  EXPECT_GT(test::differing(one[5].color, many[5].color, 1e-3), 20);
}

TEST(EffectMsaa, ACountTheDeviceLacksIsRefusedNamingTheKeyAndTheCounts) {
  int missing = 0;
  for (int n : {2, 8})
    if (!(offeredCounts() & VkSampleCountFlags(n))) missing = n;
  if (missing == 0) GTEST_SKIP() << "this device offers 1, 2, 4 and 8 samples";
  const spec::CaseSpec spec = test::effectCase(kMsaaFence, msaaPatch(missing));
  try {
    test::renderCase(spec, {0});
    FAIL() << "render.msaa " << missing << " was accepted";
  } catch (const UnsupportedSettingError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("render.msaa: " + std::to_string(missing) + " samples"), std::string::npos)
        << what;
    EXPECT_NE(what.find("it offers 1"), std::string::npos) << what;
  }
}

TEST(EffectMsaa, TheCliRefusesAnUnofferedCountWithExitTwo) {
  int missing = 0;
  for (int n : {2, 8})
    if (!(offeredCounts() & VkSampleCountFlags(n))) missing = n;
  if (missing == 0) GTEST_SKIP() << "this device offers 1, 2, 4 and 8 samples";
  const fs::path dir = fs::path(TAA_TEST_OUT) / "msaa-refused";
  fs::create_directories(dir);
  const fs::path file = dir / "msaa_unoffered.json";
  std::ofstream(file)
      << R"({"scene": {"builtin": "fence"}, "render": {"width": 32, "height": 18, "msaa": )"
      << missing << R"(}, "taa": {"mode": "off"}, "script": {"frames": 1}})";
  const auto r = test::runHarness("render " + file.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("render.msaa"), std::string::npos) << r.output;
}

TEST(EffectMsaa, ValidationRefusesOtherCountsAndTheDeferredPath) {
  auto p = test::caseProblems(R"({"render": {"msaa": 3}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("render.msaa: a sample count is 1, 2, 4 or 8"), std::string::npos) << p[0];
  p = test::caseProblems(R"({"render": {"msaa": 4, "path": "deferred"}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("render.msaa: multisampling needs forward shading"), std::string::npos)
      << p[0];
  EXPECT_TRUE(test::caseProblems(R"({"render": {"msaa": 4}})").empty());
}

}  // namespace
}  // namespace taa
