#include "core/image_io.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <system_error>
#include <vector>

#include "core/exr_codec.h"
#include "core/input_file.h"
#include "core/output_file.h"
#include "core/png_codec.h"
#include "core/sha256.h"

namespace taa {

namespace fs = std::filesystem;

ImageIoError::ImageIoError(const fs::path& path, const std::string& message)
    : InputError(path.string() + ": " + message), path_(path) {}

ImageWriteError::ImageWriteError(const fs::path& path, const std::string& message)
    : EnvironmentError(path.string() + ": " + message) {}

uint16_t floatToHalfBits(float value) {
  const uint32_t f = std::bit_cast<uint32_t>(value);
  const uint16_t sign = uint16_t((f >> 16) & 0x8000u);
  const uint32_t abs = f & 0x7fffffffu;
  // Frames read back from half targets hold normal halves, exactly: their bits only move.
  if ((abs & 0x1fffu) == 0 && abs - 0x38800000u <= 0x477fe000u - 0x38800000u)
    return uint16_t(sign | ((abs - 0x38000000u) >> 13));
  if (abs > 0x7f800000u) {
    // Keep the top payload bits so distinct NaNs stay distinct where they can, and force the
    // quiet bit so a payload that lived only in the low bits does not turn into Inf.
    return uint16_t(sign | 0x7e00u | ((abs >> 13) & 0x3ffu));
  }
  if (abs >= 0x47800000u) return uint16_t(sign | 0x7c00u);  // >= 65536 (and Inf): overflow
  if (abs < 0x38800000u) {
    // Below the smallest normal half: the result is a multiple of 2^-24. Scaling by 2^24 is exact
    // in float, and nearbyint under the default mode rounds ties to even; 1024 correctly becomes
    // the smallest normal's bit pattern.
    const float scaled = std::bit_cast<float>(abs) * 16777216.0f;
    return uint16_t(sign | uint16_t(std::nearbyint(scaled)));
  }
  const uint32_t exponent = (abs >> 23) - 127 + 15;
  const uint32_t mantissa = abs & 0x7fffffu;
  uint32_t h = (exponent << 10) | (mantissa >> 13);
  const uint32_t rest = mantissa & 0x1fffu;
  // A carry out of the mantissa bumps the exponent, which is exactly the right rounding, and
  // values in [65520, 65536) carry into the Inf pattern as IEEE requires.
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;
  return uint16_t(sign | h);
}

float halfBitsToFloat(uint16_t bits) {
  const uint32_t sign = uint32_t(bits & 0x8000u) << 16;
  const uint32_t exponent = (bits >> 10) & 0x1fu;
  const uint32_t mantissa = bits & 0x3ffu;
  if (exponent == 0) {
    const float magnitude = float(mantissa) * (1.0f / 16777216.0f);  // exact: subnormal or zero
    return sign ? -magnitude : magnitude;
  }
  if (exponent == 31) return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));
  return std::bit_cast<float>(sign | ((exponent - 15 + 127) << 23) | (mantissa << 13));
}

float halfRound(float value) {
  return halfBitsToFloat(floatToHalfBits(value));
}

std::string pixelSha256(const Image& image) {
  Sha256 hash;
  // Chunked so a 4K frame does not need a second full-size buffer.
  std::array<uint8_t, 8192> chunk;
  const float* v = image.data.data();
  for (size_t left = image.data.size(); left > 0;) {
    const size_t n = std::min(left, chunk.size() / 2);
    for (size_t i = 0; i < n; ++i) {
      const uint16_t h = floatToHalfBits(v[i]);
      chunk[2 * i] = uint8_t(h & 0xffu);
      chunk[2 * i + 1] = uint8_t(h >> 8);
    }
    hash.update(chunk.data(), 2 * n);
    v += n;
    left -= n;
  }
  const auto digest = hash.finish();
  return toHex(digest.data(), digest.size());
}

