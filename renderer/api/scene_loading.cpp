#include "api/scene_loading.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/build_scene.h"
#include "scene/gltf_loader.h"

namespace taa {

std::shared_ptr<const scene::Scene> buildCaseScene(const spec::CaseSpec& spec) {
  return std::make_shared<const scene::Scene>(scene::buildScene(spec));
}

bool gltfAnimates(const std::filesystem::path& file) { return scene::gltfHasAnimations(file); }

std::vector<std::string> gltfFiles(const std::filesystem::path& file) {
  return scene::gltfReferencedFiles(file);
}

SceneBounds gltfPosedBounds(const std::filesystem::path& file, int frames, int fps) {
  scene::Scene scene;
  scene.models.push_back(scene::loadGltf(file, scene));
  // Posed over one loop of the longest playing animation as well as every frame, so a skinned,
  // morphed or animated figure stays in view throughout, however many frames a user later
  // gives the case.
  double loop = 0.0;
  for (const int anim : scene::playingAnimations(scene.models[0]))
    loop = std::max(loop, double(scene.models[0].animations[size_t(anim)].duration));
  const int poses = std::min(600, std::max(frames, int(std::ceil(loop * fps)) + 1));
  std::vector<double> times;
  for (int i = 0; i < poses; ++i) times.push_back(double(i) / fps);
  SceneBounds bounds;
  scene::modelBounds(scene, 0, times, bounds.lo, bounds.hi);
  return bounds;
}

}  // namespace taa
