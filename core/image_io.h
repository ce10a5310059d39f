// Image files for goldens and reports: lossless half-float EXR for the data that is compared,
// tonemapped 8-bit PNG for people to look at.
//
// Pixel fingerprint (pixelSha256), the exact definition goldens rely on:
//   SHA-256 over the image's samples in row-major order, top row first, channels interleaved
//   (the layout of Image::data), each sample converted to an IEEE 754 binary16 ("half") with
//   floatToHalfBits (round to nearest, ties to even; overflow to +-Inf; NaN stays NaN) and
//   written as 2 bytes, little-endian. Nothing else is hashed: no width, height or channel count,
//   so two images of different shape but equal sample bytes hash equal; callers that care store
//   the shape next to the hash. The hash is lowercase hex (64 characters).
// Hashing the half bits rather than the floats means an image and its EXR round trip
// (writeExr then readExr) always have the same fingerprint.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "core/image.h"

namespace taa {

// An image file that cannot be read (missing, unreadable, not PNG or OpenEXR, damaged) or an
// image that no file can hold: bad input. what() names the file and carries libpng's or
// OpenEXR's own message.
class ImageIoError : public InputError {
 public:
  ImageIoError(const std::filesystem::path& path, const std::string& message);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// A write that failed in the file system (full disk, read-only or missing folder), or an
// encoder that failed: the environment, not the input. what() names the file.
class ImageWriteError : public EnvironmentError {
 public:
  ImageWriteError(const std::filesystem::path& path, const std::string& message);
};

// Writes every channel (1 to 4; named R, G, B, A in that order) as half-float OpenEXR with
// lossless ZIP compression and no wall-clock or software attributes, so the file's bytes are a
// function of its pixels. Values are rounded with floatToHalfBits, so a later readExr gives
// back exactly halfRound() of each sample. Atomic: the data goes to a temporary file in the same
// folder that is then renamed over `path`; on failure an older file at `path` is left untouched.
void writeExr(const std::filesystem::path& path, const Image& image);

// The same in 32-bit float, for data that half floats would quantise: reversed-Z depth,
// object ids above 2048, the float32 reference.
void writeExrFloat(const std::filesystem::path& path, const Image& image);

// Reads an OpenEXR file as float samples with the file's channels (R, G, B, A first, then the
// others in the file's order); any pixel type, scanline or tiled, the first part of a multi-part
// file, the data window's pixels.
// Throws ImageIoError when the file is missing, unreadable or not OpenEXR.
Image readExr(const std::filesystem::path& path);

// The largest image readImage and readExr accept (an 8192 x 8192 RGBA image, 1 GiB of floats), so a
// hostile header cannot make them allocate without bound.
inline constexpr uint64_t kMaxImageSamples = uint64_t(1) << 28;

// Reads an OpenEXR or PNG file (recognised by its first bytes, not its name) as float samples:
// EXR as readExr; PNG as stored, 8- and 16-bit samples scaled to [0, 1] with no transfer function,
// palettes expanded to RGB and transparency to an alpha channel that stays unassociated.
Image readImage(const std::filesystem::path& path);

// An image as `compare` reads it: the kind decided by the file's first bytes, not its name.
struct ReadImage {
  Image image;
  bool linear = false;  // OpenEXR (linear), else PNG (display-referred)
};

// readImage, but an EXR's channels are chosen by name: LAYER.R, LAYER.G, LAYER.B, LAYER.A (R,
// G, B, A for an empty `layer`), those present in that order, R required; a file without them
// is refused naming its channels (a layered, B,G,R-ordered or X,Y,Z file is never read as RGB
// by position).
// `maxSamples` bounds the decoded image below kMaxImageSamples where a reader needs it (compare).
ReadImage readImageByName(const std::filesystem::path& path, const std::string& layer,
                          uint64_t maxSamples = kMaxImageSamples);

// Writes a linear HDR image for viewing as 8-bit sRGB PNG, alpha dropped; see toDisplaySrgb for
// the exact mapping. Atomic like writeExr.
void writePng(const std::filesystem::path& path, const Image& hdr);

// Writes an image that is already display-referred (heatmaps, crops of a display image): each of
// the first three channels is clamped to [0, 1] and quantized as round(v * 255) with no transfer
// function applied. One channel is written as grey. NaN pixels become magenta. Atomic.
void writePngLinear8(const std::filesystem::path& path, const Image& rgb01);

// The display image writePng quantizes, as 3-channel floats in [0, 1]:
//   per channel c of linear RGB: NaN in any channel -> the whole pixel is magenta (1, 0, 1);
//   otherwise c <= 0 (and -Inf) -> 0, +Inf -> 1, else Reinhard c / (1 + c);
//   then the sRGB transfer function (IEC 61966-2-1 piecewise curve).
// A 1- or 2-channel image is treated as grey (channel 0 in R, G and B).
// flipLdrFromHdr uses the same mapping so FLIP judges what the PNG shows.
Image toDisplaySrgb(const Image& hdr);
// One channel of that mapping, for a value that is not NaN. toDisplaySrgb answers halves (what
// half-float targets read back as) from a table of this function's own values.
float displayChannel(float linear);

// IEEE 754 binary16 conversions, independent of the host's FPU modes.
uint16_t floatToHalfBits(float value);  // round to nearest, ties to even
float halfBitsToFloat(uint16_t bits);
// The value an EXR round trip produces: halfBitsToFloat(floatToHalfBits(value)).
float halfRound(float value);

// See the definition at the top of this file.
std::string pixelSha256(const Image& image);

}  // namespace taa
