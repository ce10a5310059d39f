#include "core/exr_codec.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfPartType.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <limits>
#include <vector>

#include "core/image_checks.h"
#include "core/image_io.h"

namespace taa::exr {
namespace {

constexpr const char* kExrChannelNames[4] = {"R", "G", "B", "A"};

// Reads from bytes already in memory: the file is read once, with the size limit the caller
// applied, and OpenEXR's reads past the end become an exception instead of a short read.
class ExrMemoryIn final : public Imf::IStream {
 public:
  explicit ExrMemoryIn(std::string_view bytes) : Imf::IStream("memory"), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || uint64_t(n) > bytes_.size() - pos_)
      throw ExrError("the file ends early (truncated)");
    std::memcpy(c, bytes_.data() + pos_, size_t(n));
    pos_ += uint64_t(n);
    return pos_ < bytes_.size();
  }
  uint64_t tellg() override { return pos_; }
  void seekg(uint64_t pos) override { pos_ = std::min<uint64_t>(pos, bytes_.size()); }

 private:
  std::string_view bytes_;
  uint64_t pos_ = 0;
};

// OpenEXR seeks back to fill in the line offset table, so writes may overwrite earlier bytes.
class ExrMemoryOut final : public Imf::OStream {
 public:
  ExrMemoryOut() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (pos_ + size_t(n) > bytes.size()) bytes.resize(pos_ + size_t(n));
    std::memcpy(bytes.data() + pos_, c, size_t(n));
    pos_ += size_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = size_t(pos); }
  std::string bytes;

 private:
  size_t pos_ = 0;
};

int exrChannelRank(const std::string& name) {
  for (int i = 0; i < 4; ++i)
    if (name == kExrChannelNames[i]) return i;
  return 4;
}

// LAYER.R, LAYER.G, LAYER.B, LAYER.A of `names`, those present in that order; R is required.
std::vector<std::string> exrChannelsByName(const std::vector<std::string>& names,
                                           const std::string& layer) {
  const std::string prefix = layer.empty() ? "" : layer + ".";
  std::vector<std::string> out;
  for (const char* c : kExrChannelNames)
    if (std::find(names.begin(), names.end(), prefix + c) != names.end()) out.push_back(prefix + c);
  if (out.empty() || out[0] != prefix + "R") {
    std::string list, layers;
    for (const auto& n : names) {
      list += (list.empty() ? "" : ", ") + n;
      const auto dot = n.rfind('.');
      if (dot != std::string::npos && layers.find(n.substr(0, dot)) == std::string::npos)
        layers += (layers.empty() ? "" : ", ") + n.substr(0, dot);
    }
    throw ExrError("has no " + prefix + "R channel (its channels: " + list + ")" +
                   (layers.empty() ? std::string("; channels are chosen by name, R, G, B and A")
                                   : "; choose a layer (" + layers + ") with --layer"));
  }
  return out;
}

}  // namespace

bool hasExrMagic(std::string_view bytes) {
  static const unsigned char magic[4] = {0x76, 0x2f, 0x31, 0x01};
  return bytes.size() >= 4 && std::memcmp(bytes.data(), magic, 4) == 0;
}

std::string encode(const Image& image, bool halfFloat) {
  const int channels = image.channels;
  std::vector<uint16_t> halves(halfFloat ? image.data.size() : 0);
  for (size_t i = 0; i < halves.size(); ++i) halves[i] = floatToHalfBits(image.data[i]);
  try {
    Imf::Header header(image.width, image.height);
    // ZIP is lossless and deterministic; the lossy EXR codecs would break exact comparisons.
    header.compression() = Imf::ZIP_COMPRESSION;
    const Imf::PixelType type = halfFloat ? Imf::HALF : Imf::FLOAT;
    const size_t sampleBytes = halfFloat ? 2 : 4;
    const char* base = halfFloat ? reinterpret_cast<const char*>(halves.data())
                                 : reinterpret_cast<const char*>(image.data.data());
    Imf::FrameBuffer frame;
    for (int c = 0; c < channels; ++c) {
      header.channels().insert(kExrChannelNames[c], Imf::Channel(type));
      frame.insert(kExrChannelNames[c],
                   Imf::Slice(type, const_cast<char*>(base) + size_t(c) * sampleBytes,
                              sampleBytes * size_t(channels),
                              sampleBytes * size_t(channels) * size_t(image.width)));
    }
    ExrMemoryOut out;
    {
      Imf::OutputFile file(out, header, 1);
      file.setFrameBuffer(frame);
      file.writePixels(image.height);
    }
    return std::move(out.bytes);
  } catch (const ExrError&) {
    throw;
  } catch (const std::exception& e) {
    throw ExrError(std::string("OpenEXR could not encode it: ") + e.what());
  }
}

Image decode(std::string_view bytes, uint64_t maxSamples, const std::string* layer) {
  if (!hasExrMagic(bytes)) throw ExrError("not an OpenEXR file (no OpenEXR magic number)");
  ExrHeaderInfo info;
  if (const std::string why = exrStructureProblem(bytes, maxSamples, info); !why.empty())
    throw ExrError(why);
  try {
    ExrMemoryIn in(bytes);
    Imf::InputFile file(in, 1);
    const Imf::Header& header = file.header();
    if (header.hasType() && Imf::isDeepData(header.type()))
      throw ExrError("holds deep data, which is not supported; flatten it first");
    const Imath::Box2i window = header.dataWindow();
    const int64_t width = int64_t(window.max.x) - window.min.x + 1;
    const int64_t height = int64_t(window.max.y) - window.min.y + 1;
    std::vector<std::string> names;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
      if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
        throw ExrError(std::string("channel ") + it.name() +
                       " is subsampled, which is not supported");
      names.emplace_back(it.name());
    }
    std::stable_sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
      return exrChannelRank(a) < exrChannelRank(b);
    });
    if (layer) names = exrChannelsByName(names, *layer);
    if (width <= 0 || height <= 0 || names.empty())
      throw ExrError("has an empty data window or no channels");
    if (uint64_t(width) * uint64_t(height) * names.size() > maxSamples)
      throw ExrError("is " + std::to_string(width) + "x" + std::to_string(height) + " with " +
                     std::to_string(names.size()) + " channels, over the limit of " +
                     std::to_string(maxSamples) + " samples");
    Image image(int(width), int(height), int(names.size()));
    const size_t xStride = sizeof(float) * names.size();
    const size_t yStride = xStride * size_t(width);
    // OpenEXR addresses a slice by absolute pixel coordinates; shift the base so the data
    // window's corner lands on the first sample. Done in integers: the pointer itself may
    // point outside the buffer for a window far from the origin.
    const uintptr_t origin = reinterpret_cast<uintptr_t>(image.data.data()) -
                             uintptr_t(window.min.x) * xStride - uintptr_t(window.min.y) * yStride;
    Imf::FrameBuffer frame;
    for (size_t c = 0; c < names.size(); ++c)
      frame.insert(names[c],
                   Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(origin + c * sizeof(float)),
                              xStride, yStride));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const ExrError&) {
    throw;
  } catch (const std::exception& e) {
    throw ExrError(std::string("OpenEXR could not decode it: ") + e.what());
  }
}

}  // namespace taa::exr
