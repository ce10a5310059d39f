#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/scene_error.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw SceneError(file, problem);
}

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT4:  // skins' inverse bind matrices
      return 16;
    default:
      return 0;
  }
}

// Reads one component as float, applying the glTF normalisation rules for integers.
float component(const uint8_t* p, int type, bool normalized) {
  auto get = [&](auto v) {
    std::memcpy(&v, p, sizeof(v));
    return v;
  };
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return get(float{});
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = float(get(int8_t{}));
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return float(get(uint8_t{})) / (normalized ? 255.0f : 1.0f);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = float(get(int16_t{}));
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return float(get(uint16_t{})) / (normalized ? 65535.0f : 1.0f);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return float(get(uint32_t{}));
    default:
      return 0.0f;
  }
}

// Where an accessor's elements lie, after checking with overflow-free arithmetic that
// every byte it reads is inside its buffer. base is null for an accessor without a view.
struct AccessorSpan {
  const uint8_t* base = nullptr;
  size_t stride = 0;
  size_t count = 0;
};

AccessorSpan checkSpan(const fs::path& file, const tinygltf::Model& model,
                       const tinygltf::Accessor& a, const std::string& name, int comps) {
  AccessorSpan span;
  span.count = a.count;
  if (a.bufferView < 0) {
    // Nothing in the file backs the zeros, so the count alone must be sane.
    if (a.count > kMaxUnbackedElements)
      fail(file, name + " has count " + std::to_string(a.count) +
                     " without a bufferView (all zeros); at most " +
                     std::to_string(kMaxUnbackedElements) + " are accepted, the file is corrupt");
    return span;
  }
  const int csize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (csize <= 0) fail(file, name + " has an invalid component type");
  if (size_t(a.bufferView) >= model.bufferViews.size() ||
      size_t(model.bufferViews[size_t(a.bufferView)].buffer) >= model.buffers.size())
    fail(file, name + " refers to a missing buffer view or buffer; the file is corrupt");
  const tinygltf::BufferView& v = model.bufferViews[size_t(a.bufferView)];
  const size_t have = model.buffers[size_t(v.buffer)].data.size();
  const std::string corrupt = "; the file is truncated or corrupt, re-export it";
  if (v.byteOffset > have || v.byteLength > have - v.byteOffset)
    fail(file, name + " uses bufferViews[" + std::to_string(a.bufferView) + "] (byteOffset " +
                   std::to_string(v.byteOffset) + ", byteLength " + std::to_string(v.byteLength) +
                   "), which ends past its buffer of " + std::to_string(have) + " bytes" + corrupt);
  const size_t elem = size_t(csize) * size_t(comps);
  const size_t stride = v.byteStride ? v.byteStride : elem;
  if (stride < elem)
    fail(file, name + " has a byteStride of " + std::to_string(stride) +
                   ", smaller than its element of " + std::to_string(elem) + " bytes" + corrupt);
  if (a.count == 0) return span;
  // byteOffset + stride * (count - 1) + elem <= byteLength, rearranged so nothing overflows.
  const bool fits = a.byteOffset <= v.byteLength && elem <= v.byteLength - a.byteOffset &&
                    a.count - 1 <= (v.byteLength - a.byteOffset - elem) / stride;
  if (!fits)
    fail(file, name + " (count " + std::to_string(a.count) + ", byteOffset " +
                   std::to_string(a.byteOffset) + ") reads past the end of bufferViews[" +
                   std::to_string(a.bufferView) + "] of " + std::to_string(v.byteLength) +
                   " bytes" + corrupt);
  span.base = model.buffers[size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset;
  span.stride = stride;
  return span;
}

uint32_t readIndex(const uint8_t* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    default: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// A sparse accessor's substitutions (glTF 2.0, 3.6.2.3): `count` strictly increasing
// element indices and as many replacement elements, read with the same bounds checks as
// any accessor. `set(element, valuesBase, valuesStride)` writes one replacement.
template <class Set>
void applySparse(const fs::path& file, const tinygltf::Model& model, const tinygltf::Accessor& a,
                 const std::string& name, int comps, Set set) {
  const auto& sp = a.sparse;
  if (sp.count <= 0 || size_t(sp.count) > a.count)
    fail(file, name + " is sparse with sparse.count " + std::to_string(sp.count) +
                   ", which must be between 1 and its count " + std::to_string(a.count) +
                   "; the file is corrupt, re-export it");
  const int it = sp.indices.componentType;
  if (it != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && it != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      it != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(file, name + " sparse.indices.componentType " + std::to_string(it) +
                   " is not an unsigned byte, short or int; the file is corrupt, re-export it");
  if (sp.indices.bufferView < 0 || sp.values.bufferView < 0)
    fail(file, name + " is sparse without a bufferView for its indices or values; the file is "
                      "corrupt, re-export it");
  tinygltf::Accessor indices;
  indices.bufferView = sp.indices.bufferView;
  indices.byteOffset = size_t(std::max(sp.indices.byteOffset, 0));
  indices.componentType = it;
  indices.count = size_t(sp.count);
  indices.type = TINYGLTF_TYPE_SCALAR;
  tinygltf::Accessor values = a;
  values.bufferView = sp.values.bufferView;
  values.byteOffset = size_t(std::max(sp.values.byteOffset, 0));
  values.count = size_t(sp.count);
  values.sparse.isSparse = false;
  // Sparse data is tightly packed whatever the view's byteStride says.
  const AccessorSpan is = checkSpan(file, model, indices, name + " sparse.indices", 1);
  const AccessorSpan vs = checkSpan(file, model, values, name + " sparse.values", comps);
  const size_t isize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(it)));
  const size_t vsize =
      size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType))) * size_t(comps);
  if (is.stride != isize || vs.stride != vsize)
    fail(file, name + " sparse indices or values sit in a bufferView with a byteStride; sparse "
                      "data is tightly packed, the file is corrupt, re-export it");
  int64_t last = -1;
  for (size_t k = 0; k < is.count; ++k) {
    const uint32_t e = readIndex(is.base + k * isize, it);
    if (int64_t(e) <= last || e >= a.count)
      fail(file, name + " sparse.indices[" + std::to_string(k) + "] is " + std::to_string(e) +
                     "; they must strictly increase and stay below its count " +
                     std::to_string(a.count) + ", the file is corrupt, re-export it");
    last = e;
    set(size_t(e), vs.base + k * vsize);
  }
}

}  // namespace

