// The PNG and OpenEXR readers facing files whose length fields lie and EXRs whose channels
// are not R, G, B, A. The files come from tests/fuzz/make_corpus.py (corpus/image), which
// writes them by hand; fuzz_regressions_test replays them under the sanitizers too.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/image_io.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

fs::path corpusFile(const std::string& name) {
  return fs::path(TAA_SOURCE_DIR) / "tests/fuzz/corpus/image" / name;
}

std::string imageRefusal(const fs::path& file, const std::string& layer = "") {
  try {
    (void)readImageByName(file, layer);
  } catch (const ImageIoError& e) {
    return e.what();
  }
  return "";
}

// Each file claims far more bytes than it holds; the check before libpng and OpenEXR says
// which field (without it, libpng and OpenEXR allocated 0.2 to 2 GB first, or hung).
TEST(ImageHostile, LengthFieldsPastTheBytesPresentAreRefusedBeforeDecoding) {
  const std::pair<const char*, const char*> cases[] = {
      {"png_chunk_length_huge.png", "chunk tEXt at byte 33 claims 2147483632 bytes, but only"},
      {"png_idat_short.png", "cannot inflate to the 192000000 bytes its header declares"},
      {"exr_attribute_huge.exr", "claims 2147483632 bytes, but only"},
      {"exr_offset_outside.exr", "offset table's entry 0 names a chunk that is not inside"},
      {"exr_chunk_size_huge.exr", "offset table's entry 0 names a chunk that is not inside"},
      {"exr_window_huge.exr", "cannot expand to the 768000000 bytes its header declares"},
  };
  for (const auto& [name, says] : cases) {
    SCOPED_TRACE(name);
    const std::string why = imageRefusal(corpusFile(name));
    EXPECT_NE(why.find(name), std::string::npos) << why;
    EXPECT_NE(why.find(says), std::string::npos) << why;
    // The golden reader goes through the same checks.
    EXPECT_THROW((void)readImage(corpusFile(name)), ImageIoError);
  }
}

TEST(ImageHostile, ExrChannelsAreChosenByNameNotByPosition) {
  // Stored sorted (B, G, R); R = 0.75, G = 0.5, B = 0.25 in every pixel.
  const ReadImage bgr = readImageByName(corpusFile("exr_bgr.exr"), "");
  EXPECT_TRUE(bgr.linear);
  ASSERT_EQ(bgr.image.channels, 3);
  EXPECT_EQ(bgr.image.at(1, 2, 0), 0.75f);
  EXPECT_EQ(bgr.image.at(1, 2, 1), 0.5f);
  EXPECT_EQ(bgr.image.at(1, 2, 2), 0.25f);

  // A layer's channels are only read when the layer is named.
  EXPECT_NE(imageRefusal(corpusFile("exr_layered.exr")).find("choose a layer (diffuse) with --layer"),
            std::string::npos);
  const ReadImage layer = readImageByName(corpusFile("exr_layered.exr"), "diffuse");
  ASSERT_EQ(layer.image.channels, 3);
  EXPECT_EQ(layer.image.at(0, 0, 0), 0.75f);
  EXPECT_EQ(layer.image.at(0, 0, 2), 0.25f);
  EXPECT_NE(imageRefusal(corpusFile("exr_bgr.exr"), "specular").find("has no specular.R channel"),
            std::string::npos);

  // X, Y, Z are not colours: refused, naming what the file has.
  EXPECT_NE(imageRefusal(corpusFile("exr_xyz.exr")).find("has no R channel (its channels: X, Y, Z)"),
            std::string::npos);
}

TEST(ImageHostile, KindComesFromTheContentNotTheName) {
  const ReadImage named = readImageByName(corpusFile("exr_named_as.png"), "");
  EXPECT_TRUE(named.linear);  // an OpenEXR file, whatever its name says
  EXPECT_EQ(named.image.at(3, 3, 0), 0.75f);
  const fs::path dir = fs::path(TAA_TEST_OUT) / "image-hostile";
  fs::create_directories(dir);
  writePng(dir / "png_named_as.exr", Image(4, 4, 3, 0.5f));
  EXPECT_FALSE(readImageByName(dir / "png_named_as.exr", "").linear);
}

}  // namespace
}  // namespace taa