namespace {

void checkShape(const fs::path& path, const Image& image, int maxChannels) {
  if (image.width <= 0 || image.height <= 0 || image.channels <= 0 ||
      image.channels > maxChannels) {
    throw ImageIoError(path, "cannot write a " + std::to_string(image.width) + "x" +
                                 std::to_string(image.height) + " image with " +
                                 std::to_string(image.channels) + " channels (1 to " +
                                 std::to_string(maxChannels) + " supported)");
  }
  if (image.data.size() != size_t(image.width) * size_t(image.height) * size_t(image.channels)) {
    throw ImageIoError(path, "image data size does not match its shape");
  }
}

// Encoded bytes go to a temporary file that is flushed and renamed into place; a failure
// leaves `path` as it was and is a file-system problem (ImageWriteError).
void writeEncoded(const fs::path& path, const std::string& bytes) {
  try {
    writeFileAtomically(path, bytes);
  } catch (const OutputError& e) {
    throw ImageWriteError(path, e.what());
  }
}

// The whole file, within the size limit every other input has.
std::string readImageFile(const fs::path& path) {
  try {
    return readInputFile(path, kMaxSceneFileBytes);
  } catch (const InputFileError& e) {
    throw ImageIoError(path, e.what());
  }
}

float srgbEncode(float linear) {
  if (linear <= 0.0031308f) return 12.92f * linear;
  // In float the curve maps 1.0 an ulp away from 1.0; white must stay exactly white.
  if (linear >= 1.0f) return 1.0f;
  return std::min(1.0f, 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f);
}

float reinhard(float c) {
  if (!(c > 0.0f)) return 0.0f;  // negatives, -Inf and zero
  if (std::isinf(c)) return 1.0f;
  return c / (1.0f + c);
}

// Every frame's signature and PNG maps each channel through displayChannel, and its powf was
// the harness's largest cost after hashing. Frames read back from half-float targets hold
// halves, so a table of displayChannel over every positive finite half (the float exponents
// 2^-24 to 2^15, ten mantissa bits) answers them with the very values the function gives; any
// other float takes the function itself.
constexpr uint32_t kHalfTableFirstExponent = 127 - 24, kHalfTableExponents = 40;
const std::array<float, kHalfTableExponents * 1024>& halfDisplayTable() {
  static const auto table = [] {
    std::array<float, kHalfTableExponents * 1024> t{};
    for (uint32_t i = 0; i < t.size(); ++i)
      t[i] = displayChannel(std::bit_cast<float>((kHalfTableFirstExponent << 23) + (i << 13)));
    return t;
  }();
  return table;
}

float displayChannelFast(float c, const std::array<float, kHalfTableExponents * 1024>& table) {
  const uint32_t index = (std::bit_cast<uint32_t>(c) - (kHalfTableFirstExponent << 23)) >> 13;
  // Unsigned wrap sends zero, negatives and floats below 2^-24 past the end, as it does +Inf,
  // NaN and floats above the largest half.
  if ((std::bit_cast<uint32_t>(c) & 0x1fffu) == 0 && index < table.size()) return table[index];
  return displayChannel(c);
}

uint8_t quantize8(float v01) {
  const float clamped = v01 < 0.0f ? 0.0f : (v01 > 1.0f ? 1.0f : v01);
  return uint8_t(std::lround(clamped * 255.0f));
}

void writeRgb8(const fs::path& path, const Image& rgb01) {
  checkShape(path, rgb01, 4);
  std::vector<uint8_t> bytes(rgb01.pixelCount() * 3);
  const bool grey = rgb01.channels < 3;
  for (int y = 0; y < rgb01.height; ++y) {
    for (int x = 0; x < rgb01.width; ++x) {
      uint8_t* out = &bytes[(size_t(y) * size_t(rgb01.width) + size_t(x)) * 3];
      float rgb[3];
      bool nan = false;
      for (int c = 0; c < 3; ++c) {
        rgb[c] = rgb01.at(x, y, grey ? 0 : c);
        nan = nan || std::isnan(rgb[c]);
      }
      if (nan) {
        out[0] = 255, out[1] = 0, out[2] = 255;
        continue;
      }
      for (int c = 0; c < 3; ++c) out[c] = quantize8(rgb[c]);
    }
  }
  std::string encoded;
  try {
    encoded = png::encode8(bytes.data(), rgb01.width, rgb01.height, 3, png::kZlibLevel);
  } catch (const png::PngError& e) {
    throw ImageWriteError(path, e.what());
  }
  writeEncoded(path, encoded);
}

}  // namespace

