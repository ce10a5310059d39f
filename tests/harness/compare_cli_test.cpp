// `taa-harness compare` as scripts drive it: exit codes for bounds and bad input, the JSON
// result against the library's own numbers, metric selection, options that must take effect,
// and the heatmap file.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "compare/flip.h"
#include "compare/metrics.h"
#include "core/image_io.h"
#include "support/noise.h"
#include "support/process.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

Image picture(int w, int h, uint32_t seed, float noise) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const float base = ((x / 8 + y / 8) % 2 ? 0.7f : 0.25f) + 0.1f * float(c);
        img.at(x, y, c) = std::max(0.0f, base + noise * (test::hashUnit(seed, x, y, c) - 0.5f));
      }
  return img;
}

class CompareCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(TAA_TEST_OUT) / "compare-cli" / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    writePng(path("a.png"), picture(64, 40, 1, 0.0f));
    writePng(path("b.png"), picture(64, 40, 2, 0.2f));
    writeExr(path("a.exr"), picture(64, 40, 1, 0.0f));
    writeExr(path("b.exr"), picture(64, 40, 2, 0.2f));
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  test::ProcessResult compare(const std::string& args) {
    return test::runHarness("compare " + args);
  }
  nlohmann::json json(const std::string& args) {
    const auto r = compare(args + " --json");
    EXPECT_LE(r.exitCode, 1) << r.output;
    return nlohmann::json::parse(r.output);
  }
  fs::path dir_;
};

TEST_F(CompareCli, IdenticalImagesPassAndReportZero) {
  const auto r = compare(path("a.png") + " " + path("a.png") + " --max flip_mean=0,max_abs=0");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("flip_mean 0\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("psnr inf\n"), std::string::npos) << r.output;
}

TEST_F(CompareCli, BoundsDecideTheExitCode) {
  const std::string pair = path("a.png") + " " + path("b.png");
  auto r = compare(pair + " --max flip_mean=0.001");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("FAIL flip_mean"), std::string::npos) << r.output;
  EXPECT_EQ(compare(pair + " --max flip_mean=0.9,rmse=0.5").exitCode, 0);
  r = compare(pair + " --min psnr=100");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("FAIL psnr"), std::string::npos) << r.output;
  EXPECT_EQ(compare(pair + " --min psnr=1").exitCode, 0);
}

TEST_F(CompareCli, JsonMatchesTheLibraryOnTheSameFiles) {
  const Image a = readImage(path("a.png"));
  const Image b = readImage(path("b.png"));
  const auto flip = compare::flipLdr(a, b);
  const auto lin = compare::computeMetrics(a, b);
  const auto j = json(path("a.png") + " " + path("b.png"));
  EXPECT_EQ(j["flip"], "ldr");
  EXPECT_EQ(j["width"], 64);
  EXPECT_DOUBLE_EQ(j["metrics"]["flip_mean"].get<double>(), flip.mean);
  EXPECT_DOUBLE_EQ(j["metrics"]["flip_p99"].get<double>(), flip.p99);
  EXPECT_DOUBLE_EQ(j["metrics"]["rmse"].get<double>(), lin.rmse);
  EXPECT_DOUBLE_EQ(j["metrics"]["share_over"].get<double>(), lin.shareOverThreshold);
  EXPECT_EQ(j["pass"], true);
  EXPECT_EQ(j["metrics"].size(), 10u);
}

TEST_F(CompareCli, OptionsTakeEffect) {
  const std::string pair = path("a.png") + " " + path("b.png");
  const auto only = json(pair + " --metrics rmse,psnr");
  EXPECT_EQ(only["metrics"].size(), 2u);
  EXPECT_FALSE(only["metrics"].contains("flip_mean"));
  EXPECT_EQ(only["flip"], "");
  const double defaultPpd = json(pair + " --metrics flip_mean")["metrics"]["flip_mean"];
  const double closer = json(pair + " --metrics flip_mean --flip-ppd 20")["metrics"]["flip_mean"];
  EXPECT_GT(closer, defaultPpd);
  const double loose =
      json(pair + " --metrics share_over --pixel-threshold 0.5")["metrics"]["share_over"];
  const double tight = json(pair + " --metrics share_over")["metrics"]["share_over"];
  EXPECT_LT(loose, tight);
  EXPECT_EQ(json(pair + " --threads 1")["metrics"], json(pair + " --threads 3")["metrics"]);
}

TEST_F(CompareCli, LinearFilesUseTonemappedOrHdrFlip) {
  const std::string pair = path("a.exr") + " " + path("b.exr");
  const auto ldr = json(pair);
  EXPECT_EQ(ldr["flip"], "ldr-tonemapped");
  const auto hdr = json(pair + " --hdr");
  EXPECT_EQ(hdr["flip"], "hdr");
  EXPECT_GE(hdr["hdr_exposures"]["count"].get<int>(), 2);
  EXPECT_NE(hdr["metrics"]["flip_mean"], ldr["metrics"]["flip_mean"]);
  const Image a = readExr(path("a.exr"));
  const Image b = readExr(path("b.exr"));
  EXPECT_DOUBLE_EQ(hdr["metrics"]["flip_mean"].get<double>(), compare::flipHdr(a, b).mean);
}

