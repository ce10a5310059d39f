// The sweep replays one script per preset against one shared reference and writes the
// table, CSV and plot; its numbers must order presets the way their techniques promise.
#include "sweep/sweep.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "invariants/flicker_meter.h"
#include "run/timing.h"
#include "support/gpu.h"
#include "support/text.h"

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

cases::Presets presets() {
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
  // The cost columns are each lane's median frame: nearest rank over the 6 measured frames.
  for (const auto& p : r.presets) {
    ASSERT_EQ(p.frameMsPerFrame.size(), 6u) << p.name;
    EXPECT_EQ(p.frameMs, run::percentile(p.frameMsPerFrame, 50.0)) << p.name;
    EXPECT_EQ(p.taaMs, run::percentile(p.taaMsPerFrame, 50.0)) << p.name;
  }
  EXPECT_GT(r.presets[0].referenceFlicker, 0.0);
  const fs::path out = file.parent_path().parent_path() / "out";
  sweep::writeSweep(out, r);
  for (const char* f : {"sweep.csv", "frames.csv", "sweep.md", "sweep.svg", "report.html"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const std::string frames = test::readFile(out / "frames.csv");
  EXPECT_EQ(frames.rfind("preset,frame,rmse,flip_mean,taa_ms,frame_ms\n", 0), 0u) << frames;
  EXPECT_NE(frames.find("\ndefault,4,"), std::string::npos) << frames;
  const std::string svg = test::readFile(out / "sweep.svg");
  // The static plot names the points of the Pareto front, as many as the table marks.
  EXPECT_NE(svg.find(">default</text>"), std::string::npos) << svg;
  const std::string md = sweep::markdownTable(r);
  EXPECT_NE(md.find("| default |"), std::string::npos) << md;
  EXPECT_NE(md.find("| yes |"), std::string::npos) << md;  // a Pareto front exists
  EXPECT_EQ(test::count(svg, "class=\"point-label\""), test::count(md, "| yes |")) << md;
}

// Flicker over the measured frames F..N-1 counts every pair from (F-1, F) on: the frame before
// the first measured one is read too. Recomputed here from the case's own frames.
TEST(Sweep, FlickerCountsThePairEndingAtTheFirstMeasuredFrame) {
  const fs::path file = writeCase("flicker");
  sweep::SweepOptions o;
  o.fromFrame = 4;
  const auto r = sweep::runSweep(test::device(), file, presets(), {"default"}, o);
  ASSERT_EQ(r.presets.size(), 1u);
  const auto records = test::renderCase(cases::loadCase(file).spec, {3, 4, 5, 6, 7, 8, 9});
  invariants::FlickerMeter expected;
  for (const auto& rec : records)
    if (rec.hasImages) expected.add(rec.color, rec.frame > 3);
  EXPECT_DOUBLE_EQ(r.presets[0].flicker, expected.mean());
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

// MSAA is a baseline of the sweep: next to no_aa on the same replay it lands closer to the
// reference, and the raster pass that does the work is what its time shows.
TEST(Sweep, MsaaBaselineBeatsNoAaAndPaysInTheRasterPass) {
  // Geometric edges (MSAA does nothing for texture aliasing) against a fine reference.
  const fs::path dir = fs::path(TAA_TEST_OUT) / "sweep" / "msaa" / "cases";
  fs::create_directories(dir);
  const fs::path file = dir / "fence.json";
  std::ofstream(file) << R"({
    "scene": {"builtin": "fence"}, "render": {"width": 96, "height": 54},
    "camera": {"strafe": {"speed": 1.2, "distance": 0.6}}, "script": {"frames": 8},
    "reference": {"samples": 32}
  })";
  const auto shipped = cases::loadPresets(fs::path(TAA_SOURCE_DIR) / "cases/presets/presets.json");
  sweep::SweepOptions o;
  o.fromFrame = 4;
  const auto r = sweep::runSweep(test::device(), file, shipped, {"no_aa", "msaa_4x"}, o);
  ASSERT_EQ(r.presets.size(), 2u);
  const auto& none = r.presets[0];
  const auto& msaa = r.presets[1];
  EXPECT_LT(msaa.rmse, 0.8 * none.rmse) << "msaa " << msaa.rmse << " no_aa " << none.rmse;
  EXPECT_EQ(msaa.taaMs, 0.0);  // no pass after the raster: MSAA's cost is all in frameMs
  EXPECT_GT(msaa.frameMs, 0.0);
  ASSERT_FALSE(msaa.passes.empty());
  EXPECT_NE(msaa.passes[0].find("4x MSAA"), std::string::npos) << msaa.passes[0];
}

// Every shipped preset is a valid patch of every sweep scene (a count the device lacks is
// refused only when rendering, by the device).
TEST(Sweep, ShippedPresetsParseOnEverySweepScene) {
  const fs::path root(TAA_SOURCE_DIR);
  const auto shipped = cases::loadPresets(root / "cases/presets/presets.json");
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(root / "cases/sweep")) {
    const nlohmann::json base = nlohmann::json::parse(test::readFile(entry.path()));
    for (const auto& [name, patch] : shipped) {
      nlohmann::json patched = base;
      patched.merge_patch(patch);
      EXPECT_NO_THROW(cases::parseCase(patched.dump(), entry.path()))
          << entry.path() << " + " << name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 4 * 19);
}

// A preset's lane: the case's invariants it cannot meet are not applicable (the sweep judges
// none), its shader may sit beside the presets file, and a preset whose shader lacks a
// capability the case needs is skipped with the reason instead of refusing the sweep.
TEST(Sweep, PresetLanesNoteInapplicableInvariantsFindShadersAndSkipWhatTheyCannotRun) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "sweep" / "lanes" / "cases";
  fs::create_directories(dir / "presets");
  std::ofstream(dir / "mover.json") << R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 64, "height": 36},
    "movers": [{"shape": "cube", "start": [-2, 0.5, 2], "end": [2, 0.5, 2], "speed": 2.4}],
    "script": {"frames": 6}, "reference": {"samples": 2},
    "checks": {"invariants": ["finite", "no_ghosting"]}
  })";
  std::ofstream(dir / "presets" / "mine.comp") << R"(#version 450
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p), 1.0));
}
)";
  setenv("TAA_SHADER_CACHE", (dir / "cache").c_str(), 1);
  const cases::Presets lanes = {
      {"off", {{"taa", {{"mode", "off"}}}}},
      {"mine", {{"taa", {{"shader", "mine.comp"}}}}},
      {"mine_up", {{"render", {{"upsample", 2.0}}}, {"taa", {{"shader", "mine.comp"}}}}}};
  sweep::SweepOptions o;
  o.presetsDir = dir / "presets";
  const auto r = sweep::runSweep(test::device(), dir / "mover.json", lanes, {"off", "mine", "mine_up"}, o);
  ASSERT_EQ(r.presets.size(), 3u);
  EXPECT_EQ(r.presets[0].name, "off");
  ASSERT_EQ(r.presets[0].notApplicable.size(), 1u);
  EXPECT_NE(r.presets[0].notApplicable[0].find("no_ghosting: "), std::string::npos)
      << r.presets[0].notApplicable[0];
  EXPECT_TRUE(r.presets[0].skipped.empty());
  EXPECT_EQ(r.presets[1].name, "mine");  // found in presets/, beside the presets file
  EXPECT_TRUE(r.presets[1].skipped.empty());
  EXPECT_GT(r.presets[1].flipMean, 0.0);
  EXPECT_EQ(r.presets[2].name, "mine_up");
  EXPECT_NE(r.presets[2].skipped.find("does not declare upsampling"), std::string::npos)
      << r.presets[2].skipped;
  EXPECT_TRUE(r.presets[2].flipPerFrame.empty());
  const std::string md = sweep::markdownTable(r);
  EXPECT_NE(md.find("n/a: no_ghosting"), std::string::npos) << md;
  EXPECT_NE(md.find("| mine_up | - |"), std::string::npos) << md;
  EXPECT_NE(md.find("skipped: "), std::string::npos) << md;
}

}  // namespace
}  // namespace taa
