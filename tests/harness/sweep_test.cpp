// The sweep replays one script per preset against one shared reference and writes the
// table, CSV and plot; its numbers must order presets the way their techniques promise.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "case/case_error.h"
#include "support/gpu.h"
#include "support/text.h"
#include "sweep/sweep.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

fs::path writeCase(const char* name) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "sweep" / name / "cases";
  fs::create_directories(dir);
  std::ofstream(dir / "pan.json") << R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 64, "height": 36},
    "camera": {"strafe": {"speed": 1.5, "distance": 0.5}}, "script": {"frames": 10},
    "reference": {"samples": 4}
  })";
  return dir / "pan.json";
}

sweep::Presets presets() {
  return {{"basic", {{"taa", {{"mode", "basic"}}}}}, {"default", nlohmann::json::object()},
          {"bad", {{"taa", {{"alpah", 0.2}}}}}};
}

TEST(Sweep, BasicGhostsMoreThanTheFullResolveAndEverythingIsWritten) {
  const fs::path file = writeCase("order");
  sweep::SweepOptions o;
  o.fromFrame = 4;
  const auto r = sweep::runSweep(test::device(), file, presets(), {"default", "basic"}, o);
  ASSERT_EQ(r.presets.size(), 2u);
  EXPECT_EQ(r.presets[0].rmsePerFrame.size(), 6u);  // frames 4..9
  EXPECT_GT(r.presets[1].rmse, 1.5 * r.presets[0].rmse) << "basic " << r.presets[1].rmse << " default "
                                                        << r.presets[0].rmse;
  EXPECT_GT(r.presets[1].flipMean, r.presets[0].flipMean);
  EXPECT_GT(r.presets[0].frameMs, 0.0);
  EXPECT_GT(r.presets[0].referenceFlicker, 0.0);
  const fs::path out = file.parent_path().parent_path() / "out";
  sweep::writeSweep(out, r);
  for (const char* f : {"sweep.csv", "frames.csv", "sweep.md", "sweep.svg", "report.html"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const std::string svg = test::readFile(out / "sweep.svg");
  // The static plot names the points of the Pareto front, as many as the table marks.
  EXPECT_NE(svg.find(">default</text>"), std::string::npos) << svg;
  const std::string md = sweep::markdownTable(r);
  EXPECT_NE(md.find("| default |"), std::string::npos) << md;
  EXPECT_NE(md.find("| yes |"), std::string::npos) << md;  // a Pareto front exists
  EXPECT_EQ(test::count(svg, "class=\"point-label\""), test::count(md, "| yes |")) << md;
}

TEST(Sweep, UnknownOrInvalidPresetsAreBadInputNamingThePreset) {
  const fs::path file = writeCase("bad");
  try {
    sweep::runSweep(test::device(), file, presets(), {"defualt", "bad"}, {});
    FAIL() << "expected CaseError";
  } catch (const cases::CaseError& e) {
    const std::string all = e.what();
    EXPECT_NE(all.find("unknown preset 'defualt'; did you mean 'default'?"), std::string::npos) << all;
    EXPECT_NE(all.find("preset bad:"), std::string::npos) << all;
    EXPECT_NE(all.find("taa.alpah"), std::string::npos) << all;
  }
}

}  // namespace
}  // namespace taa