std::vector<float> readGltfAccessor(const fs::path& file, const tinygltf::Model& model, int index,
                                    const std::string& what, int want) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    fail(file, what + " refers to a missing accessor");
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const std::string name = "accessors[" + std::to_string(index) + "] (" + what + ")";
  const int comps = componentCount(a.type);
  if (comps != want)
    fail(file,
         name + " has " + std::to_string(comps) + " components, expected " + std::to_string(want));
  const AccessorSpan span = checkSpan(file, model, a, name, comps);
  std::vector<float> out(span.count * size_t(comps), 0.0f);
  const int csize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  auto element = [&](size_t i, const uint8_t* p) {
    for (int c = 0; c < comps; ++c)
      out[i * size_t(comps) + size_t(c)] =
          component(p + size_t(c) * size_t(csize), a.componentType, a.normalized);
  };
  // No buffer view: all zeros, as the spec defines (then the sparse values alone count).
  for (size_t i = 0; span.base && i < span.count; ++i) element(i, span.base + i * span.stride);
  if (a.sparse.isSparse) applySparse(file, model, a, name, comps, element);
  // The glTF spec allows finite values only: a NaN or infinite vertex, weight or keyframe
  // would reach the frame (and its hash) as whatever the rasteriser makes of it.
  for (size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i]))
      fail(file, name + " element " + std::to_string(i / size_t(comps)) + " holds " +
                     (std::isnan(out[i]) ? "NaN" : "an infinity") +
                     "; accessors hold finite numbers only, so fix or re-export the scene");
  return out;
}

std::vector<uint32_t> readGltfIndices(const fs::path& file, const tinygltf::Model& model, int index,
                                      const std::string& what) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    fail(file, what + " indices refer to a missing accessor");
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(file, what + " indices must be unsigned integers");
  const std::vector<float> f = readGltfAccessor(file, model, index, what + " indices", 1);
  // Floats hold integers exactly only up to 2^24; read 32-bit indices directly.
  std::vector<uint32_t> out(f.size());
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    for (size_t i = 0; i < out.size(); ++i) out[i] = uint32_t(f[i]);
    return out;
  }
  // readGltfAccessor has checked the views, the buffers and the bounds already.
  const AccessorSpan span = checkSpan(file, model, a, what + " indices", 1);
  for (size_t i = 0; span.base && i < out.size(); ++i)
    std::memcpy(&out[i], span.base + i * span.stride, 4);
  if (a.sparse.isSparse)
    applySparse(file, model, a, what + " indices", 1,
                [&](size_t i, const uint8_t* p) { std::memcpy(&out[i], p, 4); });
  return out;
}

}  // namespace taa::scene
