// KHR_draco_mesh_compression through Debian's libdraco. Debian's tinygltf is built
// without Draco, and it refuses a primitive whose indices accessor has no buffer view
// (a compressed file's usually have none), so before parsing those "indices" keys are
// taken out of the JSON and remembered; after parsing each compressed primitive is
// decoded into a new buffer, with new accessors in the types its accessors declare, and
// the primitive is pointed at them. Everything downstream sees plain geometry.
#include <draco/compression/decode.h>

#include <nlohmann/json.hpp>

#include "scene/gltf_convert.h"
#include "scene/scene_error.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

const char* const kDracoExt = "KHR_draco_mesh_compression";

// The primitive's extension object, or null.
const nlohmann::json* dracoExtensionOf(const nlohmann::json& prim) {
  const auto ext = prim.find("extensions");
  if (ext == prim.end() || !ext->is_object()) return nullptr;
  const auto d = ext->find(kDracoExt);
  return d != ext->end() && d->is_object() ? &*d : nullptr;
}

bool accessorHasView(const nlohmann::json& doc, size_t index) {
  const auto accessors = doc.find("accessors");
  return accessors != doc.end() && accessors->is_array() && index < accessors->size() &&
         (*accessors)[index].is_object() && (*accessors)[index].contains("bufferView");
}

int dracoInt(const fs::path& file, const tinygltf::Value& v, const std::string& what) {
  if (!v.IsInt() && !v.IsNumber())
    throw SceneError(file, what + " is not an integer; the file is corrupt");
  const double d = v.GetNumberAsDouble();
  if (!(d >= 0.0 && d < 2147483647.0) || d != double(int(d)))
    throw SceneError(file, what + " is not a valid index; the file is corrupt");
  return int(d);
}

// Appends count elements of the attribute, in point order, as `comps` components of
// type T. False when Draco cannot convert a value (out of the type's range).
template <typename T>
bool dracoWriteAttribute(const draco::PointAttribute& att, uint32_t points, int comps,
                         std::vector<unsigned char>& out) {
  std::vector<T> value(static_cast<size_t>(comps), T(0));
  for (uint32_t i = 0; i < points; ++i) {
    if (!att.ConvertValue<T>(att.mapped_index(draco::PointIndex(i)), int8_t(comps), value.data()))
      return false;
    const auto* bytes = reinterpret_cast<const unsigned char*>(value.data());
    out.insert(out.end(), bytes, bytes + sizeof(T) * size_t(comps));
  }
  return true;
}

