// `taa-harness render`: the frames a case writes, and with --reference the supersampled ground
// truth beside each of them (EXR in float and a PNG view), opaque and the frame's size.
#include "harness/cli_fixture.h"

#include "core/image_io.h"

namespace taa::render_cli_test {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;
using test::kSmallCase;

TEST_F(HarnessCli, RenderWritesTheReferenceBesideEachFrameOnlyWhenAsked) {
  writeCase("small", kSmallCase);
  const fs::path plain = root_ / "plain", withRef = root_ / "with_reference";
  auto r = harness("render " + casePath("small") + " --out " + plain.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  r = harness("render " + casePath("small") + " --out " + withRef.string() + " --reference");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int frames = 0;
  for (const auto& e : fs::directory_iterator(plain / "small")) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find("reference"), std::string::npos) << name;
    if (e.path().extension() != ".exr" || name.find('.') != name.rfind('.')) continue;
    ++frames;  // frame_NNNN.exr
    const std::string stem = e.path().stem().string();
    ASSERT_TRUE(fs::is_regular_file(withRef / "small" / (stem + ".reference.exr"))) << stem;
    const Image frame = readImage(withRef / "small" / (stem + ".exr"));
    const Image reference = readImage(withRef / "small" / (stem + ".reference.exr"));
    EXPECT_TRUE(fs::is_regular_file(withRef / "small" / (stem + ".reference.png"))) << stem;
    ASSERT_TRUE(reference.sameShape(frame)) << stem;
    int transparent = 0;
    for (int y = 0; y < reference.height; ++y)
      for (int x = 0; x < reference.width; ++x) transparent += reference.at(x, y, 3) != 1.0f;
    EXPECT_EQ(transparent, 0) << stem;
  }
  EXPECT_EQ(frames, 2);  // the case's two output frames
}

// `render --validate` fails (exit 1) when the validation layer spoke, counting its messages. The
// renderer gives none, so the layer's best-practices checks (lavapipe's small allocations) speak.
TEST_F(HarnessCli, RenderValidateFailsWhenTheLayerReportsAMessage) {
  const std::string render = "render " + casePath("small") + " --validate --out ";
  auto r = harness(render + (root_ / "quiet").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("validation message(s)"), std::string::npos) << r.output;
  r = harness(render + (root_ / "loud").string(),
              "VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("small: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" validation message(s)\n"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace taa::render_cli_test
