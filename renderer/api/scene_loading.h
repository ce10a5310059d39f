// A case's scene as the harness sees it: built once and handed to each Renderer of the case
// (api/renderer.h takes it by reference), never looked into. scene/scene.h's data and the
// glTF loader stay inside renderer/.
#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include "spec/case_spec.h"

namespace taa {

namespace scene {
struct Scene;
}

// The world plus one model per mover (scene::buildScene), shared by the renderers that replay
// the case. Throws SceneError (an InputError) naming the file, the problem and the fix.
std::shared_ptr<const scene::Scene> buildCaseScene(const spec::CaseSpec& spec);

// Whether the glTF file lists any animation, read as the case's input hash reads it (bounded,
// a regular file, gltfReferencedFiles' parse): false when it cannot be read, which loading the
// scene then reports. For spec-level checks that need to know whether a glTF scene moves
// without loading it.
bool gltfAnimates(const std::filesystem::path& file);

// The files the glTF `file`, whose bytes are `bytes` (.gltf or .glb), reads besides itself:
// its external buffers and images, relative to its folder (scene::gltfFileUris). Empty when
// the bytes are not a glTF document loading could read (loading then reports why). For the
// case's input hash: editing a .bin or a texture is editing the case.
std::vector<std::string> gltfReferencedFiles(const std::filesystem::path& file,
                                             const std::string& bytes);

struct SceneBounds {
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};
};

// The object-space bounds of the glTF file's scene posed at every one of `frames` frames at
// `fps` and over one loop of its longest playing animation, for framing a camera on it (at most
// 600 poses). Throws SceneError.
SceneBounds gltfPosedBounds(const std::filesystem::path& file, int frames, int fps);

}  // namespace taa
