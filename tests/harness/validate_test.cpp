// validate loads everything a case references, as render does before it needs a device, and
// reports every file it is given. Before issue 25 it read the case file alone: it said ok for
// scenes render refused, and stopped at the first bad file.
#include "harness/cli_fixture.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

class HarnessValidate : public test::HarnessCli {
 protected:
  // A case whose world is cases/scenes/NAME (copied from the repository's cases/scenes).
  void sceneCase(const std::string& caseName, const std::string& scene) {
    fs::create_directories((root_ / "cases/scenes" / scene).parent_path());
    fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases/scenes" / scene, root_ / "cases/scenes" / scene,
                  fs::copy_options::overwrite_existing);
    writeCase(caseName, R"({"scene": {"gltf": "scenes/)" + scene +
                            R"("}, "render": {"width": 32, "height": 18}, "script": {"frames": 1}})");
  }
};

TEST_F(HarnessValidate, RefusesEveryScene) {
  // Each file of cases/scenes/refused/ is one defect render refuses (exit 2, naming it).
  int checked = 0;
  for (const auto& e : fs::directory_iterator(fs::path(TAA_SOURCE_DIR) / "cases/scenes/refused")) {
    const std::string scene = "refused/" + e.path().filename().string();
    SCOPED_TRACE(scene);
    sceneCase("bad", scene);
    const auto v = harness("validate " + casePath("bad"));
    const auto r = harness("render " + casePath("bad") + " --out " + (root_ / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(v.exitCode, 2) << v.output;
    EXPECT_NE(v.output.find(e.path().filename().string()), std::string::npos) << v.output;
    EXPECT_EQ(v.output.find(": ok"), std::string::npos) << v.output;
    ++checked;
  }
  EXPECT_GE(checked, 9);
}

TEST_F(HarnessValidate, ReportsEveryFileAndTheCount) {
  sceneCase("good", "sparse.gltf");
  sceneCase("basisu", "refused/requires_basisu.gltf");
  writeCase("typo", R"({"taa": {"alpah": 0.2}})");
  const auto r = harness("validate " + casePath("basisu") + " " + casePath("good") + " " +
                         casePath("typo"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("good.json: ok"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("KHR_texture_basisu"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("typo.json: taa.alpah: unknown key"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2 of 3 case files have problems"), std::string::npos) << r.output;
  // The count is for several files with problems: one file's error is its own summary, and
  // files that are all fine print only their "ok".
  const auto good = harness("validate " + casePath("good") + " " + casePath("good"));
  EXPECT_EQ(good.exitCode, 0) << good.output;
  EXPECT_EQ(good.output.find("have problems"), std::string::npos) << good.output;
  const auto one = harness("validate " + casePath("typo"));
  EXPECT_EQ(one.exitCode, 2) << one.output;
  EXPECT_EQ(one.output.find("have problems"), std::string::npos) << one.output;
}

TEST_F(HarnessValidate, LoadsTheTracksAndMoversTooAsRenderDoes) {
  // A mover's glTF that is missing, and a camera track that is not there: both refused.
  writeCase("mover", R"({"movers": [{"shape": "gltf", "gltf": "scenes/absent.gltf"}],
                         "script": {"frames": 1}})");
  writeCase("track", R"({"camera": {"track": "tracks/absent.json"}, "script": {"frames": 1}})");
  for (const char* name : {"mover", "track"}) {
    const auto v = harness(std::string("validate ") + casePath(name));
    EXPECT_EQ(v.exitCode, 2) << name << ": " << v.output;
    EXPECT_NE(v.output.find("absent"), std::string::npos) << v.output;
  }
}

}  // namespace
}  // namespace taa
