#include "scene/gltf_images.h"

#include <cstring>

namespace taa::scene {
namespace {

uint32_t be32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

uint32_t be16(const unsigned char* p) {
  return uint32_t(p[0]) << 8 | uint32_t(p[1]);
}

ImageHeader sized(uint32_t w, uint32_t h, uint64_t bytesPerChannel) {
  ImageHeader out;
  if (w == 0 || h == 0)
    out.problem = "has a header that gives a size of " + std::to_string(w) + " x " +
                  std::to_string(h) + "; the image is corrupt, re-export it";
  else if (w > uint32_t(kMaxTextureSide) || h > uint32_t(kMaxTextureSide))
    out.problem = "is " + std::to_string(w) + " x " + std::to_string(h) + ", over the limit of " +
                  std::to_string(kMaxTextureSide) + " per side; scale it down";
  out.decodedBytes = uint64_t(w) * h * 4 * bytesPerChannel;
  return out;
}

ImageHeader refused(const std::string& problem) {
  return ImageHeader{problem, 0};
}

// The frame size from a JPEG's first start-of-frame marker.
ImageHeader jpegHeader(const unsigned char* b, size_t size) {
  size_t i = 2;
  while (i + 4 <= size) {
    if (b[i] != 0xFF) return refused("is a JPEG with a corrupt marker sequence");
    const unsigned char m = b[i + 1];
    if (m == 0xFF) {  // fill byte
      ++i;
      continue;
    }
    if (m == 0x01 || (m >= 0xD0 && m <= 0xD7)) {  // markers without a length
      i += 2;
      continue;
    }
    const size_t len = be16(b + i + 2);
    if (len < 2) return refused("is a JPEG with a corrupt segment length");
    const bool sof = m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
    if (sof) {
      if (i + 9 > size) break;
      return sized(be16(b + i + 7), be16(b + i + 5), 1);
    }
    if (m == 0xD9 || m == 0xDA) return refused("is a JPEG without a frame header before its data");
    i += 2 + len;
  }
  return refused("is a truncated JPEG (no frame header)");
}

}  // namespace

ImageHeader readImageHeader(const unsigned char* b, size_t size) {
  static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (size >= 8 && std::memcmp(b, png, 8) == 0) {
    if (size < 25 || std::memcmp(b + 12, "IHDR", 4) != 0)
      return refused("is a PNG without a valid IHDR header");
    return sized(be32(b + 16), be32(b + 20), b[24] == 16 ? 2 : 1);
  }
  if (size >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return jpegHeader(b, size);
  return refused(
      "is neither a PNG nor a JPEG (the two image formats glTF allows); convert it to PNG");
}

bool loadCheckedImage(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                      int reqWidth, int reqHeight, const unsigned char* bytes, int size,
                      void* statePtr) {
  auto& state = *static_cast<ImageLoadState*>(statePtr);
  const tinygltf::Model* model = state.model;
  const std::string name = "images[" + std::to_string(index) + "]";
  auto refuse = [&](const std::string& problem) {
    if (err) *err += name + " " + problem + "\n";
    return false;
  };
  if (image->bufferView >= 0) {
    // tinygltf hands over the view's bytes without checking them against the buffer.
    const tinygltf::BufferView& v = model->bufferViews[size_t(image->bufferView)];
    const size_t have = model->buffers[size_t(v.buffer)].data.size();
    if (v.byteOffset > have || v.byteLength > have - v.byteOffset)
      return refuse(
          "uses bufferViews[" + std::to_string(image->bufferView) + "], which reaches byte " +
          (v.byteOffset > have
               ? std::to_string(v.byteOffset)
               : std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength)) +
          " of a buffer of " + std::to_string(have) + " bytes; the file is corrupt, re-export it");
    if (v.byteLength > size_t(INT32_MAX)) return refuse("is over 2 GiB");
  }
  if (size <= 0) return refuse("is empty");
  const ImageHeader header = readImageHeader(bytes, size_t(size));
  if (!header.problem.empty()) return refuse(header.problem);
  state.decodedBytes += header.decodedBytes;
  if (state.decodedBytes > kMaxDecodedImageBytes)
    return refuse("takes the file's decoded images past " +
                  std::to_string(kMaxDecodedImageBytes >> 20) +
                  " MiB; use fewer or smaller images");
  return tinygltf::LoadImageData(image, index, err, warn, reqWidth, reqHeight, bytes, size,
                                 nullptr);
}

}  // namespace taa::scene
