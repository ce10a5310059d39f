// History resampling under a panning camera: the Catmull-Rom variants keep the history sharp
// and closer to the reference than bilinear; the B-spline (all-positive weights) blurs it.
#include <gtest/gtest.h>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

const char* kHistoryFilterPan = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"rotate": {"yaw_deg_per_s": 30}},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 24},
  "reference": {"samples": 16}
})";

const std::vector<int> kLast4 = {20, 21, 22, 23};

struct Measured {
  double error = 0.0;     // mean rmse vs reference over frames 20-23
  double contrast = 0.0;  // mean local contrast over the same frames
};

Measured measure(const char* filter) {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const auto& truth =
      renderOnce(kHistoryFilterPan, R"({"taa": {"history_filter": "catmull_rom_5"}})", kLast4, o);
  const auto& run =
      renderOnce(kHistoryFilterPan, std::string(R"({"taa": {"history_filter": ")") + filter + "\"}}", kLast4,
                 std::string(filter) == "catmull_rom_5" ? o : RenderOptions{});
  Measured m;
  for (int f : kLast4) {
    m.error += test::rmse(run[f].color, truth[f].reference) / kLast4.size();
    m.contrast += test::localContrast(run[f].color) / kLast4.size();
  }
  report(std::string("rmse vs reference, ") + filter, m.error);
  report(std::string("local contrast, ") + filter, m.contrast);
  return m;
}

TEST(EffectHistoryFilter, CatmullRomIsCloserToTheReferenceThanBilinearUnderAPan) {
  const Measured bilinear = measure("bilinear");
  for (const char* f : {"catmull_rom_9", "catmull_rom_5", "catmull_rom_16"}) {
    EXPECT_LT(measure(f).error, 0.85 * bilinear.error) << f;
  }
  report("reference local contrast", [] {
    RenderOptions o;
    o.captures |= {Capture::Reference};
    const auto& truth =
        renderOnce(kHistoryFilterPan, R"({"taa": {"history_filter": "catmull_rom_5"}})", kLast4, o);
    return test::localContrast(truth[23].reference);
  }());
}

TEST(EffectHistoryFilter, NineTapCatmullRomMatchesTheExactSixteenTap) {
  const Measured cr9 = measure("catmull_rom_9"), cr16 = measure("catmull_rom_16");
  EXPECT_NEAR(cr9.error, cr16.error, 0.01 * cr16.error);
}

TEST(EffectHistoryFilter, BSplineIsBlurrierThanCatmullRom) {
  const Measured bspline = measure("bspline"), cr = measure("catmull_rom_9");
  EXPECT_LT(bspline.contrast, 0.7 * cr.contrast);
  EXPECT_GT(bspline.error, 1.3 * cr.error);
}

}  // namespace
}  // namespace taa
