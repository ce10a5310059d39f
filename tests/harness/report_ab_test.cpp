// report.ab and report.zoom through the real runner: the B side is the case rendered with
// the preset merged in (an empty preset gives A's bytes, another preset other pixels), the
// chosen region is what the crops show, and the report says so. Bad presets and regions are
// refused when the case loads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "case/case_loader.h"
#include "report/html_report.h"
#include "run/case_runner.h"
#include "support/case_problems.h"
#include "support/gpu.h"
#include "support/text.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

class ReportAb : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::path(TAA_TEST_OUT) / "report-ab" / info->name();
    fs::remove_all(root_);
    fs::create_directories(root_ / "cases/presets");
    std::ofstream(root_ / "cases/presets/presets.json") << R"({
      "same": {},
      "no_history": {"taa": {"alpha": 1.0}},
      "wider": {"render": {"width": 80}}
    })";
  }

  fs::path writeCase(const std::string& report) {
    const fs::path file = root_ / "cases/ab.json";
    std::ofstream(file)
        << R"({"scene": {"builtin": "checkerboard"}, "render": {"width": 64, "height": 36},
      "camera": {"strafe": {"speed": 1.5, "distance": 0.5}}, "script": {"frames": 6},
      "output": {"frames": [2, 5]}, "report": )"
        << report << "}";
    return file;
  }

  run::CaseResult run(const std::string& report) {
    run::RunOptions o;
    o.outDir = root_ / "out";
    return run::runCase(test::device(), cases::loadCase(writeCase(report)), o);
  }

  std::vector<std::string> problems(const std::string& report) {
    return test::caseRefusal([&] { cases::loadCase(writeCase(report)); });
  }

  fs::path root_;
};

TEST_F(ReportAb, AnEmptyPresetReproducesAAndAnotherPresetDiffers) {
  const auto same = run(R"({"ab": "same"})");
  ASSERT_EQ(same.frames.size(), 2u);
  EXPECT_EQ(same.framesRendered, 2 * 6) << "A and B, six frames each (the run line's count)";
  for (const auto& f : same.frames) {
    ASSERT_FALSE(f.images.ab.empty());
    EXPECT_EQ(f.images.abLabel, "preset same");
    EXPECT_EQ(test::readFile(root_ / "out" / f.images.ab),
              test::readFile(root_ / "out" / f.images.actual))
        << "frame " << f.frame;
  }
  const auto other = run(R"({"ab": "no_history"})");
  ASSERT_EQ(other.frames.size(), 2u);
  // Frame 5 has history to lose; alpha 1 shows the raw jittered frame instead.
  const auto& f5 = other.frames[1];
  EXPECT_NE(test::readFile(root_ / "out" / f5.images.ab),
            test::readFile(root_ / "out" / f5.images.actual));
  const std::string html = report::renderHtmlReport({.cases = {other}}, root_ / "out");
  EXPECT_NE(html.find("A: this case | B: preset no_history"), std::string::npos);
  EXPECT_NE(html.find(f5.images.ab), std::string::npos);
}

TEST_F(ReportAb, TheChosenRegionIsWhatTheCropsShow) {
  const auto r = run(R"({"ab": "no_history", "zoom": {"x": 8, "y": 4, "width": 16, "height": 9}})");
  ASSERT_EQ(r.frames.size(), 2u);
  for (const auto& f : r.frames) {
    const auto& im = f.images;
    EXPECT_TRUE(im.zoomChosen);
    EXPECT_EQ(im.zoomX, 8);
    EXPECT_EQ(im.zoomY, 4);
    EXPECT_EQ(im.zoomW, 16);
    EXPECT_EQ(im.zoomH, 9);
    EXPECT_TRUE(fs::exists(root_ / "out" / im.zoomActual)) << im.zoomActual;
    EXPECT_TRUE(fs::exists(root_ / "out" / im.zoomAb)) << im.zoomAb;
  }
  const std::string html = report::renderHtmlReport({.cases = {r}}, root_ / "out");
  EXPECT_NE(html.find("chosen region (report.zoom)"), std::string::npos);
  // Without report.zoom and without goldens there is no worst region to show.
  const auto plain = run(R"({})");
  ASSERT_EQ(plain.frames.size(), 2u);
  EXPECT_TRUE(plain.frames[0].images.zoomActual.empty());
  EXPECT_TRUE(plain.frames[0].images.ab.empty());
}

TEST_F(ReportAb, BadPresetsAndRegionsAreRefusedWhenTheCaseLoads) {
  auto p = problems(R"({"ab": "sam"})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("report.ab: no preset 'sam' in presets/presets.json; did you mean 'same'?"),
            std::string::npos)
      << p[0];
  p = problems(R"({"ab": "wider"})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("changes the output size or the frame count"), std::string::npos) << p[0];
  p = problems(R"({"ab": "same", "ab_presets": "missing.json"})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("report.ab_presets"), std::string::npos) << p[0];
  p = problems(R"({"zoom": {"x": 60, "y": 0, "width": 16, "height": 9}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("report.zoom: the region 60,0 16x9 leaves the 64x36 output"),
            std::string::npos)
      << p[0];
  p = problems(R"({"zoom": {"x": 4}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("report.zoom: a region needs a width and a height"), std::string::npos)
      << p[0];
}

}  // namespace
}  // namespace taa
