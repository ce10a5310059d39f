// OpenImageIO as an independent implementation of PNG and OpenEXR: what the harness's libpng and
// OpenEXR code writes, OpenImageIO must read back to the same samples; what OpenImageIO writes,
// the harness must read as OpenImageIO does; and every golden EXR must decode identically with
// both and match its manifest's pixel hash. Its own program (tests/CMakeLists.txt) so that no
// other test process loads OpenImageIO.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/image_io.h"

namespace fs = std::filesystem;
using taa::Image;

namespace {

fs::path crosscheckDir(const std::string& name) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "oiio_crosscheck" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// OpenImageIO's reading of a file as float samples, alpha as stored (no premultiplication).
Image oiioRead(const fs::path& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) throw std::runtime_error(path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image image(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data()))
    throw std::runtime_error(path.string() + ": " + in->geterror());
  return image;
}

void oiioWrite(const fs::path& path, const OIIO::ImageSpec& spec, const void* pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(spec.format, pixels)) << out->geterror();
  ASSERT_TRUE(out->close());
}

// Bit-equal samples, NaNs equal to NaNs.
void expectSameSamples(const Image& ours, const Image& theirs, const std::string& what) {
  ASSERT_EQ(ours.width, theirs.width) << what;
  ASSERT_EQ(ours.height, theirs.height) << what;
  ASSERT_EQ(ours.channels, theirs.channels) << what;
  for (size_t i = 0; i < ours.data.size(); ++i) {
    if (std::isnan(ours.data[i]) && std::isnan(theirs.data[i])) continue;
    ASSERT_EQ(std::bit_cast<uint32_t>(ours.data[i]), std::bit_cast<uint32_t>(theirs.data[i]))
        << what << " sample " << i << ": " << ours.data[i] << " vs " << theirs.data[i];
  }
}

// A frame-like image with smooth gradients, hard edges, HDR values, negatives and non-finite
// samples, so both codecs' paths (and half rounding) are exercised.
Image crosscheckPattern(int w, int h, int c) {
  Image img(w, h, c);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < c; ++k) {
        float v = float(x) / float(w) * (1.0f + float(k)) + ((x / 7 + y / 5) % 2 ? 0.3f : 0.0f);
        if ((x * 31 + y * 17 + k) % 97 == 0) v = 40.0f * float(y + 1) / 3.0f;
        if ((x + y + k) % 211 == 0) v = -0.25f;
        img.at(x, y, k) = v;
      }
  img.at(1, 1, 0) = std::numeric_limits<float>::infinity();
  img.at(2, 1, 0) = std::nanf("");
  return img;
}

}  // namespace

TEST(OiioCrosscheck, OpenImageIOReadsOurExrAndPng) {
  const fs::path dir = crosscheckDir("ours");
  for (int c = 1; c <= 4; ++c) {
    const Image img = crosscheckPattern(61, 37, c);
    const std::string n = std::to_string(c);
    taa::writeExr(dir / ("h" + n + ".exr"), img);
    taa::writeExrFloat(dir / ("f" + n + ".exr"), img);
    taa::writePng(dir / ("p" + n + ".png"), img);
    const Image half = taa::readExr(dir / ("h" + n + ".exr"));
    expectSameSamples(half, oiioRead(dir / ("h" + n + ".exr")), "half EXR " + n);
    EXPECT_EQ(taa::pixelSha256(half), taa::pixelSha256(img));
    const Image full = taa::readExr(dir / ("f" + n + ".exr"));
    expectSameSamples(full, img, "float EXR " + n + " against the written image");
    expectSameSamples(full, oiioRead(dir / ("f" + n + ".exr")), "float EXR " + n);
    expectSameSamples(taa::readImage(dir / ("p" + n + ".png")), oiioRead(dir / ("p" + n + ".png")),
                      "PNG " + n);
  }
  // A display-referred heatmap-like image, including the grey path and NaN's magenta.
  Image grey(40, 9, 1);
  for (size_t i = 0; i < grey.data.size(); ++i) grey.data[i] = float(i % 256) / 255.0f;
  grey.data[3] = std::nanf("");
  taa::writePngLinear8(dir / "grey.png", grey);
  const Image back = taa::readImage(dir / "grey.png");
  expectSameSamples(back, oiioRead(dir / "grey.png"), "grey PNG");
  EXPECT_EQ(back.channels, 3);
  EXPECT_EQ(back.at(3, 0, 0), 1.0f);
  EXPECT_EQ(back.at(3, 0, 1), 0.0f);
  EXPECT_EQ(back.at(10, 0, 2), 10.0f / 255.0f);
}

