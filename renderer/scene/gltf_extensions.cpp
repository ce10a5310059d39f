// The glTF extension check, run on the JSON before tinygltf parses buffers and images:
// a compressed mesh or a KTX2 texture would otherwise fail deep inside tinygltf with a
// message that does not name the extension.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene_error.h"

namespace taa::scene {
namespace {

// What to do about an extension this loader does not implement.
std::string advice(const std::string& ext) {
  if (ext == "KHR_texture_basisu" || ext == "EXT_texture_webp" || ext == "MSFT_texture_dds")
    return "re-export with PNG or JPEG textures (no Debian package decodes these textures here)";
  if (ext == "KHR_materials_pbrSpecularGlossiness")
    return "convert the materials to metallic-roughness (glTF-Transform's metalrough command) "
           "and re-export";
  return "re-export the file without it";
}

std::vector<std::string> names(const nlohmann::json& doc, const char* key) {
  std::vector<std::string> out;
  const auto list = doc.find(key);
  if (list == doc.end() || !list->is_array()) return out;
  for (const auto& e : *list)
    if (e.is_string()) out.push_back(e.get<std::string>());
  return out;
}

}  // namespace

const std::vector<std::string>& supportedGltfExtensions() {
  // KHR_mesh_quantization needs nothing beyond the accessor reader's integer formats.
  static const std::vector<std::string> list = {
      "EXT_mesh_gpu_instancing",         "EXT_meshopt_compression",
      "KHR_draco_mesh_compression",      "KHR_materials_emissive_strength",
      "KHR_materials_unlit",             "KHR_mesh_quantization",
      "KHR_texture_transform"};
  return list;
}

std::string checkGltfExtensions(const std::filesystem::path& file, const nlohmann::json& doc) {
  const auto& supported = supportedGltfExtensions();
  auto isSupported = [&](const std::string& e) {
    return std::find(supported.begin(), supported.end(), e) != supported.end();
  };
  for (const std::string& e : names(doc, "extensionsRequired"))
    if (!isSupported(e))
      throw SceneError(file, "extensionsRequired lists " + e +
                                 ", which this renderer does not support; " + advice(e));
  std::string unused;
  for (const std::string& e : names(doc, "extensionsUsed"))
    if (!isSupported(e) && unused.find(e) == std::string::npos)
      unused += (unused.empty() ? "" : ", ") + e;
  if (unused.empty()) return "";
  return file.string() + ": extensionsUsed lists " + unused +
         ", not supported here and not required by the file; rendered without " +
         (unused.find(',') == std::string::npos ? "it" : "them");
}

}  // namespace taa::scene
