// new-case frames what the case will show: a skinned figure by its posed vertices over its
// animation, not by its bind-pose mesh. skinned_quad.gltf's right edge rises 8 units in 10 s
// (at rest the quad is 1 x 1: a camera for the rest pose loses it); gltfpack's quantised copy
// keeps its dequantisation in the inverse bind matrices (its raw bind-pose bounds are 16383
// units wide: a camera for those sees a speck). Before issue 25 both failed below.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "case/case_loader.h"
#include "harness/cli_fixture.h"
#include "scene/build_scene.h"
#include "script/frame_state.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

class HarnessNewCase : public test::HarnessCli {};

// The figure's projected extent over the case's frames: whether every vertex stayed inside
// the image and in front of the camera, and the largest share of the image height it filled.
struct Framing {
  bool inside = true;
  double tallest = 0.0;
};

Framing framing(const std::filesystem::path& caseFile) {
  const spec::CaseSpec spec = cases::loadCase(caseFile).spec;
  const scene::Scene scene = scene::buildScene(spec);
  Framing out;
  for (int f = 0; f < spec.script.frames; f += 10) {
    const auto s = script::frameState(spec, f);
    double lo = 1e30, hi = -1e30;
    for (const scene::MeshDraw& d : scene::poseModel(scene, 0, s.worldAnimTime))
      for (const scene::Vertex& v : scene::deformVertices(scene, d)) {
        const glm::vec4 c = s.camera.viewProjection * d.transform * glm::vec4(v.position, 1.0f);
        const glm::vec3 ndc = glm::vec3(c) / c.w;
        out.inside &= c.w > 0.0f && std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f;
        lo = std::min(lo, double(ndc.y));
        hi = std::max(hi, double(ndc.y));
      }
    out.tallest = std::max(out.tallest, (hi - lo) / 2.0);
  }
  return out;
}

TEST_F(HarnessNewCase, SkinnedFiguresStayInViewThroughTheirAnimation) {
  fs::create_directories(root_ / "cases/scenes");
  for (const char* asset : {"skinned_quad.gltf", "skinned_quad_gltfpack.glb"}) {
    SCOPED_TRACE(asset);
    fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases/scenes" / asset, root_ / "cases/scenes" / asset,
                  fs::copy_options::overwrite_existing);
    const std::string name = std::string(asset).substr(0, std::string(asset).find('.'));
    const auto r = harness("new-case --scene " + (root_ / "cases/scenes" / asset).string() +
                           " --name " + name + " --frames 301");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Framing f = framing(casePath(name));
    EXPECT_TRUE(f.inside) << "every posed vertex of every frame is in view";
    EXPECT_GT(f.tallest, 0.3) << "and the figure fills a fair share of the frame";
    std::ifstream in(casePath(name));
    const auto j = nlohmann::json::parse(in);
    const auto& p = j["camera"]["position"];
    EXPECT_LT(std::hypot(p[0].get<double>(), p[1].get<double>(), p[2].get<double>()), 50.0)
        << "not kilometres away";
  }
}

TEST_F(HarnessNewCase, BadFrameCountsAreUsageErrors) {
  fs::create_directories(root_ / "cases/scenes");
  fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases/scenes/skinned_quad.gltf",
                root_ / "cases/scenes/skinned_quad.gltf");
  for (const char* frames : {"0", "ten", "12x"}) {
    const auto r = harness("new-case --scene " + (root_ / "cases/scenes/skinned_quad.gltf").string() +
                           " --name q --frames " + frames);
    EXPECT_EQ(r.exitCode, 2) << frames << ": " << r.output;
    // The option and the value given: a number out of range, or text that is none.
    const std::string says = std::string(frames) == "0" ? "--frames: 0 is outside [1, "
                                                        : "--frames: '" + std::string(frames) + "' is not a number";
    EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
  }
}

// A name becomes a file name: 5,000 characters (over the file system's limit, once exit 3) or a
// control character (once written into the name) are usage errors, and nothing is written.
TEST_F(HarnessNewCase, NamesAreShortAndPrintable) {
  fs::create_directories(root_ / "cases/scenes");
  fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases/scenes/skinned_quad.gltf",
                root_ / "cases/scenes/skinned_quad.gltf");
  for (const std::string& name :
       {std::string(5000, 'a'), std::string("'a\tb'"), std::string("$'a\\001b'")}) {
    const auto r = harness("new-case --scene " +
                           (root_ / "cases/scenes/skinned_quad.gltf").string() + " --name " + name);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("use 1 to 100 letters, digits"), std::string::npos) << r.output;
  }
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(root_ / "cases")) files += e.is_regular_file();
  EXPECT_EQ(files, 1u) << "only the case the fixture wrote";
  // The limit is the longest name taken: 100 characters make a case, 101 do not.
  const auto at = harness("new-case --scene " + (root_ / "cases/scenes/skinned_quad.gltf").string() +
                          " --name " + std::string(100, 'b'));
  EXPECT_EQ(at.exitCode, 0) << at.output;
  EXPECT_TRUE(fs::is_regular_file(root_ / "cases" / (std::string(100, 'b') + ".json")));
  const auto over = harness("new-case --scene " + (root_ / "cases/scenes/skinned_quad.gltf").string() +
                            " --name " + std::string(101, 'c'));
  EXPECT_EQ(over.exitCode, 2) << over.output;
}

}  // namespace
}  // namespace taa
