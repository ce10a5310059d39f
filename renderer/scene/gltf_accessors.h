// Internal to the glTF loader: typed reads of accessor data with the bounds checks a
// hostile or truncated file needs.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace taa::scene {

// Elements an accessor without a bufferView (all zeros) may declare: nothing in the file
// backs them, so without a bound 3 bytes of JSON could ask for gigabytes.
inline constexpr size_t kMaxUnbackedElements = size_t(1) << 24;

// Reads accessor `index` as floats, `components` per element (integer components are
// normalised when the accessor says so), sparse substitutions applied. Throws SceneError
// naming `file` and `what` when the accessor is missing, has another shape or overruns
// its buffer, or its sparse indices are not strictly increasing within its count.
std::vector<float> readGltfAccessor(const std::filesystem::path& file, const tinygltf::Model& model,
                                    int index, const std::string& what, int components);

// Reads an index accessor (unsigned byte, short or int).
std::vector<uint32_t> readGltfIndices(const std::filesystem::path& file,
                                      const tinygltf::Model& model, int index,
                                      const std::string& what);

}  // namespace taa::scene
