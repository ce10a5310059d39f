// Size limits that hold on memory (docs/trust.md): the largest inputs of issue 43 run under
// `ulimit -v` of 3 GB, as the issue's bound, and end in exit 2 naming the file and the limit
// within seconds, where they once took 4 GB or more and ended in std::bad_alloc (exit 3).
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "harness/cli_fixture.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;

class MemoryLimits : public HarnessCli {
 protected:
  test::ProcessResult limited(const std::string& args) {
    const auto start = std::chrono::steady_clock::now();
    const auto r = test::runHarness(args + " ", "ulimit -v 3000000; CI=false ");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30)) << args;
    EXPECT_LT(r.output.size(), 20000u) << "a refusal, not a message per entry";
    return r;
  }
};

uint32_t pngCrc32(const std::string& bytes) {
  uint32_t c = 0xffffffffu;
  for (const unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}

std::string bigEndian32(uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A PNG whose header says width x height (colour type 0 grey or 6 RGBA, 8 bits) with just
// enough image data to inflate that far (1032:1, the structure check's bound): the grey one is
// the issue's 260 KB file of 16384x16384 pixels. The data is no zlib stream, so a reader that
// inflated it would fail, never succeed; the limit must come first.
void writeHugePngHeader(const fs::path& file, uint32_t width, uint32_t height, char colourType) {
  auto chunk = [](const std::string& kind, const std::string& data) {
    return bigEndian32(uint32_t(data.size())) + kind + data + bigEndian32(pngCrc32(kind + data));
  };
  const std::string ihdr =
      bigEndian32(width) + bigEndian32(height) + std::string{8, colourType, 0, 0, 0};
  const uint64_t raw = (uint64_t(width) * (colourType == 6 ? 4 : 1) + 1) * height;
  const size_t idat = size_t(raw / 1032 + 1024);
  std::ofstream(file, std::ios::binary)
      << std::string("\x89PNG\r\n\x1a\n", 8) << chunk("IHDR", ihdr)
      << chunk("IDAT", std::string(idat, '\0')) << chunk("IEND", "");
}

TEST_F(MemoryLimits, TenThousandShaderParamsAreOneRefusal) {
  std::string params;
  for (int i = 0; i < 10000; ++i)
    params += std::string(i ? "," : "") + R"({"name": "alpha", "value": 1})";
  writeCase("params", R"({"taa": {"shader": "user.glsl", "shader_params": [)" + params + "]}}");
  const auto r = limited("validate " + casePath("params"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("taa.shader_params: 10000 entries, over the limit of 256"),
            std::string::npos)
      << r.output;
}

TEST_F(MemoryLimits, BakeOfAHundredThousandFramesAndSixtyFourMoversIsRefused) {
  std::string movers;
  for (int i = 0; i < 64; ++i) movers += std::string(i ? "," : "") + R"({"shape": "sphere"})";
  writeCase("long", R"({"script": {"frames": 100000}, "movers": [)" + movers + "]}");
  const auto r = limited("bake " + casePath("long") + " --out " + (root_ / "track.json").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("6500000 poses, over bake's limit of 500000"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(root_ / "track.json"));
}

TEST_F(MemoryLimits, CompareRefusesImagesOverItsLimitBeforeDecoding) {
  const fs::path small = root_ / "small.png", grey = root_ / "grey.png", rgba = root_ / "rgba.png";
  writeHugePngHeader(small, 4, 4, 0);
  writeHugePngHeader(grey, 16384, 16384, 0);  // 2^28 grey samples: 4.1 GB and 106 s once
  writeHugePngHeader(rgba, 8192, 8192, 6);    // 2^28 RGBA samples: 2.5 GB once
  for (const fs::path& big : {grey, rgba}) {
    const auto r = limited("compare " + big.string() + " " + small.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(big.string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("over the limit of 134217728 samples"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace taa
