// An in-memory run with a passing, a failing, a golden-less and an erroring case, plus the small
// PNGs it references, for the report and JUnit tests.
#pragma once

#include <filesystem>
#include <limits>
#include <string>

#include "compare/heatmap.h"
#include "core/image_io.h"
#include "run/results.h"

namespace taa::test {

inline std::filesystem::path freshDir(const std::string& name) {
  const auto dir = std::filesystem::path(TAA_TEST_OUT) / "report" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "img");
  return dir;
}

// A 48x32 display image: a gradient with a checkerboard, so pixel zoom shows hard edges.
inline Image testPicture(float shift) {
  Image img(48, 32, 3);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float check = ((x / 4 + y / 4) % 2) ? 0.15f : 0.0f;
      img.at(x, y, 0) = float(x) / 47.0f * 0.8f + check;
      img.at(x, y, 1) = float(y) / 31.0f * 0.7f + check;
      img.at(x, y, 2) = 0.3f + check + shift;
    }
  return img;
}

// Writes golden/actual/diff and the worst-region crops of one frame under dir/img and returns
// their paths relative to dir.
inline run::FrameImages writeFrameImages(const std::filesystem::path& dir, const std::string& stem,
                                         bool differ) {
  const Image golden = testPicture(0.0f);
  Image actual = golden;
  if (differ)
    for (int y = 20; y < 27; ++y)
      for (int x = 30; x < 37; ++x) actual.at(x, y, 0) = 1.0f, actual.at(x, y, 1) = 0.1f;
  Image error(golden.width, golden.height, 1);
  for (int y = 0; y < golden.height; ++y)
    for (int x = 0; x < golden.width; ++x)
      for (int c = 0; c < 3; ++c)
        error.at(x, y) =
            std::max(error.at(x, y), std::abs(golden.at(x, y, c) - actual.at(x, y, c)));
  const Image diff = compare::heatmap(error, 0.5f);
  const compare::Region r = compare::worstRegion(error, 12, 8);
  run::FrameImages im;
  auto put = [&](const std::string& suffix, const Image& img) {
    const std::string rel = "img/" + stem + "_" + suffix + ".png";
    writePngLinear8(dir / rel, img);
    return rel;
  };
  im.golden = put("golden", golden);
  im.actual = put("actual", actual);
  im.diff = put("diff", diff);
  auto zoom = [&](const Image& img) {
    return compare::upscaleNearest(compare::crop(img, r.x, r.y, r.width, r.height), 8);
  };
  im.zoomGolden = put("zoom_golden", zoom(golden));
  im.zoomActual = put("zoom_actual", zoom(actual));
  im.zoomDiff = put("zoom_diff", zoom(diff));
  im.zoomX = r.x, im.zoomY = r.y, im.zoomW = r.width, im.zoomH = r.height;
  return im;
}

inline run::RunResults sampleRun(const std::filesystem::path& dir) {
  const double inf = std::numeric_limits<double>::infinity();
  run::RunResults r;
  r.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
  r.fingerprint = "mesa-23.2.1/lavapipe/x86_64/avx2";

  run::CaseResult pass;
  pass.name = "static_sponza";
  pass.file = "cases/static_sponza.json";
  pass.description = "Static camera; history should converge.";
  pass.status = run::CaseStatus::Pass;
  pass.fingerprint = r.fingerprint;
  pass.goldenFingerprint = r.fingerprint;
  run::FrameComparison exact;
  exact.frame = 15;
  exact.status = run::FrameStatus::Exact;
  exact.actualSha256 = exact.goldenSha256 = std::string(64, 'a');
  exact.metrics = {0.0, 0.0, inf, 0.0, 0.0, 0.0};
  exact.images = writeFrameImages(dir, "static_15", false);
  pass.frames = {exact};
  pass.invariants = {{"convergence",
                      true,
                      "rmse to reference 0.004 <= 0.01",
                      {{"rmse_last", 0.004}, {"bound", 0.01}}}};
  for (int i = 0; i < 16; ++i) {
    pass.referenceRmse.push_back(0.08 / (1.0 + i));
    pass.frameMs.push_back(4.0 + 0.25 * (i % 3));
  }
  pass.timings = {{"gbuffer", 1.25, 1.5}, {"taa_resolve", 0.5, 0.625}};
  pass.log = {"pass gbuffer 64x48", "buffer history_color rgba16f 64x48"};
  pass.seconds = 1.5;

  run::CaseResult fail;
  fail.name = "moving_fence";
  fail.file = "cases/moving_fence.json";
  fail.description = "Thin geometry <script>alert(1)</script> & ghosting";
  fail.status = run::CaseStatus::Fail;
  fail.message = "2 frames differ from the golden\nsee the report";
  fail.blessCommand = "taa-harness bless cases/moving_fence.json";
  fail.fingerprint = r.fingerprint;
  fail.goldenFingerprint = "mesa-23.0.0/lavapipe/x86_64/avx2";
  run::FrameComparison tol;
  tol.frame = 4;
  tol.status = run::FrameStatus::WithinTolerance;
  tol.toleranceMode = true;
  tol.metrics = {0.002, 0.0004, 67.9, 0.0, 0.001, 0.004};
  tol.images = writeFrameImages(dir, "fence_4", false);
  tol.images.zoomDiff = "img/deleted_zoom.png";  // never written: must show a placeholder
  run::FrameComparison bad;
  bad.frame = 8;
  bad.status = run::FrameStatus::Failed;
  bad.toleranceMode = true;
  bad.metrics = {0.9, 0.021, 33.5, 0.02, 0.08, std::numeric_limits<double>::quiet_NaN()};
  bad.failures = {"rmse 0.021 > 0.01", "flip_mean 0.08 > 0.05", "flip_p99 nan > 0.2"};
  bad.images = writeFrameImages(dir, "fence_8", true);
  fail.frames = {tol, bad};
  fail.invariants = {{"no_nan", true, "no NaN or Inf in 12 frames", {}},
                     {"ghosting_decay",
                      false,
                      "residual 0.12 > 0.05 after 8 frames at (31, 22)",
                      {{"residual", 0.12}, {"bound", 0.05}, {"frames", 8}}}};
  for (int i = 0; i < 12; ++i) {
    fail.referenceRmse.push_back(i == 3 ? std::numeric_limits<double>::quiet_NaN()
                                        : 0.01 + 0.002 * i);
    fail.frameMs.push_back(5.0 + i * 0.1);
  }
  fail.timings = {{"gbuffer", 1.5, 2.0}};
  fail.seconds = 2.25;

  run::CaseResult fresh;
  fresh.name = "new_case";
  fresh.file = "cases/new_case.json";
  fresh.status = run::CaseStatus::NoGolden;
  fresh.message = "no golden yet";
  fresh.blessCommand = "taa-harness bless cases/new_case.json";
  run::FrameComparison missing;
  missing.frame = 0;
  missing.status = run::FrameStatus::MissingGolden;
  missing.images.actual = writeFrameImages(dir, "new_0", false).actual;
  fresh.frames = {missing};

  run::CaseResult error;
  error.name = "broken_gltf";
  error.file = "cases/broken_gltf.json";
  error.status = run::CaseStatus::Error;
  error.message = "scene: accessor 3 reads past the end of buffer 0 \"<bin>\"";

  r.cases = {pass, fail, fresh, error};
  return r;
}

}  // namespace taa::test
