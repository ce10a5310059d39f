#include "api/scene_loading.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/json_guard.h"
#include "scene/build_scene.h"
#include "scene/gltf_loader.h"
#include "scene/scene_error.h"

namespace taa {

std::shared_ptr<const scene::Scene> buildCaseScene(const spec::CaseSpec& spec) {
  return std::make_shared<const scene::Scene>(scene::buildScene(spec));
}

bool gltfAnimates(const std::filesystem::path& file) {
  return scene::gltfHasAnimations(file);
}

std::vector<std::string> gltfReferencedFiles(const std::filesystem::path& file,
                                             const std::string& bytes) {
  std::string json = bytes;
  if (bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0) {
    try {
      json = scene::glbJsonChunk(file, std::vector<uint8_t>(bytes.begin(), bytes.end()));
    } catch (const scene::SceneError&) {
      return {};
    }
  }
  // Bounded nesting before the parse, as loading checks it.
  if (!jsonStructureProblem(json).empty()) return {};
  const nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
  if (doc.is_discarded()) return {};
  return scene::gltfFileUris(doc);
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
