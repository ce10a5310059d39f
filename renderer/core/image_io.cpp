#include "core/image_io.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <system_error>
#include <vector>

#include "core/output_file.h"
#include "core/sha256.h"

namespace taa {

namespace fs = std::filesystem;

ImageIoError::ImageIoError(const fs::path& path, const std::string& message)
    : std::runtime_error(path.string() + ": " + message), path_(path) {}

uint16_t floatToHalfBits(float value) {
  const uint32_t f = std::bit_cast<uint32_t>(value);
  const uint16_t sign = uint16_t((f >> 16) & 0x8000u);
  const uint32_t abs = f & 0x7fffffffu;
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
  size_t used = 0;
  for (float v : image.data) {
    const uint16_t h = floatToHalfBits(v);
    chunk[used++] = uint8_t(h & 0xffu);
    chunk[used++] = uint8_t(h >> 8);
    if (used == chunk.size()) {
      hash.update(chunk.data(), used);
      used = 0;
    }
  }
  hash.update(chunk.data(), used);
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

// A name no other writer in this process or another one uses at the same moment, hidden so a
// directory listing during the write does not show a half-written image under a real name.
fs::path temporaryPathFor(const fs::path& path) {
  static std::atomic<uint64_t> counter{0};
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  return dir / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                std::to_string(counter.fetch_add(1)));
}

// Writes `pixels` (already in `type`) through OpenImageIO into a temporary file and renames it
// into place. Any failure removes the temporary file and throws, leaving `path` as it was.
void writeAtomically(const fs::path& path, const char* format, const OIIO::ImageSpec& spec,
                     const void* pixels) {
  const fs::path tmp = temporaryPathFor(path);
  auto fail = [&](const std::string& message) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw ImageWriteError(path, message);
  };
  {
    auto out = OIIO::ImageOutput::create(format);
    if (!out) fail("OpenImageIO has no " + std::string(format) + " writer: " + OIIO::geterror());
    if (!out->open(tmp.string(), spec)) fail(out->geterror());
    if (!out->write_image(spec.format, pixels)) {
      const std::string message = out->geterror();
      out->close();
      fail(message);
    }
    if (!out->close()) fail(out->geterror());
  }
  // Flushed before the rename so a crash cannot leave the new name pointing at a file whose
  // data never arrived; a full disk often shows only here.
  try {
    syncFile(tmp);
  } catch (const OutputError& e) {
    fail(e.what());
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) fail("cannot move the written file into place: " + ec.message());
}

constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};

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
  OIIO::ImageSpec spec(rgb01.width, rgb01.height, 3, OIIO::TypeDesc::UINT8);
  writeAtomically(path, "png", spec, bytes.data());
}

}  // namespace

void writeExr(const fs::path& path, const Image& image) {
  checkShape(path, image, 4);
  std::vector<uint16_t> halves(image.data.size());
  for (size_t i = 0; i < halves.size(); ++i) halves[i] = floatToHalfBits(image.data[i]);
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::HALF);
  spec.channelnames.assign(kChannelNames, kChannelNames + image.channels);
  spec.alpha_channel = image.channels == 4 ? 3 : -1;
  // ZIP is lossless and deterministic; the lossy EXR codecs would break exact comparisons.
  spec.attribute("compression", "zip");
  writeAtomically(path, "openexr", spec, halves.data());
}

void writeExrFloat(const fs::path& path, const Image& image) {
  checkShape(path, image, 4);
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames.assign(kChannelNames, kChannelNames + image.channels);
  spec.alpha_channel = image.channels == 4 ? 3 : -1;
  spec.attribute("compression", "zip");
  writeAtomically(path, "openexr", spec, image.data.data());
}

Image readImage(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw ImageIoError(path, OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.depth > 1) throw ImageIoError(path, "volume images are not supported");
  Image image(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data())) {
    throw ImageIoError(path, in->geterror());
  }
  in->close();
  return image;
}

Image readExr(const fs::path& path) {
  {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw ImageIoError(path, OIIO::geterror());
    if (std::string(in->format_name()) != "openexr") {
      throw ImageIoError(path, std::string("not an OpenEXR file (") + in->format_name() + ")");
    }
  }
  return readImage(path);
}

Image toDisplaySrgb(const Image& hdr) {
  if (hdr.channels <= 0 && hdr.pixelCount() > 0) {
    throw std::invalid_argument("toDisplaySrgb: image has pixels but no channels");
  }
  Image out(hdr.width, hdr.height, 3);
  const bool grey = hdr.channels < 3;
  for (int y = 0; y < hdr.height; ++y) {
    for (int x = 0; x < hdr.width; ++x) {
      float rgb[3];
      bool nan = false;
      for (int c = 0; c < 3; ++c) {
        rgb[c] = hdr.at(x, y, grey ? 0 : c);
        nan = nan || std::isnan(rgb[c]);
      }
      for (int c = 0; c < 3; ++c) {
        out.at(x, y, c) = nan ? (c == 1 ? 0.0f : 1.0f) : srgbEncode(reinhard(rgb[c]));
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
