#include "core/image_io.h"

#include <Imath/half.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/sha256.h"

namespace fs = std::filesystem;
using taa::Image;

namespace {

float imathHalfToFloat(uint16_t bits) {
  Imath::half h;
  h.setBits(bits);
  return float(h);
}

fs::path scratchDir(const std::string& name) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "image_io" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string fileBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every sample exactly representable in half, mixing signs, subnormals and large values.
Image halfExactImage(int w, int h, int c) {
  Image img(w, h, c);
  for (size_t i = 0; i < img.data.size(); ++i) {
    const uint16_t bits = uint16_t((i * 2654435761u) >> 7) & 0x7bffu;  // finite halves only
    img.data[i] = taa::halfBitsToFloat(uint16_t(bits | ((i & 1) ? 0x8000u : 0u)));
  }
  return img;
}

size_t entriesIn(const fs::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(ImageIoHalf, MatchesImathForEveryHalfAndMidpoints) {
  // Every half value converts back to itself, and the midpoints between neighbours (where ties to
  // even matter) round the way OpenEXR's own Imath::half does.
  for (uint32_t bits = 0; bits < 0x10000u; ++bits) {
    const uint16_t h = uint16_t(bits);
    const float f = taa::halfBitsToFloat(h);
    if (std::isnan(f)) {
      EXPECT_TRUE(std::isnan(imathHalfToFloat(h))) << bits;
      EXPECT_TRUE(std::isnan(taa::halfRound(f)));
      continue;
    }
    ASSERT_EQ(std::bit_cast<uint32_t>(f), std::bit_cast<uint32_t>(imathHalfToFloat(h))) << bits;
    ASSERT_EQ(taa::floatToHalfBits(f), h) << bits;
    const float next = std::nextafter(f, std::copysign(std::numeric_limits<float>::infinity(), f));
    for (float probe :
         {next, f * 1.0001f, f + (taa::halfBitsToFloat(uint16_t(h + 1)) - f) * 0.5f}) {
      if (std::isnan(probe)) continue;
      ASSERT_EQ(taa::floatToHalfBits(probe), Imath::half(probe).bits()) << bits << " " << probe;
    }
  }
}

TEST(ImageIoHalf, RoundsOverflowAndTinyValues) {
  EXPECT_EQ(taa::halfRound(65504.0f), 65504.0f);
  EXPECT_EQ(taa::halfRound(65519.0f), 65504.0f);
  EXPECT_TRUE(std::isinf(taa::halfRound(65520.0f)));
  EXPECT_TRUE(std::isinf(taa::halfRound(1e30f)));
  EXPECT_EQ(taa::halfRound(1e-10f), 0.0f);
  EXPECT_EQ(taa::halfRound(1.0f + 1.0f / 4096.0f), 1.0f);  // tie rounds to even
  EXPECT_EQ(taa::halfRound(0.1f), 0.0999755859375f);
  EXPECT_EQ(taa::floatToHalfBits(-0.0f), 0x8000u);
}

TEST(ImageIoExr, RoundTripIsExactForHalfValues) {
  const fs::path dir = scratchDir("roundtrip");
  for (int channels = 1; channels <= 4; ++channels) {
    const Image img = halfExactImage(7, 5, channels);
    const fs::path p = dir / ("rt" + std::to_string(channels) + ".exr");
    taa::writeExr(p, img);
    const Image back = taa::readExr(p);
    ASSERT_TRUE(back.sameShape(img)) << channels;
    for (size_t i = 0; i < img.data.size(); ++i) {
      ASSERT_EQ(std::bit_cast<uint32_t>(back.data[i]), std::bit_cast<uint32_t>(img.data[i])) << i;
    }
    EXPECT_EQ(taa::pixelSha256(back), taa::pixelSha256(img));
  }
  EXPECT_EQ(entriesIn(dir), 4u);  // no temporary files left behind
}

TEST(ImageIoExr, RoundTripEqualsHalfRoundAndKeepsNonFinite) {
  const fs::path dir = scratchDir("nonexact");
  Image img(4, 2, 4);
  const float inf = std::numeric_limits<float>::infinity();
  const float values[] = {0.1f, 1.0f / 3.0f, 1e5f, -inf, inf, std::nanf(""), 1e-9f, 123.456f};
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = values[i % 8] * float(1 + i / 8);
  taa::writeExr(dir / "x.exr", img);
  const Image back = taa::readExr(dir / "x.exr");
  ASSERT_TRUE(back.sameShape(img));
  for (size_t i = 0; i < img.data.size(); ++i) {
    const float expected = taa::halfRound(img.data[i]);
    if (std::isnan(expected)) {
      EXPECT_TRUE(std::isnan(back.data[i])) << i;
    } else {
      EXPECT_EQ(back.data[i], expected) << i;
    }
  }
  EXPECT_EQ(taa::pixelSha256(back), taa::pixelSha256(img));
}

TEST(ImageIoExr, ReadingMissingOrNonExrFileNamesIt) {
  const fs::path dir = scratchDir("missing");
  try {
    taa::readExr(dir / "nope.exr");
    FAIL() << "expected ImageIoError";
  } catch (const taa::ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("nope.exr"), std::string::npos) << e.what();
    EXPECT_EQ(e.path(), dir / "nope.exr");
  }
  taa::writePngLinear8(dir / "a.png", Image(2, 2, 3, 0.5f));
  EXPECT_THROW(taa::readExr(dir / "a.png"), taa::ImageIoError);
}

// toDisplaySrgb answers halves from a table: every half that is not NaN (both signs, zero,
// subnormals, Inf) and the floats either side of it, which the table must not answer, map to
// the very bits displayChannel gives.
TEST(ImageIoPng, DisplayTableGivesTheCurvesOwnValues) {
  std::vector<float> values;
  for (uint32_t bits = 0; bits < 0x10000u; ++bits) {
    const float h = taa::halfBitsToFloat(uint16_t(bits));
    if (std::isnan(h)) continue;
    values.insert(values.end(), {h, std::nextafter(h, -INFINITY), std::nextafter(h, INFINITY)});
  }
  Image img(int(values.size()), 1, 1);
  img.data = values;
  const Image d = taa::toDisplaySrgb(img);
  for (size_t i = 0; i < values.size(); ++i) {
    const float want = taa::displayChannel(values[i]);
    ASSERT_EQ(std::bit_cast<uint32_t>(d.data[i * 3]), std::bit_cast<uint32_t>(want))
        << "linear " << values[i] << " (bits " << std::hex << std::bit_cast<uint32_t>(values[i]) << ")";
  }
}

TEST(ImageIoPng, TonemapsWithReinhardAndSrgb) {
  Image hdr(6, 1, 4);
  const float inf = std::numeric_limits<float>::infinity();
  const float rgb[6][3] = {{0, 0, 0},
                           {1, 1, 1},
                           {-2, 0.25f, 3},
                           {inf, -inf, 0},
                           {std::nanf(""), 0, 0},
                           {1e6f, 0.004f, 0.02f}};
  for (int x = 0; x < 6; ++x) {
    for (int c = 0; c < 3; ++c) hdr.at(x, 0, c) = rgb[x][c];
    hdr.at(x, 0, 3) = 0.0f;  // alpha must not matter
  }
  const Image d = taa::toDisplaySrgb(hdr);
  ASSERT_EQ(d.channels, 3);
  auto srgb = [](double l) {
    return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
  };
  EXPECT_EQ(d.at(0, 0, 0), 0.0f);
  EXPECT_NEAR(d.at(1, 0, 1), srgb(0.5), 1e-6);
  EXPECT_EQ(d.at(2, 0, 0), 0.0f);
  EXPECT_NEAR(d.at(2, 0, 1), srgb(0.2), 1e-6);
  EXPECT_NEAR(d.at(2, 0, 2), srgb(0.75), 1e-6);
  EXPECT_EQ(d.at(3, 0, 0), 1.0f);
  EXPECT_EQ(d.at(3, 0, 1), 0.0f);
  EXPECT_EQ(d.at(4, 0, 0), 1.0f);  // NaN pixel -> magenta
  EXPECT_EQ(d.at(4, 0, 1), 0.0f);
  EXPECT_EQ(d.at(4, 0, 2), 1.0f);
  EXPECT_NEAR(d.at(5, 0, 1), srgb(0.004 / 1.004), 1e-6);

  const fs::path dir = scratchDir("png");
  taa::writePng(dir / "t.png", hdr);
  const Image back = taa::readImage(dir / "t.png");
  ASSERT_EQ(back.width, 6);
  ASSERT_EQ(back.height, 1);
  ASSERT_EQ(back.channels, 3);
  for (int x = 0; x < 6; ++x) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(back.at(x, 0, c) * 255.0f, std::round(d.at(x, 0, c) * 255.0f), 1e-3) << x << c;
    }
  }
}

