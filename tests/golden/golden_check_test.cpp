// GoldenCheck fed by hand, frame by frame, as the runner feeds it: no device needed, so the
// sanitizer tree runs these too.
#include "run/golden_check.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/image_io.h"

namespace taa::run {
namespace {

namespace fs = std::filesystem;

// A case with no goldens compares nothing (and reads nothing of a golden set it lacks), yet
// hashes every frame for the results; outside CI it is a skip.
TEST(GoldenCheck, WithoutGoldensEveryFrameIsHashedAndNothingCompared) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "golden_check" / "no_goldens";
  fs::remove_all(dir);
  spec::CheckedCase spec;
  spec.name = "no_goldens";
  spec.file = dir / "cases" / "no_goldens.json";
  RunOptions options;
  options.outDir = dir / "out";
  options.goldensRoot = dir / "goldens";
  options.writeImages = false;
  const golden::Environment env{"device", "driver", "driver info", "1.3.0", "x86-64-v3"};
  GoldenCheck check(spec, env, options);
  std::vector<std::string> hashes;
  for (int f = 0; f < 3; ++f) {
    FrameRecord r;
    r.frame = f;
    r.color = Image(4, 4, 4, 0.25f * float(f));
    r.colorSha256 = pixelSha256(r.color);
    hashes.push_back(r.colorSha256);
    check.observe(r);
  }
  CaseResult result;
  EXPECT_EQ(check.finish({}, "case sha", result), CaseStatus::NoGolden);
  EXPECT_EQ(result.frameSha256, hashes);
  EXPECT_EQ(result.frameSignatures.size(), 3u);
  EXPECT_TRUE(result.frames.empty());
  EXPECT_NE(result.message.find("no goldens in"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace taa::run
