#include "api/scene_loading.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/input_file.h"
#include "core/json_guard.h"
#include "scene/build_scene.h"
#include "scene/gltf_loader.h"
#include "scene/scene_error.h"

namespace taa {

std::shared_ptr<const scene::Scene> buildCaseScene(const spec::CaseSpec& spec) {
  return std::make_shared<const scene::Scene>(scene::buildScene(spec));
}

namespace {

// The JSON of a .gltf or .glb file's bytes, nesting bounded before the parse as loading bounds
// it; discarded when the bytes are not such a document.
nlohmann::json gltfDocument(const std::filesystem::path& file, const std::string& bytes) {
  const nlohmann::json none = nlohmann::json::value_t::discarded;
  std::string json = bytes;
  if (bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0) {
    try {
      json = scene::glbJsonChunk(file, std::vector<uint8_t>(bytes.begin(), bytes.end()));
    } catch (const scene::SceneError&) {
      return none;
    }
  }
  if (!jsonStructureProblem(json).empty()) return none;
  nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
  return doc.is_object() ? doc : none;
}

}  // namespace

bool gltfAnimates(const std::filesystem::path& file) {
  std::string bytes;
  try {
    bytes = readInputFile(file, kMaxSceneFileBytes);
  } catch (const InputFileError&) {
    return false;
  }
  const nlohmann::json doc = gltfDocument(file, bytes);
  if (doc.is_discarded()) return false;
  const auto a = doc.find("animations");
  return a != doc.end() && a->is_array() && !a->empty();
}

std::vector<std::string> gltfReferencedFiles(const std::filesystem::path& file,
                                             const std::string& bytes) {
  const nlohmann::json doc = gltfDocument(file, bytes);
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
