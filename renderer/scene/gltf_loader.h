// glTF 2.0 import (.gltf and .glb) through tinygltf. Only files inside the glTF's
// own folder are read: buffers and images with an external URI, an absolute path or
// a path leaving the folder are refused before tinygltf touches them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene/scene.h"

namespace taa::scene {

// Appends the meshes, materials and textures of the glTF's default scene to `scene`
// and returns its node hierarchy and animations as a Model (not added to
// scene.models). Nodes are flattened depth-first so parents precede children;
// matrices become TRS; missing normals become flat normals (as the glTF spec asks);
// texture mips are generated on the CPU. Throws SceneError naming the file, the
// problem and the fix.
Model loadGltf(const std::filesystem::path& file, Scene& scene);

// The JSON chunk of a .glb container. Throws SceneError when the container is malformed.
std::string glbJsonChunk(const std::filesystem::path& file, const std::vector<uint8_t>& bytes);

// Throws SceneError when a buffers[].uri or images[].uri of the glTF JSON is not a
// data: URI or a relative path staying inside the file's folder (after percent-decoding,
// as tinygltf decodes it). The message names `file`, the key and the uri.
void checkGltfUris(const std::filesystem::path& file, const nlohmann::json& doc);

// The files a glTF document's buffers[].uri and images[].uri name, relative to its folder
// (percent-decoded, as loading opens them), in document order: not data: URIs, nor the uris
// checkGltfUris refuses (loading reports those).
std::vector<std::string> gltfFileUris(const nlohmann::json& doc);

// The extensions loadGltf implements (extensionsRequired may list only these).
const std::vector<std::string>& supportedGltfExtensions();

// Throws SceneError naming `file`, the extension and the fix when extensionsRequired
// lists one that is not supported. Returns a one-line note naming the extensions that
// extensionsUsed lists but the loader ignores ("" when there are none).
std::string checkGltfExtensions(const std::filesystem::path& file, const nlohmann::json& doc);

}  // namespace taa::scene
