// Internal to the glTF loader: the image callback tinygltf calls for each images[] entry.
// It checks the bytes before any decoder sees them: an image in a buffer view must lie
// inside its buffer, and the bytes must be a PNG or JPEG whose header states a size the
// renderer accepts, so a corrupt or hostile header cannot make the decoder read past the
// data or allocate gigabytes.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>

namespace taa::scene {

// Largest texture side accepted (and the largest render width): a 8192 x 8192 RGBA8
// texture is 256 MiB before mips.
inline constexpr int kMaxTextureSide = 8192;

// Decoded bytes all images of one file may take together: each image is bounded by its
// side, but a hundred small compressed images can each claim the full size.
inline constexpr uint64_t kMaxDecodedImageBytes = uint64_t(1) << 30;  // 1 GiB

// What a PNG or JPEG header says, read without decoding.
struct ImageHeader {
  std::string problem;        // "" when the header is a PNG or JPEG within kMaxTextureSide
  uint64_t decodedBytes = 0;  // RGBA at the file's bit depth, as tinygltf decodes it
};
ImageHeader readImageHeader(const unsigned char* bytes, size_t size);

// What loadCheckedImage needs: the tinygltf::Model being loaded (its buffers and buffer
// views are parsed before its images) and the decoded bytes so far.
struct ImageLoadState {
  const tinygltf::Model* model = nullptr;
  uint64_t decodedBytes = 0;
};

// tinygltf's LoadImageDataFunction; `state` is an ImageLoadState.
bool loadCheckedImage(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                      int reqWidth, int reqHeight, const unsigned char* bytes, int size,
                      void* state);

}  // namespace taa::scene