bool dracoWriteAs(int componentType, const draco::PointAttribute& att, uint32_t points, int comps,
                  std::vector<unsigned char>& out) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return dracoWriteAttribute<float>(att, points, comps, out);
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return dracoWriteAttribute<int8_t>(att, points, comps, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return dracoWriteAttribute<uint8_t>(att, points, comps, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return dracoWriteAttribute<int16_t>(att, points, comps, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return dracoWriteAttribute<uint16_t>(att, points, comps, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return dracoWriteAttribute<uint32_t>(att, points, comps, out);
    default:
      return false;
  }
}

// Decoded data of one primitive goes into one new buffer; each array gets a view.
class DracoOutput {
 public:
  DracoOutput(tinygltf::Model& g) : g_(g), buffer_(int(g.buffers.size())) {
    g_.buffers.emplace_back();
  }
  std::vector<unsigned char>& data() { return g_.buffers[size_t(buffer_)].data; }
  void align() {
    while (data().size() % 4) data().push_back(0);
  }
  // A new accessor like `like` over the bytes written since `start`.
  int accessor(const tinygltf::Accessor& like, size_t start, size_t count) {
    tinygltf::BufferView v;
    v.buffer = buffer_;
    v.byteOffset = start;
    v.byteLength = data().size() - start;
    g_.bufferViews.push_back(v);
    tinygltf::Accessor a = like;
    a.bufferView = int(g_.bufferViews.size()) - 1;
    a.byteOffset = 0;
    a.count = count;
    a.sparse = {};
    g_.accessors.push_back(a);
    return int(g_.accessors.size()) - 1;
  }

 private:
  tinygltf::Model& g_;
  int buffer_;
};

std::unique_ptr<draco::Mesh> decodeDracoStream(const fs::path& file, const tinygltf::Model& g,
                                               int viewIndex, const std::string& what) {
  if (size_t(viewIndex) >= g.bufferViews.size())
    throw SceneError(file, what + ".bufferView " + std::to_string(viewIndex) +
                               " does not exist; the file is corrupt");
  const tinygltf::BufferView& view = g.bufferViews[size_t(viewIndex)];
  if (view.buffer < 0 || size_t(view.buffer) >= g.buffers.size() ||
      view.byteOffset > g.buffers[size_t(view.buffer)].data.size() ||
      view.byteLength > g.buffers[size_t(view.buffer)].data.size() - view.byteOffset)
    throw SceneError(file, what + ": bufferViews[" + std::to_string(viewIndex) +
                               "] lies outside its buffer; the file is truncated or corrupt");
  draco::DecoderBuffer buffer;
  buffer.Init(
      reinterpret_cast<const char*>(g.buffers[size_t(view.buffer)].data.data()) + view.byteOffset,
      view.byteLength);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
    throw SceneError(file, what + ": the Draco stream in bufferViews[" + std::to_string(viewIndex) +
                               "] does not decode (draco: " + decoded.status().error_msg_string() +
                               "); the file is truncated or corrupt, re-export it");
  std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  if (!mesh || mesh->num_faces() == 0)
    throw SceneError(file, what + ": the Draco stream in bufferViews[" + std::to_string(viewIndex) +
                               "] holds no triangles; re-export the mesh without Draco");
  return mesh;
}

void decodeDracoPrimitive(const fs::path& file, tinygltf::Model& g, tinygltf::Primitive& prim,
                          int indices, const std::string& where) {
  const std::string what = where + ".extensions." + kDracoExt;
  const tinygltf::Value& ext = prim.extensions.at(kDracoExt);
  if (prim.mode != TINYGLTF_MODE_TRIANGLES)
    throw SceneError(file, where + " is Draco-compressed with mode " + std::to_string(prim.mode) +
                               "; only triangle lists are supported, re-export with triangles");
  if (!prim.targets.empty())
    throw SceneError(file, where +
                               " has morph targets and Draco compression, which reorders its "
                               "vertices away from the targets'; re-export without Draco, or "
                               "with EXT_meshopt_compression");
  if (!ext.IsObject() || !ext.Has("bufferView") || !ext.Has("attributes") ||
      !ext.Get("attributes").IsObject())
    throw SceneError(file, what +
                               " needs a bufferView and an attributes object; the file is "
                               "corrupt");
  const std::unique_ptr<draco::Mesh> mesh =
      decodeDracoStream(file, g, dracoInt(file, ext.Get("bufferView"), what + ".bufferView"), what);
  const uint32_t points = mesh->num_points();
  const tinygltf::Value& attributes = ext.Get("attributes");
  DracoOutput out(g);
  for (const std::string& name : attributes.Keys()) {
    const std::string key = what + ".attributes." + name;
    // Exporters list attributes here that the primitive leaves out (glTF-Sample-Models'
    // Box/glTF-Draco has a TEXCOORD_0 only here); without an accessor the loader has no use for
    // them.
    const auto slot = prim.attributes.find(name);
    if (slot == prim.attributes.end()) continue;
    if (slot->second < 0 || size_t(slot->second) >= g.accessors.size())
      throw SceneError(file, where + ".attributes." + name + " refers to a missing accessor");
    const tinygltf::Accessor like = g.accessors[size_t(slot->second)];
    const draco::PointAttribute* att =
        mesh->GetAttributeByUniqueId(uint32_t(dracoInt(file, attributes.Get(name), key)));
    const int comps = tinygltf::GetNumComponentsInType(uint32_t(like.type));
    if (!att)
      throw SceneError(file, key +
                                 " names a Draco attribute the stream does not hold; the file "
                                 "is corrupt");
    if (comps <= 0 || att->num_components() != comps)
      throw SceneError(
          file, key + ": the Draco attribute has " + std::to_string(att->num_components()) +
                    " components, its accessor " + std::to_string(comps) + "; the file is corrupt");
    if (like.count != points)
      throw SceneError(file, key + ": the Draco stream holds " + std::to_string(points) +
                                 " vertices, accessors[" + std::to_string(slot->second) +
                                 "] declares " + std::to_string(like.count) +
                                 "; the file is corrupt");
    out.align();
    const size_t start = out.data().size();
    if (!dracoWriteAs(like.componentType, *att, points, comps, out.data()))
      throw SceneError(file, key + ": the decoded values do not fit accessors[" +
                                 std::to_string(slot->second) +
                                 "]'s component type; the file is corrupt");
    slot->second = out.accessor(like, start, points);
  }
  // Indices: Draco's faces, as 32-bit indices whatever the file declared.
  const size_t count = size_t(mesh->num_faces()) * 3;
  if (indices >= 0 && size_t(indices) < g.accessors.size() &&
      g.accessors[size_t(indices)].count != count)
    throw SceneError(file, what + ": the Draco stream holds " + std::to_string(count) +
                               " indices, accessors[" + std::to_string(indices) + "] declares " +
                               std::to_string(g.accessors[size_t(indices)].count) +
                               "; the file is corrupt");
  out.align();
  const size_t start = out.data().size();
  for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
    for (const draco::PointIndex& p : mesh->face(f)) {
      const uint32_t v = p.value();
      const auto* bytes = reinterpret_cast<const unsigned char*>(&v);
      out.data().insert(out.data().end(), bytes, bytes + 4);
    }
  tinygltf::Accessor like;
  like.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  like.type = TINYGLTF_TYPE_SCALAR;
  prim.indices = out.accessor(like, start, count);
}

}  // namespace

DracoIndices detachDracoIndices(nlohmann::json& doc, bool& changed) {
  DracoIndices found;
  const auto meshes = doc.find("meshes");
  if (meshes == doc.end() || !meshes->is_array()) return found;
  for (size_t m = 0; m < meshes->size(); ++m) {
    auto& mesh = (*meshes)[m];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
      continue;
    auto& prims = mesh["primitives"];
    for (size_t p = 0; p < prims.size(); ++p) {
      auto& prim = prims[p];
      if (!prim.is_object() || !dracoExtensionOf(prim)) continue;
      const auto idx = prim.find("indices");
      int index = -1;
      if (idx != prim.end() && idx->is_number_unsigned() && idx->get<uint64_t>() < (1u << 31))
        index = int(idx->get<uint64_t>());
      found[{int(m), int(p)}] = index;
      if (index >= 0 && !accessorHasView(doc, size_t(index))) {
        prim.erase("indices");
        changed = true;
      }
    }
  }
  return found;
}

void decodeDraco(const fs::path& file, tinygltf::Model& g, const DracoIndices& indices) {
  for (size_t m = 0; m < g.meshes.size(); ++m)
    for (size_t p = 0; p < g.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& prim = g.meshes[m].primitives[p];
      if (prim.extensions.find(kDracoExt) == prim.extensions.end()) continue;
      const auto it = indices.find({int(m), int(p)});
      const int index = it != indices.end() ? it->second : prim.indices;
      decodeDracoPrimitive(
          file, g, prim, index,
          "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]");
    }
}

}  // namespace taa::scene
