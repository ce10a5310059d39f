// Internal to the glTF loader: turns a parsed tinygltf::Model into scene data.
#pragma once

#include <tiny_gltf.h>

#include <filesystem>
#include <string>

#include "scene/scene.h"

namespace taa::scene {

// `warnings` are tinygltf's, quoted when an image it could not read is needed.
Model convertGltf(const std::filesystem::path& file, const tinygltf::Model& gltf,
                  const std::string& warnings, Scene& scene);

// Splits a node matrix (column-major, no shear as glTF requires) into TRS. A negative
// determinant becomes a negative x scale.
void decomposeTrs(const glm::mat4& m, glm::vec3& t, glm::quat& r, glm::vec3& s);

}  // namespace taa::scene
