// EXT_meshopt_compression through Debian's libmeshoptimizer. A compressed file's buffer
// views point into a "fallback" buffer that often has no data (no uri) and so would stop
// tinygltf; before parsing, such buffers get an all-zero data URI of their length, and
// after parsing every compressed view is decoded into its place, so the accessor reader
// and everything after it see ordinary data.
#include <meshoptimizer.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "scene/gltf_convert.h"
#include "scene/scene_error.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

bool isFallback(const nlohmann::json& buffer) {
  const auto ext = buffer.find("extensions");
  if (ext == buffer.end() || !ext->is_object()) return false;
  const auto m = ext->find("EXT_meshopt_compression");
  return m != ext->end() && m->is_object() && m->value("fallback", false) == true;
}

// Base64 of `n` zero bytes.
std::string zeros(size_t n) {
  std::string out((n / 3) * 4, 'A');
  if (n % 3 == 1) out += "AA==";
  if (n % 3 == 2) out += "AAA=";
  return out;
}

size_t number(const fs::path& file, const tinygltf::Value& ext, const char* key,
              const std::string& what, bool required = true) {
  if (!ext.Has(key)) {
    if (required)
      throw SceneError(file, what + ".extensions.EXT_meshopt_compression." + key + " is missing");
    return 0;
  }
  const tinygltf::Value& v = ext.Get(key);
  if (!v.IsNumber() && !v.IsInt() && !v.IsReal())
    throw SceneError(file,
                     what + ".extensions.EXT_meshopt_compression." + key + " is not a number");
  const double d = v.GetNumberAsDouble();
  if (!(d >= 0.0 && d < 1e15))
    throw SceneError(file,
                     what + ".extensions.EXT_meshopt_compression." + key + " is out of range");
  return size_t(d);
}

std::string string(const tinygltf::Value& ext, const char* key, const char* fallback) {
  return ext.Has(key) && ext.Get(key).IsString() ? ext.Get(key).Get<std::string>() : fallback;
}

void putU32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
}

}  // namespace

std::vector<uint8_t> glbWithJson(const std::vector<uint8_t>& glb, std::string json) {
  // glbJsonChunk has checked the header and the first chunk's length.
  const size_t oldLength =
      size_t(glb[12]) | size_t(glb[13]) << 8 | size_t(glb[14]) << 16 | size_t(glb[15]) << 24;
  while (json.size() % 4) json += ' ';
  const size_t rest = glb.size() - 20 - oldLength;
  // Sized once and filled with memcpy: vector::insert here trips GCC 12's -Warray-bounds.
  std::vector<uint8_t> out(20 + json.size() + rest);
  std::memcpy(out.data(), glb.data(), 20);
  std::memcpy(out.data() + 20, json.data(), json.size());
  if (rest > 0) std::memcpy(out.data() + 20 + json.size(), glb.data() + 20 + oldLength, rest);
  putU32(out, 8, uint32_t(out.size()));
  putU32(out, 12, uint32_t(json.size()));
  return out;
}

bool fillMeshoptFallbacks(nlohmann::json& doc) {
  const auto buffers = doc.find("buffers");
  if (buffers == doc.end() || !buffers->is_array()) return false;
  bool changed = false;
  for (auto& b : *buffers) {
    if (!b.is_object() || b.contains("uri") || !isFallback(b)) continue;
    const auto length = b.find("byteLength");
    if (length == b.end() || !length->is_number_unsigned()) continue;  // tinygltf reports it
    b["uri"] = "data:application/octet-stream;base64," + zeros(length->get<size_t>());
    changed = true;
  }
  return changed;
}

void decodeMeshopt(const fs::path& file, tinygltf::Model& g) {
  for (size_t i = 0; i < g.bufferViews.size(); ++i) {
    tinygltf::BufferView& view = g.bufferViews[i];
    const auto it = view.extensions.find("EXT_meshopt_compression");
    if (it == view.extensions.end()) continue;
    const std::string what = "bufferViews[" + std::to_string(i) + "]";
    const tinygltf::Value& ext = it->second;
    const size_t source = number(file, ext, "buffer", what);
    const size_t offset = number(file, ext, "byteOffset", what, false);
    const size_t length = number(file, ext, "byteLength", what);
    const size_t stride = number(file, ext, "byteStride", what);
    const size_t count = number(file, ext, "count", what);
    const std::string mode = string(ext, "mode", "");
    const std::string filter = string(ext, "filter", "NONE");
    if (source >= g.buffers.size() || offset > g.buffers[source].data.size() ||
        length > g.buffers[source].data.size() - offset)
      throw SceneError(file, what + ": the compressed data lies outside buffers[" +
                                 std::to_string(source) + "]; the file is corrupt");
    if (view.buffer < 0 || size_t(view.buffer) >= g.buffers.size() || stride == 0 || stride > 256 ||
        count > (size_t(1) << 32) / stride ||
        view.byteOffset > g.buffers[size_t(view.buffer)].data.size() ||
        count * stride > g.buffers[size_t(view.buffer)].data.size() - view.byteOffset)
      throw SceneError(file, what + ": " + std::to_string(count) + " elements of " +
                                 std::to_string(stride) +
                                 " bytes do not fit its buffer; the file is corrupt");
    const unsigned char* src = g.buffers[source].data.data() + offset;
    unsigned char* dst = g.buffers[size_t(view.buffer)].data.data() + view.byteOffset;
    int rc = -1;
    if (mode == "ATTRIBUTES" && stride % 4 == 0)
      rc = meshopt_decodeVertexBuffer(dst, count, stride, src, length);
    else if (mode == "TRIANGLES" && (stride == 2 || stride == 4) && count % 3 == 0)
      rc = meshopt_decodeIndexBuffer(dst, count, stride, src, length);
    else if (mode == "INDICES" && (stride == 2 || stride == 4))
      rc = meshopt_decodeIndexSequence(dst, count, stride, src, length);
    else
      throw SceneError(file, what + ": EXT_meshopt_compression mode '" + mode +
                                 "' with byteStride " + std::to_string(stride) +
                                 " is not valid; re-export the file");
    if (rc != 0)
      throw SceneError(file, what + ": the meshopt " + mode + " stream does not decode (error " +
                                 std::to_string(rc) + "); the file is corrupt, re-export it");
    if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
      meshopt_decodeFilterOct(dst, count, stride);
    else if (filter == "QUATERNION" && stride == 8)
      meshopt_decodeFilterQuat(dst, count, stride);
    else if (filter == "EXPONENTIAL")
      meshopt_decodeFilterExp(dst, count, stride);
    else if (filter != "NONE")
      throw SceneError(file, what + ": EXT_meshopt_compression filter '" + filter +
                                 "' with byteStride " + std::to_string(stride) +
                                 " is not valid; re-export the file");
  }
}

}  // namespace taa::scene