TEST(OiioCrosscheck, WeReadOpenImageIOsFilesAsItDoes) {
  const fs::path dir = crosscheckDir("theirs");
  const int w = 53, h = 29;
  for (int c : {1, 2, 3, 4}) {
    std::vector<uint8_t> b8(size_t(w * h * c));
    std::vector<uint16_t> b16(b8.size());
    for (size_t i = 0; i < b8.size(); ++i) {
      b8[i] = uint8_t((i * 37) % 256);
      b16[i] = uint16_t((i * 2654435761u) >> 16);
    }
    const std::string n = std::to_string(c);
    oiioWrite(dir / ("u8_" + n + ".png"), OIIO::ImageSpec(w, h, c, OIIO::TypeDesc::UINT8),
              b8.data());
    oiioWrite(dir / ("u16_" + n + ".png"), OIIO::ImageSpec(w, h, c, OIIO::TypeDesc::UINT16),
              b16.data());
    expectSameSamples(taa::readImage(dir / ("u8_" + n + ".png")),
                      oiioRead(dir / ("u8_" + n + ".png")), "8-bit PNG " + n);
    expectSameSamples(taa::readImage(dir / ("u16_" + n + ".png")),
                      oiioRead(dir / ("u16_" + n + ".png")), "16-bit PNG " + n);
    const Image src = crosscheckPattern(w, h, c);
    for (const char* compression : {"zip", "piz", "none"}) {
      OIIO::ImageSpec spec(w, h, c, OIIO::TypeDesc::HALF);
      spec.attribute("compression", compression);
      const fs::path p = dir / ("e" + n + compression + ".exr");
      std::vector<uint16_t> halves(src.data.size());
      for (size_t i = 0; i < halves.size(); ++i) halves[i] = taa::floatToHalfBits(src.data[i]);
      oiioWrite(p, spec, halves.data());
      expectSameSamples(taa::readExr(p), oiioRead(p), std::string("EXR ") + compression + " " + n);
    }
  }
  // Tiled float EXR with a data window away from the origin.
  OIIO::ImageSpec tiled(w, h, 3, OIIO::TypeDesc::FLOAT);
  tiled.tile_width = 16;
  tiled.tile_height = 16;
  tiled.x = 5;
  tiled.y = -3;
  const Image src = crosscheckPattern(w, h, 3);
  oiioWrite(dir / "tiled.exr", tiled, src.data.data());
  const Image ours = taa::readExr(dir / "tiled.exr");
  expectSameSamples(ours, oiioRead(dir / "tiled.exr"), "tiled EXR");
  expectSameSamples(ours, src, "tiled EXR against its source");
}

// The goldens were written by OpenImageIO before the harness wrote EXR itself: both readers must
// give every stored frame the pixels its manifest's hash names.
TEST(OiioCrosscheck, EveryGoldenDecodesIdenticallyAndMatchesItsManifest) {
  size_t frames = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(TAA_SOURCE_DIR) / "goldens")) {
    std::ifstream in(entry.path() / "manifest.json");
    if (!in) continue;
    const auto manifest = nlohmann::json::parse(in);
    for (const auto& f : manifest.at("frames")) {
      const fs::path file = entry.path() / f.at("file").get<std::string>();
      const Image ours = taa::readExr(file);
      expectSameSamples(ours, oiioRead(file), file.string());
      EXPECT_EQ(taa::pixelSha256(ours), f.at("sha256").get<std::string>()) << file;
      ++frames;
    }
  }
  EXPECT_GE(frames, 50u);  // the check must not pass by finding nothing
}
