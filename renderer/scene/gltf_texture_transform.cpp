// KHR_texture_transform on a material's texture. The loader bakes the affine transform
// into the primitive's UV set the texture samples (Converter::textureRef): rasterisation,
// the reference and the adaptive tracer (and its ray differentials) then all see the
// transformed coordinates with no per-draw state.
#include <cmath>

#include "scene/gltf_convert.h"
#include "scene/scene_error.h"

namespace taa::scene {

namespace {

bool number(const tinygltf::Value& v) {
  return v.IsNumber() || v.IsInt() || v.IsReal();
}

// A numeric array member of `ext` with `n` entries, or `fallback` when absent.
std::vector<float> numbers(const std::filesystem::path& file, const tinygltf::Value& ext,
                           const char* key, size_t n, std::vector<float> fallback,
                           const std::string& what) {
  if (!ext.Has(key)) return fallback;
  const tinygltf::Value& v = ext.Get(key);
  std::vector<float> out;
  if (v.IsArray() && v.ArrayLen() == n)
    for (size_t i = 0; i < n; ++i)
      if (number(v.Get(int(i)))) out.push_back(float(v.Get(int(i)).GetNumberAsDouble()));
  if (n == 1 && number(v)) out.push_back(float(v.GetNumberAsDouble()));
  if (out.size() != n)
    throw SceneError(file,
                     what + ".extensions.KHR_texture_transform." + key + " must be " +
                         (n == 1 ? "a number" : "an array of " + std::to_string(n) + " numbers"));
  return out;
}

}  // namespace

GltfTextureTransform gltfTextureTransform(const std::filesystem::path& file,
                                          const tinygltf::ExtensionMap& extensions,
                                          const std::string& what) {
  GltfTextureTransform out;
  const auto it = extensions.find("KHR_texture_transform");
  if (it == extensions.end()) return out;
  const tinygltf::Value& ext = it->second;
  if (ext.Has("texCoord")) {
    if (!ext.Get("texCoord").IsInt())
      throw SceneError(file, what + ".extensions.KHR_texture_transform.texCoord must be an integer");
    out.texCoord = ext.Get("texCoord").GetNumberAsInt();
  }
  const std::vector<float> offset = numbers(file, ext, "offset", 2, {0.0f, 0.0f}, what);
  const float rotation = numbers(file, ext, "rotation", 1, {0.0f}, what)[0];
  const std::vector<float> scale = numbers(file, ext, "scale", 2, {1.0f, 1.0f}, what);
  // translation * rotation * scale. The rotation is u' = c u + s v, v' = -s u + c v: the
  // extension's example (offset [0, 1], rotation pi/2, scale 0.5) then samples the lower
  // left quadrant as it says (column-major, as glm stores it).
  const float c = std::cos(rotation), s = std::sin(rotation);
  const glm::mat3 t(1, 0, 0, 0, 1, 0, offset[0], offset[1], 1);
  const glm::mat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
  const glm::mat3 sc(scale[0], 0, 0, 0, scale[1], 0, 0, 0, 1);
  out.uv = t * r * sc;
  return out;
}

}  // namespace taa::scene