TEST(ImageIoPng, Linear8WritesValuesUnchangedAndClamped) {
  const fs::path dir = scratchDir("linear8");
  Image img(3, 1, 3);
  const float v[9] = {0.0f, 0.5f, 1.0f, -1.0f, 2.0f, 0.2f, 0.25f, 0.75f, 0.999f};
  std::copy(v, v + 9, img.data.begin());
  taa::writePngLinear8(dir / "l.png", img);
  const Image back = taa::readImage(dir / "l.png");
  ASSERT_EQ(back.channels, 3);
  const int expected[9] = {0, 128, 255, 0, 255, 51, 64, 191, 255};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(back.data[size_t(i)] * 255.0f, expected[i], 1e-3) << i;
}

TEST(ImageIoAtomic, FailedWriteLeavesPreviousFileAndNoTemporary) {
  const fs::path dir = scratchDir("atomic");
  const fs::path target = dir / "golden.exr";
  taa::writeExr(target, Image(3, 3, 4, 0.5f));
  const std::string before = fileBytes(target);

  // Invalid images fail before anything touches the disk.
  EXPECT_THROW(taa::writeExr(target, Image(0, 3, 4)), taa::ImageIoError);
  EXPECT_THROW(taa::writeExr(target, Image(2, 2, 5)), taa::ImageIoError);
  EXPECT_EQ(fileBytes(target), before);

  // A directory squatting on the name makes the final rename fail after the temporary file was
  // fully written: the temporary must be cleaned up and the directory left alone.
  const fs::path squatted = dir / "squatted.exr";
  fs::create_directories(squatted / "keep");
  // A file-system failure is the environment's (exit 3), not the image's.
  EXPECT_THROW(taa::writeExr(squatted, Image(2, 2, 4, 1.0f)), taa::ImageWriteError);
  EXPECT_TRUE(fs::is_directory(squatted / "keep"));

  // An unwritable path (a parent that is a regular file) fails for root too.
  std::ofstream(dir / "plain.txt") << "x";
  try {
    taa::writePng(dir / "plain.txt" / "sub.png", Image(2, 2, 3));
    FAIL() << "expected ImageWriteError";
  } catch (const taa::ImageWriteError& e) {
    EXPECT_NE(std::string(e.what()).find("sub.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(fileBytes(target), before);
  EXPECT_EQ(entriesIn(dir), 3u);  // golden.exr, squatted.exr/, plain.txt
}

TEST(ImageIoAtomic, ReadOnlyFolderLeavesPreviousFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  const fs::path dir = scratchDir("readonly");
  const fs::path target = dir / "golden.png";
  taa::writePng(target, Image(2, 2, 3, 0.25f));
  const std::string before = fileBytes(target);
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(taa::writePng(target, Image(2, 2, 3, 4.0f)), taa::ImageWriteError);
  fs::permissions(dir, fs::perms::owner_all);
  EXPECT_EQ(fileBytes(target), before);
  EXPECT_EQ(entriesIn(dir), 1u);
}

TEST(ImageIoSha, StableAndSensitiveToOneHalfUlp) {
  Image img(3, 2, 4);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = float(i) * 0.125f;
  const std::string h = taa::pixelSha256(img);
  EXPECT_EQ(h.size(), 64u);
  EXPECT_EQ(taa::pixelSha256(img), h);

  // Hand-built byte stream per the header's definition.
  std::string bytes;
  for (float v : img.data) {
    const uint16_t b = taa::floatToHalfBits(v);
    bytes.push_back(char(b & 0xff));
    bytes.push_back(char(b >> 8));
  }
  EXPECT_EQ(h, taa::sha256Hex(bytes.data(), bytes.size()));

  // Changes below half precision are invisible; one half ulp is not.
  Image same = img;
  same.data[5] = std::nextafter(same.data[5], 10.0f);
  EXPECT_EQ(taa::pixelSha256(same), h);
  Image bumped = img;
  bumped.data[5] = taa::halfBitsToFloat(uint16_t(taa::floatToHalfBits(bumped.data[5]) + 1));
  EXPECT_NE(taa::pixelSha256(bumped), h);

  // Known answer: one 0.0 sample is the two bytes 00 00.
  EXPECT_EQ(taa::pixelSha256(Image(1, 1, 1, 0.0f)),
            "96a296d224f285c67bee93c30f8a309157f0daa35dc5b87e410b78630a09cfc7");
}

namespace taa {
namespace {

TEST(ImageIoExr, FloatWriterKeepsEveryBitThatHalfWouldLose) {
  const fs::path dir = scratchDir("float");
  Image depth(5, 3, 1);
  for (size_t i = 0; i < depth.data.size(); ++i)
    depth.data[i] = 0.5f + 1e-6f * float(i);  // below half's step
  writeExrFloat(dir / "depth.exr", depth);
  const Image back = readExr(dir / "depth.exr");
  ASSERT_TRUE(back.sameShape(depth));
  EXPECT_EQ(back.data, depth.data);
  writeExr(dir / "depth_half.exr", depth);
  EXPECT_NE(readExr(dir / "depth_half.exr").data,
            depth.data);  // the half writer would have lost them
}

}  // namespace
}  // namespace taa

namespace taa {
namespace {

TEST(ImageIoBytes, FilesAreAFunctionOfTheirPixels) {
  const fs::path dir = scratchDir("bytes");
  const Image img = halfExactImage(33, 17, 4);
  writeExr(dir / "a.exr", img);
  writeExr(dir / "b.exr", img);
  writePng(dir / "a.png", img);
  writePng(dir / "b.png", img);
  EXPECT_EQ(fileBytes(dir / "a.exr"), fileBytes(dir / "b.exr"));
  EXPECT_EQ(fileBytes(dir / "a.png"), fileBytes(dir / "b.png"));
  // No wall-clock or software stamp (OpenImageIO wrote DateTime and Software into every EXR).
  for (const char* stamp : {"DateTime", "capDate", "Software", "tIME"}) {
    EXPECT_EQ(fileBytes(dir / "a.exr").find(stamp), std::string::npos) << stamp;
    EXPECT_EQ(fileBytes(dir / "a.png").find(stamp), std::string::npos) << stamp;
  }
  Image other = img;
  other.data[7] = halfBitsToFloat(uint16_t(floatToHalfBits(other.data[7]) ^ 1u));
  writeExr(dir / "c.exr", other);
  EXPECT_NE(fileBytes(dir / "c.exr"), fileBytes(dir / "a.exr"));
}

TEST(ImageIoBytes, TruncatedAndForeignFilesAreErrorsNamingTheFile) {
  const fs::path dir = scratchDir("broken");
  writeExr(dir / "whole.exr", halfExactImage(40, 30, 3));
  writePngLinear8(dir / "whole.png", Image(40, 30, 3, 0.5f));
  for (const char* name : {"whole.exr", "whole.png"}) {
    const std::string bytes = fileBytes(dir / name);
    for (size_t keep : {size_t(4), size_t(40), bytes.size() / 2, bytes.size() - 1}) {
      const fs::path cut = dir / ("cut_" + std::to_string(keep) + "_" + name);
      std::ofstream(cut, std::ios::binary) << bytes.substr(0, keep);
      try {
        (void)readImage(cut);
        ADD_FAILURE() << cut << " read without error";
      } catch (const ImageIoError& e) {
        EXPECT_NE(std::string(e.what()).find(cut.filename().string()), std::string::npos)
            << e.what();
      }
    }
  }
  std::ofstream(dir / "text.png") << "not an image at all";
  try {
    (void)readImage(dir / "text.png");
    ADD_FAILURE() << "a text file read as an image";
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("neither OpenEXR nor PNG"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)readImage(dir), ImageIoError);  // a folder
}

TEST(ImageIoPng, ReadsSixteenBitAndGreyAlphaAsStored) {
  // The harness writes only 8-bit RGB, so a 16-bit grey + alpha file is made by hand: IHDR 2x1,
  // depth 16, colour type 4; one stored (uncompressed) zlib block holding filter byte 0 and the
  // big-endian (grey, alpha) pairs (0x0000, 0xffff), (0x8000, 0x4000); IEND.
  const fs::path dir = scratchDir("png16");
  const unsigned char png[] = {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00,
                               0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00,
                               0x00, 0x01, 0x10, 0x04, 0x00, 0x00, 0x00, 0x0e, 0xbb, 0x6b, 0x42,
                               0x00, 0x00, 0x00, 0x14, 0x49, 0x44, 0x41, 0x54, 0x78, 0x01, 0x01,
                               0x09, 0x00, 0xf6, 0xff, 0x00, 0x00, 0x00, 0xff, 0xff, 0x80, 0x00,
                               0x40, 0x00, 0x0d, 0x7e, 0x02, 0xbf, 0xcc, 0x09, 0xe1, 0xa5, 0x00,
                               0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  std::ofstream(dir / "ga16.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png), sizeof(png));
  const Image img = readImage(dir / "ga16.png");
  ASSERT_EQ(img.width, 2);
  ASSERT_EQ(img.height, 1);
  ASSERT_EQ(img.channels, 2);
  EXPECT_EQ(img.data[0], 0.0f);
  EXPECT_EQ(img.data[1], 1.0f);
  EXPECT_EQ(img.data[2], float(0x8000) / 65535.0f);
  EXPECT_EQ(img.data[3], float(0x4000) / 65535.0f);
}

}  // namespace
}  // namespace taa