TEST_F(CompareCli, HeatmapIsWrittenAtImageSize) {
  const auto r = compare(path("a.png") + " " + path("b.png") + " --metrics rmse --heatmap " +
                         path("heat.png"));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const Image heat = readImage(path("heat.png"));
  EXPECT_EQ(heat.width, 64);
  EXPECT_EQ(heat.height, 40);
}

TEST_F(CompareCli, BadInputIsExitTwoWithTheReason) {
  const std::string a = path("a.png");
  auto expectBad = [&](const std::string& args, const std::string& says) {
    const auto r = compare(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << args << "\n" << r.output;
  };
  expectBad(a + " " + path("missing.png"), "missing.png");
  expectBad(a, "expected REFERENCE and TEST");
  expectBad(a + " " + path("a.exr"), "compare an EXR with an EXR");
  expectBad(a + " " + a + " --hdr", "--hdr needs linear inputs");
  expectBad(a + " " + a + " --metrics flip_mean,sharpness", "unknown metric 'sharpness'");
  expectBad(a + " " + a + " --max flip_mean", "METRIC=VALUE");
  expectBad(a + " " + a + " --max flip_mean=lots", "not a number");
  // Every numeric option is range-checked before any work: a FLIP kernel for 1e6 pixels
  // per degree ran until killed, 1e9 ended in bad_alloc.
  expectBad(a + " " + a + " --flip-ppd -3", "--flip-ppd: -3 is outside [0.01, 1000]");
  expectBad(a + " " + a + " --flip-ppd 1000000", "--flip-ppd: 1000000 is outside");
  expectBad(a + " " + a + " --flip-ppd 1e9", "--flip-ppd: 1e9 is outside");
  expectBad(a + " " + a + " --flip-ppd nan", "--flip-ppd: 'nan' is not a number");
  expectBad(a + " " + a + " --threads 0", "--threads: 0 is outside");
  expectBad(a + " " + a + " --threads 2.5", "--threads: '2.5' is not a whole number");
  expectBad(a + " " + a + " --pixel-threshold -1", "--pixel-threshold: -1 is outside");
  expectBad(a + " " + a + " --max ''", "--max");
  expectBad(a + " " + a + " --layer ''", "--layer");
  writePng(path("small.png"), picture(32, 40, 1, 0.0f));
  expectBad(a + " " + path("small.png"), "same size");
}

// An engine's capture often carries alpha where the harness's frames may not: the colour is
// compared, in either order, and alpha is not.
TEST_F(CompareCli, AnRgbAndAnRgbaFileCompareOnTheirColour) {
  const Image rgb = picture(64, 40, 1, 0.0f);  // a.png's
  Image rgba(rgb.width, rgb.height, 4, 0.5f);
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x)
      for (int c = 0; c < 3; ++c) rgba.at(x, y, c) = rgb.at(x, y, c);
  writePng(path("a_rgba.png"), rgba);
  for (const std::string& pair : {path("a.png") + " " + path("a_rgba.png"),
                                 path("a_rgba.png") + " " + path("a.png")}) {
    const auto r = compare(pair + " --max max_abs=0,flip_mean=0");
    EXPECT_EQ(r.exitCode, 0) << pair << "\n" << r.output;
  }
}

TEST_F(CompareCli, FilesAreToldApartByContentAndExrChannelsByName) {
  const fs::path corpus = fs::path(TAA_SOURCE_DIR) / "tests/fuzz/corpus/image";
  const std::string bgr = (corpus / "exr_bgr.exr").string();
  // R 0.75, G 0.5, B 0.25 written by OpenEXR in its own channel order equals the hand-made
  // file stored B, G, R; an EXR named .png is still an EXR.
  Image rgb(4, 4, 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      rgb.at(x, y, 0) = 0.75f;
      rgb.at(x, y, 1) = 0.5f;
      rgb.at(x, y, 2) = 0.25f;
    }
  writeExr(path("rgb.exr"), rgb);
  for (const char* other : {"exr_bgr.exr", "exr_named_as.png"}) {
    const auto r = compare(path("rgb.exr") + " " + (corpus / other).string() +
                           " --metrics max_abs --max max_abs=0");
    EXPECT_EQ(r.exitCode, 0) << other << "\n" << r.output;
  }
  auto refused = [&](const std::string& args, const std::string& says) {
    const auto r = compare(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << args << "\n" << r.output;
  };
  refused(bgr + " " + (corpus / "exr_layered.exr").string(), "choose a layer (diffuse)");
  refused(bgr + " " + (corpus / "exr_xyz.exr").string(), "has no R channel");
  refused(bgr + " " + bgr + " --layer diffuse", "has no diffuse.R channel");
  const std::string layered = (corpus / "exr_layered.exr").string();
  const auto same = compare(layered + " " + layered + " --layer diffuse --max max_abs=0");
  EXPECT_EQ(same.exitCode, 0) << same.output;
}

}  // namespace
}  // namespace taa
