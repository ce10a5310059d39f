// `taa-harness render`: the frames a case writes, and with --reference the supersampled ground
// truth beside each of them (EXR in float and a PNG view), opaque and the frame's size.
#include "harness/cli_fixture.h"

#include <nlohmann/json.hpp>

#include "core/image_io.h"
#include "support/text.h"
#include "vk/driver_manifests.h"

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

// A manifest that names lavapipe's library but gives no driver (a broken install, another
// architecture's) must not cost a user their device: the harness, which loads lavapipe's
// manifests alone (vk/driver_manifests.h), then takes every driver the loader finds, here a
// manifest naming lavapipe under another file name.
TEST_F(HarnessCli, ALavapipeManifestThatGivesNoDeviceFallsBackToEveryDriver) {
  const std::string system = vk::lavapipeOnlyDriverFiles(std::getenv);
  if (system.empty()) GTEST_SKIP() << "drivers chosen in the environment, or no lavapipe manifest";
  const auto manifest = nlohmann::json::parse(test::readFile(system.substr(0, system.find(':'))));
  const fs::path library = manifest["ICD"]["library_path"].get<std::string>();
  if (!library.is_absolute()) GTEST_SKIP() << "lavapipe's manifest names no folder: " << library;
  const fs::path config = root_ / "config" / "vulkan" / "icd.d", data = root_ / "data" / "vulkan" / "icd.d";
  fs::create_directories(config);
  fs::create_directories(data);
  fs::create_directories(root_ / "lib");
  fs::create_symlink(library, root_ / "lib" / "libcpu_renamed.so");
  std::ofstream(config / "lvp_icd.json") << R"({"file_format_version": "1.0.0", "ICD":
    {"library_path": "/nonexistent/libvulkan_lvp.so", "api_version": "1.3.0"}})";
  nlohmann::json renamed = manifest;
  renamed["ICD"]["library_path"] = (root_ / "lib" / "libcpu_renamed.so").string();
  std::ofstream(data / "cpu_icd.json") << renamed.dump();
  const std::string env = "XDG_CONFIG_HOME=" + (root_ / "config").string() +
                          " XDG_CONFIG_DIRS=/nonexistent XDG_DATA_HOME=/nonexistent XDG_DATA_DIRS=" +
                          (root_ / "data").string();
  const auto r = harness("render " + casePath("small") + " --out " + (root_ / "out").string(), env);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("llvmpipe"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace taa::render_cli_test
