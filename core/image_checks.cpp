#include "core/image_checks.h"

#include <algorithm>
#include <cstring>
#include <map>

namespace taa {

namespace {

uint32_t bigEndian32(const unsigned char* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

int32_t littleEndian32(const unsigned char* p) {
  uint32_t v =
      uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
  int32_t out;
  std::memcpy(&out, &v, 4);
  return out;
}

// A PNG chunk type is four ASCII letters; anything else is not named back.
std::string chunkName(const unsigned char* p) {
  for (int i = 0; i < 4; ++i)
    if (!((p[i] >= 'a' && p[i] <= 'z') || (p[i] >= 'A' && p[i] <= 'Z'))) return "a chunk";
  return "chunk " + std::string(reinterpret_cast<const char*>(p), 4);
}

// Lines an EXR scanline chunk holds, by compression (OpenEXR's ImfCompression.h order).
int64_t exrLinesPerChunk(int compression) {
  switch (compression) {
    case 3:  // ZIP
    case 5:  // PXR24
      return 16;
    case 4:  // PIZ
    case 6:  // B44
    case 7:  // B44A
    case 8:  // DWAA
      return 32;
    case 9:  // DWAB
      return 256;
    default:  // NONE, RLE, ZIPS
      return 1;
  }
}

// The most one byte of deflate (zlib) data can inflate to: 258 bytes per 2-bit code, which
// zlib's documentation rounds to 1032:1.
constexpr uint64_t kMaxInflateRatio = 1032;

// Bytes of raw samples a PNG's IHDR implies (filter bytes left out, so a lower bound for
// interlaced images too); 0 for a colour type PNG does not define.
uint64_t pngRawBytes(const unsigned char* ihdr) {
  // Sides clamped to 2^24 keep the product inside 64 bits and the result a lower bound.
  const uint64_t width = std::min<uint64_t>(bigEndian32(ihdr), 1u << 24);
  const uint64_t height = std::min<uint64_t>(bigEndian32(ihdr + 4), 1u << 24);
  const int depth = ihdr[8];
  // Samples per pixel by colour type: grey, -, RGB, palette index, grey + alpha, -, RGBA.
  static constexpr int kChannels[7] = {1, 0, 3, 1, 2, 0, 4};
  const int channels = ihdr[9] < 7 ? kChannels[ihdr[9]] : 0;
  return (width * height * uint64_t(channels) * uint64_t(depth)) / 8;
}

// The most raw sample bytes one byte of an EXR chunk can hold, by compression; 0 where the
// codec has no such bound (PIZ's Huffman run codes, DWA's, and codecs newer than these).
uint64_t exrMaxRatio(int compression) {
  // NONE 1; RLE 128 (a count byte and a value repeat at most 128 times); ZIPS and ZIP
  // deflate; PXR24 deflate of float samples cut to 24 bits; B44 and B44A store a 4x4 block
  // of half samples (32 bytes) in 14 or 3.
  static constexpr uint64_t kRatio[8] = {
      1, 128, kMaxInflateRatio, kMaxInflateRatio, 0, 2 * kMaxInflateRatio, 16, 16};
  return compression >= 0 && compression < 8 ? kRatio[compression] : 0;
}

// OpenEXR reads a known attribute type by its own layout, not by the size the file gives it:
// a box2i is 16 bytes whatever its size says, a chlist runs to its empty name, a preview
// allocates width x height x 4 bytes, a stringvector each string's length. Where the two
// disagree, OpenEXR goes on reading at another position than the size leads to, where any
// bytes can pass for a huge length. So each such value must fill exactly its size; "" when
// it does (or the type is one OpenEXR reads by size alone).
std::string exrAttributeLayoutProblem(const std::string& type, const unsigned char* v, size_t size) {
  static const std::map<std::string, size_t> kFixed = {
      {"box2i", 16},  {"box2f", 16},  {"chromaticities", 32}, {"compression", 1}, {"double", 8},
      {"envmap", 1},  {"float", 4},   {"int", 4},             {"keycode", 28},    {"lineOrder", 1},
      {"m33f", 36},   {"m33d", 72},   {"m44f", 64},           {"m44d", 128},      {"rational", 8},
      {"tiledesc", 9}, {"timecode", 8}, {"v2i", 8},           {"v2f", 8},         {"v2d", 16},
      {"v3i", 12},    {"v3f", 12},    {"v3d", 24},            {"deepImageState", 1}};
  if (const auto it = kFixed.find(type); it != kFixed.end())
    return size == it->second ? "" : "a " + type + " takes " + std::to_string(it->second) + " bytes";
  if (type == "chlist") {
    size_t c = 0;
    while (c < size && v[c] != 0) {
      while (c < size && v[c] != 0) ++c;
      c += 1 + 16;  // the name's NUL, then type, pLinear, reserved, x and y sampling
    }
    return c + 1 == size ? "" : "its channel list does not end where its size does";
  }
  if (type == "preview") {
    if (size < 8) return "a preview takes at least 8 bytes";
    const uint64_t w = uint32_t(littleEndian32(v)), h = uint32_t(littleEndian32(v + 4));
    return 8 + 4 * w * h == size ? "" : "its preview's width and height do not match its size";
  }
  if (type == "stringvector") {
    size_t c = 0;
    while (c < size) {
      if (size - c < 4) return "its string list is cut short";
      const int64_t len = littleEndian32(v + c);
      c += 4;
      if (len < 0 || uint64_t(len) > size - c) return "a string of its list runs past its size";
      c += size_t(len);
    }
    return "";
  }
  return "";
}

}  // namespace

std::string pngStructureProblem(std::string_view bytes) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  size_t at = 8;  // after the signature
  bool first = true;
  uint64_t raw = 0, compressed = 0;
  while (at < bytes.size()) {
    if (bytes.size() - at < 12)
      return "the chunk at byte " + std::to_string(at) + " is cut short (truncated file)";
    const uint32_t length = bigEndian32(b + at);
    const std::string name = chunkName(b + at + 4);
    if (length > 0x7fffffffu || uint64_t(length) > bytes.size() - at - 12)
      return name + " at byte " + std::to_string(at) + " claims " + std::to_string(length) +
             " bytes, but only " + std::to_string(bytes.size() - at - 12) +
             " follow (a corrupt or hostile file)";
    if (first && (std::memcmp(b + at + 4, "IHDR", 4) != 0 || length != 13))
      return "does not start with a 13-byte IHDR chunk";
    if (first) raw = pngRawBytes(b + at + 8);
    first = false;
    if (std::memcmp(b + at + 4, "IDAT", 4) == 0) compressed += length;
    if (std::memcmp(b + at + 4, "IEND", 4) == 0) break;
    at += 12 + size_t(length);
  }
  if (first) return "has no chunks after its signature";
  // libpng allocates the rows before inflating them: a 1 KB file must not claim gigapixels.
  if (compressed * kMaxInflateRatio + 1024 < raw)
    return "holds " + std::to_string(compressed) + " bytes of image data (IDAT), which cannot " +
           "inflate to the " + std::to_string(raw) + " bytes its header declares (a truncated, " +
           "corrupt or hostile file)";
  return {};
}

std::string exrStructureProblem(std::string_view bytes, uint64_t maxSamples, ExrHeaderInfo& info) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t n = bytes.size();
  if (n < 8) return "is shorter than an OpenEXR header";
  const uint32_t flags = uint32_t(littleEndian32(b + 4)) >> 8;
  const bool tiled = flags & 0x2, longNames = flags & 0x4, multipart = flags & 0x10;
  const size_t maxName = longNames ? 256 : 32;
  size_t at = 8;
  int part = 0;
  int compression = 0;
  int64_t tileW = 0, tileH = 0;
  bool window = false;
  struct ChannelBytes {
    int64_t bytes, xSampling, ySampling;
  };
  std::vector<ChannelBytes> sampleBytes;
  // Reads a NUL-terminated name of at most maxName bytes; false when it runs out.
  auto name = [&](std::string& out) {
    const size_t end = std::min(n, at + maxName);
    for (size_t i = at; i < end; ++i)
      if (b[i] == 0) {
        out.assign(reinterpret_cast<const char*>(b + at), i - at);
        at = i + 1;
        return true;
      }
    return false;
  };
  for (;;) {
    if (at >= n) return "its header ends early (truncated file)";
    if (b[at] == 0) {  // the end of a header
      ++at;
      if (!multipart || (at < n && b[at] == 0)) {
        if (multipart) ++at;  // the empty header ending the list
        break;
      }
      ++part;
      if (part > 1024) return "declares more than 1024 parts";
      continue;
    }
    const size_t attrAt = at;
    std::string attr, type;
    if (!name(attr) || !name(type))
      return "the attribute at byte " + std::to_string(attrAt) +
             " has a name or type longer than the format allows, or none";
    if (n - at < 4) return "its header ends early (truncated file)";
    const int32_t size = littleEndian32(b + at);
    at += 4;
    if (size < 0 || uint64_t(size) > n - at)
      return "the attribute at byte " + std::to_string(attrAt) + " claims " + std::to_string(size) +
             " bytes, but only " + std::to_string(n - at) + " follow (a corrupt or hostile file)";
    const unsigned char* v = b + at;
    if (const std::string why = exrAttributeLayoutProblem(type, v, size_t(size)); !why.empty())
      return "the attribute " + attr + " at byte " + std::to_string(attrAt) + " claims " +
             std::to_string(size) + " bytes, but " + why + " (a corrupt or hostile file)";
    if (part == 0) {
      if (attr == "channels" && type == "chlist") {
        size_t c = 0;
        while (c < size_t(size) && v[c] != 0) {
          const size_t start = c;
          while (c < size_t(size) && v[c] != 0) ++c;
          if (c + 1 + 16 > size_t(size)) return "its channel list is cut short";
          info.channels.emplace_back(reinterpret_cast<const char*>(v + start), c - start);
          // pixel type (0 uint, 1 half, 2 float), pLinear and 3 reserved bytes, x and y
          // sampling: the raw bytes the channel's samples take.
          const int32_t pixelType = littleEndian32(v + c + 1);
          const int64_t xs = littleEndian32(v + c + 9), ys = littleEndian32(v + c + 13);
          sampleBytes.push_back({pixelType == 1 ? 2 : 4, xs, ys});
          c += 1 + 16;
        }
      } else if (attr == "dataWindow" && type == "box2i" && size == 16) {
        const int64_t x0 = littleEndian32(v), y0 = littleEndian32(v + 4),
                      x1 = littleEndian32(v + 8), y1 = littleEndian32(v + 12);
        info.width = x1 - x0 + 1;
        info.height = y1 - y0 + 1;
        window = true;
      } else if (attr == "compression" && type == "compression" && size == 1) {
        compression = v[0];
      } else if (attr == "tiles" && type == "tiledesc" && size == 9) {
        tileW = int64_t(uint32_t(littleEndian32(v)));
        tileH = int64_t(uint32_t(littleEndian32(v + 4)));
      }
    }
    at += size_t(size);
  }
  if (!window) return "has no dataWindow attribute";
  if (info.width <= 0 || info.height <= 0) return "has an empty data window";
  const uint64_t channels = std::max<uint64_t>(1, info.channels.size());
  if (uint64_t(info.width) > maxSamples || uint64_t(info.height) > maxSamples ||
      uint64_t(info.width) * uint64_t(info.height) * channels > maxSamples)
    return "is " + std::to_string(info.width) + "x" + std::to_string(info.height) + " with " +
           std::to_string(channels) + " channels, over the limit of " + std::to_string(maxSamples) +
           " samples";
  // Each chunk of the first part has an 8-byte entry in the offset table that follows.
  int64_t chunks = 0;
  if (tiled || (multipart && tileW > 0)) {
    if (tileW <= 0 || tileH <= 0) return "is tiled with an empty tile size";
    chunks = ((info.width + tileW - 1) / tileW) * ((info.height + tileH - 1) / tileH);
  } else {
    const int64_t lines = exrLinesPerChunk(compression);
    chunks = (info.height + lines - 1) / lines;
  }
  const size_t table = std::min(n, at);
  if (uint64_t(chunks) * 8 > n - table)
    return "needs an offset table of " + std::to_string(chunks) + " chunks (" +
           std::to_string(uint64_t(chunks) * 8) + " bytes), but only " + std::to_string(n - table) +
           " bytes follow its header (truncated file)";
  // Every chunk the table names must lie inside the file, with the data size it declares;
  // only then does OpenEXR get to allocate the image. A chunk starts with the part number
  // (multi-part files), its scanline (or four tile coordinates) and the data size.
  const size_t lead = (multipart ? 4 : 0) + (tiled || tileW > 0 ? 16 : 4);
  uint64_t data = 0;
  for (int64_t i = 0; i < chunks; ++i) {
    uint64_t offset = 0;
    for (int k = 7; k >= 0; --k) offset = (offset << 8) | b[table + size_t(i) * 8 + size_t(k)];
    const size_t end = table + size_t(chunks) * 8;
    const int32_t size = offset >= end && offset <= n && n - offset >= lead + 4
                             ? littleEndian32(b + offset + lead)
                             : -1;
    if (size < 0 || uint64_t(size) > n - offset - lead - 4)
      return "its offset table's entry " + std::to_string(i) + " names a chunk that is not " +
             "inside the file (truncated or corrupt)";
    data += uint64_t(size);
  }
  // A codec with a known best ratio cannot make the declared image from fewer bytes.
  uint64_t raw = 0;
  for (const ChannelBytes& c : sampleBytes)
    if (c.xSampling > 0 && c.ySampling > 0)
      raw += uint64_t(c.bytes) * uint64_t(info.width / c.xSampling) *
             uint64_t(info.height / c.ySampling);
  const uint64_t ratio = exrMaxRatio(compression);
  if (ratio > 0 && data * ratio + 1024 < raw)
    return "holds " + std::to_string(data) + " bytes of image data, which its compression " +
           "cannot expand to the " + std::to_string(raw) + " bytes its header declares (a " +
           "truncated, corrupt or hostile file)";
  return {};
}

}  // namespace taa