void writeExr(const fs::path& path, const Image& image) {
  checkShape(path, image, 4);
  std::string encoded;
  try {
    encoded = exr::encode(image, true);
  } catch (const exr::ExrError& e) {
    throw ImageWriteError(path, e.what());
  }
  writeEncoded(path, encoded);
}

void writeExrFloat(const fs::path& path, const Image& image) {
  checkShape(path, image, 4);
  std::string encoded;
  try {
    encoded = exr::encode(image, false);
  } catch (const exr::ExrError& e) {
    throw ImageWriteError(path, e.what());
  }
  writeEncoded(path, encoded);
}

Image readImage(const fs::path& path) {
  const std::string bytes = readImageFile(path);
  try {
    if (exr::hasExrMagic(bytes)) return exr::decode(bytes, kMaxImageSamples);
    if (png::hasPngSignature(bytes)) return png::decode(bytes, kMaxImageSamples);
  } catch (const std::runtime_error& e) {
    throw ImageIoError(path, e.what());
  }
  throw ImageIoError(path,
                     "is neither OpenEXR nor PNG (the two formats the harness reads); "
                     "convert it to one of them");
}

ReadImage readImageByName(const fs::path& path, const std::string& layer, uint64_t maxSamples) {
  const std::string bytes = readImageFile(path);
  ReadImage out;
  try {
    if (exr::hasExrMagic(bytes)) {
      out.image = exr::decode(bytes, maxSamples, &layer);
      out.linear = true;
      return out;
    }
    if (png::hasPngSignature(bytes)) {
      out.image = png::decode(bytes, maxSamples);
      return out;
    }
  } catch (const std::runtime_error& e) {
    throw ImageIoError(path, e.what());
  }
  throw ImageIoError(path,
                     "is neither OpenEXR nor PNG (the two formats the harness reads); "
                     "convert it to one of them");
}

Image readExr(const fs::path& path) {
  const std::string bytes = readImageFile(path);
  if (!exr::hasExrMagic(bytes)) {
    throw ImageIoError(
        path, std::string("not an OpenEXR file (") +
                  (png::hasPngSignature(bytes) ? "a PNG" : "no OpenEXR magic number") + ")");
  }
  try {
    return exr::decode(bytes, kMaxImageSamples);
  } catch (const exr::ExrError& e) {
    throw ImageIoError(path, e.what());
  }
}

float displayChannel(float linear) { return srgbEncode(reinhard(linear)); }

Image toDisplaySrgb(const Image& hdr) {
  if (hdr.channels <= 0 && hdr.pixelCount() > 0) {
    throw std::invalid_argument("toDisplaySrgb: image has pixels but no channels");
  }
  Image out(hdr.width, hdr.height, 3);
  const bool grey = hdr.channels < 3;
  const auto& table = halfDisplayTable();
  for (int y = 0; y < hdr.height; ++y) {
    for (int x = 0; x < hdr.width; ++x) {
      float rgb[3];
      bool nan = false;
      for (int c = 0; c < 3; ++c) {
        rgb[c] = hdr.at(x, y, grey ? 0 : c);
        nan = nan || std::isnan(rgb[c]);
      }
      for (int c = 0; c < 3; ++c) {
        out.at(x, y, c) = nan ? (c == 1 ? 0.0f : 1.0f) : displayChannelFast(rgb[c], table);
      }
    }
  }
  return out;
}

void writePng(const fs::path& path, const Image& hdr) {
  checkShape(path, hdr, 4);
  writeRgb8(path, toDisplaySrgb(hdr));
}

void writePngLinear8(const fs::path& path, const Image& rgb01) {
  writeRgb8(path, rgb01);
}

}  // namespace taa
