// Hostile glTF files, built here so each states its one defect: sizes, counts and offsets
// that overflow 64-bit arithmetic, images that lie about themselves, references past the
// end of their arrays, depth that would exhaust the stack, and paths that are not files.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "scene/gltf_images.h"
#include "scene/gltf_loader.h"
#include "scene/scene_error.h"
#include "support/text.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(TAA_TEST_OUT) / "gltf_hostile" / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A triangle: 36 bytes of positions in tri.bin, then whatever `extraBin` appends. The
// accessor, buffer view and the rest of the JSON come from the arguments.
fs::path writeTriangle(const fs::path& dir, const std::string& accessor,
                       const std::string& bufferViews, const std::string& extra = "",
                       const std::string& extraBin = "", const std::string& primitive = "") {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string bin(reinterpret_cast<const char*>(p), sizeof(p));
  bin += extraBin;
  std::ofstream(dir / "tri.bin", std::ios::binary) << bin;
  const fs::path file = dir / "tri.gltf";
  std::ofstream(file) << R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0})" +
                             primitive + R"(}]}],
  "buffers": [{"uri": "tri.bin", "byteLength": )" +
                             std::to_string(bin.size()) + R"(}],
  "bufferViews": )" + bufferViews +
                             R"(,
  "accessors": [)" + accessor +
                             "]" + extra + "}";
  return file;
}

const std::string kView = R"([{"buffer": 0, "byteLength": 36}])";

std::string accessor(const std::string& count, const std::string& byteOffset = "0",
                     const std::string& view = "0") {
  return R"({"bufferView": )" + view + R"(, "byteOffset": )" + byteOffset +
         R"(, "componentType": 5126, "type": "VEC3", "count": )" + count + "}";
}

std::string refusal(const fs::path& file) {
  Scene s;
  try {
    loadGltf(file, s);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

::testing::AssertionResult refused(const fs::path& file, const std::string& part) {
  const std::string msg = refusal(file);
  if (msg.empty()) return ::testing::AssertionFailure() << file << " loaded";
  if (msg.find(file.string()) == std::string::npos)
    return ::testing::AssertionFailure() << "the file is not named: " << msg;
  if (msg.find(part) == std::string::npos)
    return ::testing::AssertionFailure() << "'" << part << "' not in: " << msg;
  return ::testing::AssertionSuccess();
}

TEST(GltfHostile, TheTriangleItselfLoads) {
  Scene s;
  loadGltf(writeTriangle(scratch(), accessor("3"), kView), s);
  EXPECT_EQ(s.vertices.size(), 3u);
}

TEST(GltfHostile, AccessorCountsAndOffsetsThatOverflow) {
  const fs::path dir = scratch();
  struct Case {
    std::string accessor, views, expect;
  } cases[] = {
      // count * stride wraps to a small number.
      {accessor("1537228672809129302"), kView, "reads past the end of bufferViews[0]"},
      {accessor("3", "18446744073709551600"), kView, "reads past the end"},
      {accessor("4294967296"), kView, "reads past the end"},
      {accessor("3"),
       R"([{"buffer": 0, "byteOffset": 9223372036854775808, "byteLength": 9223372036854775808}])",
       "ends past its buffer"},
      {accessor("3"), R"([{"buffer": 0, "byteOffset": 18446744073709551615, "byteLength": 37}])",
       "ends past its buffer"},
      {accessor("3"), R"([{"buffer": 0, "byteLength": 36, "byteStride": 4}])", "byteStride of 4"},
      // No bufferView: zeros that nothing in the file backs.
      {R"({"componentType": 5126, "type": "VEC3", "count": 2147483648})", kView,
       "without a bufferView"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.accessor + " " + c.views);
    EXPECT_TRUE(refused(writeTriangle(dir, c.accessor, c.views), c.expect));
  }
}

TEST(GltfHostile, IndexAccessorPastItsView) {
  const fs::path dir = scratch();
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::ofstream(dir / "tri.bin", std::ios::binary)
      << std::string(reinterpret_cast<const char*>(p), sizeof(p)) << std::string(12, '\0');
  std::ofstream(dir / "idx.gltf")
      << R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [{"uri": "tri.bin", "byteLength": 48}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12}],
    "accessors": [)" +
             accessor("3") +
             R"(, {"bufferView": 1, "byteOffset": 8, "componentType": 5125, "type": "SCALAR", "count": 4611686018427387905}]})";
  EXPECT_TRUE(refused(dir / "idx.gltf", "reads past the end of bufferViews[1]"));
}

// A texture whose image lives in a buffer view; `image` is the image's bytes.
fs::path writeTextured(const fs::path& dir, const std::string& image, const std::string& imageView,
                       const std::string& texture = R"({"source": 0})") {
  return writeTriangle(
      dir, accessor("3"), R"([{"buffer": 0, "byteLength": 36}, )" + imageView + "]",
      R"(, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [)" +
          texture + R"(], "images": [{"bufferView": 1, "mimeType": "image/png"}])",
      image, R"(, "material": 0)");
}

std::string pngHeader(uint32_t w, uint32_t h) {
  std::string s("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (uint32_t v : {w, h})
    for (int k = 3; k >= 0; --k) s += char((v >> (8 * k)) & 0xFF);
  return s + std::string("\x08\x06\0\0\0", 5) + std::string(4, '\0');
}

TEST(GltfHostile, ImagesAreCheckedBeforeTheDecoder) {
  const fs::path dir = scratch();
  const std::string png = pngHeader(4, 4);
  const std::string view =
      R"({"buffer": 0, "byteOffset": 36, "byteLength": )" + std::to_string(png.size()) + "}";
  EXPECT_TRUE(
      refused(writeTextured(dir, png, R"({"buffer": 0, "byteOffset": 36, "byteLength": 100000})"),
              "images[0] uses bufferViews[1], which reaches byte 36 + 100000"));
  EXPECT_TRUE(refused(
      writeTextured(dir, png, R"({"buffer": 0, "byteOffset": 4000000000, "byteLength": 8})"),
      "images[0] uses bufferViews[1]"));
  EXPECT_TRUE(refused(writeTextured(dir, pngHeader(100000, 100000), view),
                      "over the limit of 8192 per side"));
  EXPECT_TRUE(refused(writeTextured(dir, pngHeader(0, 5), view), "a size of 0 x 5"));
  EXPECT_TRUE(refused(writeTextured(dir, std::string("BM") + std::string(50, '\0'), view),
                      "neither a PNG nor a JPEG"));
  const std::string jpeg("\xFF\xD8\xFF\xC0\x00\x11\x08\x7F\xFF\x7F\xFF\x03", 12);
  EXPECT_TRUE(refused(writeTextured(dir, jpeg + std::string(16, '\0'),
                                    R"({"buffer": 0, "byteOffset": 36, "byteLength": 28})"),
                      "is 32767 x 32767"));
}

// tinygltf checks a BIN chunk's length without its 8-byte header.
TEST(GltfHostile, GlbBinChunkPastTheEnd) {
  const fs::path dir = scratch();
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 24}]})";
  json.resize((json.size() + 3) / 4 * 4, ' ');
  const std::string data(16, '\0');
  const uint32_t total = uint32_t(12 + 8 + json.size() + 8 + data.size());
  std::ofstream(dir / "over.glb", std::ios::binary)
      << "glTF" << u32(2) << u32(total) << u32(uint32_t(json.size())) << "JSON" << json
      << u32(uint32_t(data.size() + 8)) << "BIN" << '\0' << data;
  EXPECT_TRUE(refused(dir / "over.glb", "BIN chunk runs past the end"));
  std::ofstream(dir / "long.glb", std::ios::binary)
      << "glTF" << u32(2) << u32(total + 100) << u32(uint32_t(json.size())) << "JSON" << json;
  EXPECT_TRUE(refused(dir / "long.glb", "total length of"));
}

TEST(GltfHostile, ImageHeadersGiveTheDecodedSizeBeforeDecoding) {
  std::string png = pngHeader(100, 50);
  auto bytes = [](const std::string& s) {
    return reinterpret_cast<const unsigned char*>(s.data());
  };
  ImageHeader h = readImageHeader(bytes(png), png.size());
  EXPECT_EQ(h.problem, "");
  EXPECT_EQ(h.decodedBytes, 100u * 50u * 4u);
  png[24] = 16;  // bit depth: tinygltf keeps 16-bit samples
  EXPECT_EQ(readImageHeader(bytes(png), png.size()).decodedBytes, 100u * 50u * 8u);
  EXPECT_NE(readImageHeader(bytes(png), 20).problem, "") << "a truncated header";
  const std::string jpeg("\xFF\xD8\xFF\xE0\x00\x04\x00\x00\xFF\xC2\x00\x11\x08\x00\x30\x00\x40\x03",
                         18);
  h = readImageHeader(bytes(jpeg), jpeg.size());
  EXPECT_EQ(h.problem, "");
  EXPECT_EQ(h.decodedBytes, 64u * 48u * 4u)
      << "skips the APP0 segment to the progressive frame header";
}

TEST(GltfHostile, TextureSourceAndSamplerOutOfRange) {
  const fs::path dir = scratch();
  const std::string png = test::readFile(fs::path(TAA_SOURCE_DIR) / "cases/scenes/alpha_leaf.png");
  ASSERT_FALSE(png.empty());
  const std::string view =
      R"({"buffer": 0, "byteOffset": 36, "byteLength": )" + std::to_string(png.size()) + "}";
  Scene ok;
  EXPECT_NO_THROW(loadGltf(writeTextured(dir, png, view), ok));
  EXPECT_TRUE(refused(writeTextured(dir, png, view, R"({"source": 7})"),
                      "textures[0].source is 7, but images has 1 entry, index 0"));
  EXPECT_TRUE(refused(writeTextured(dir, png, view, R"({"source": 0, "sampler": 3})"),
                      "textures[0].sampler is 3, but there are no samplers"));
}

// A primitive's material one past the end (the array's size, the likeliest off-by-one) is
// refused by the document's index rules, before conversion reads it; the last one loads.
TEST(GltfHostile, MaterialIndexOnePastTheEnd) {
  const fs::path dir = scratch();
  const std::string materials = R"(, "materials": [{"name": "only"}])";
  Scene ok;
  EXPECT_NO_THROW(loadGltf(writeTriangle(dir, accessor("3"), kView, materials, "", R"(, "material": 0)"), ok));
  EXPECT_TRUE(refused(writeTriangle(dir, accessor("3"), kView, materials, "", R"(, "material": 1)"),
                      "meshes[0].primitives[0].material is 1, but materials has 1 entry"));
}

TEST(GltfHostile, DeepNodeChainLoadsWithoutRecursion) {
  const fs::path dir = scratch();
  constexpr int kDepth = 100000;
  std::string nodes;
  for (int i = 0; i < kDepth; ++i)
    nodes += (i ? ", " : "") + (i + 1 < kDepth ? R"({"children": [)" + std::to_string(i + 1) + "]}"
                                               : std::string(R"({"mesh": 0})"));
  writeTriangle(dir, accessor("3"), kView);  // for tri.bin
  std::ofstream(dir / "chain.gltf")
      << R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [)" << nodes
      << R"(], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "buffers": [{"uri": "tri.bin", "byteLength": 36}], "bufferViews": )"
      << kView << R"(, "accessors": [)" << accessor("3") << "]}";
  Scene s;
  const Model m = loadGltf(dir / "chain.gltf", s);
  ASSERT_EQ(m.nodes.size(), size_t(kDepth));
  EXPECT_EQ(m.nodes.back().parent, kDepth - 2);
  EXPECT_EQ(m.nodes.back().mesh, 0);
}

TEST(GltfHostile, CyclesAreStillRefused) {
  const fs::path dir = scratch();
  writeTriangle(dir, accessor("3"), kView);
  std::ofstream(dir / "cycle.gltf") << R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
    "nodes": [{"children": [1]}, {"children": [2]}, {"children": [0]}]})";
  EXPECT_TRUE(refused(dir / "cycle.gltf", "nodes[0] is reached twice"));
}

// docs/trust.md: a cycle is refused with or without scenes (without, no root leads to it).
TEST(GltfHostile, CyclesWithoutScenesAreRefused) {
  const fs::path dir = scratch();
  writeTriangle(dir, accessor("3"), kView);
  std::ofstream(dir / "cycle.gltf") << R"({"asset": {"version": "2.0"},
    "nodes": [{"mesh": 0}, {"children": [2]}, {"children": [1]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "buffers": [{"uri": "tri.bin", "byteLength": 36}], "bufferViews": )" +
                                           kView + R"(,
    "accessors": [)" + accessor("3") + "]}";
  EXPECT_TRUE(refused(dir / "cycle.gltf", "nodes[1] is on a cycle of children"));
}

TEST(GltfHostile, OnlyGltf2IsRead) {
  const fs::path dir = scratch();
  for (const char* version : {"1.0", "3.0", "2", "2.x"}) {
    std::ofstream(dir / "old.gltf") << R"({"asset": {"version": ")" << version << R"("}})";
    EXPECT_TRUE(refused(dir / "old.gltf", "not glTF 2.x")) << version;
  }
}

TEST(GltfHostile, NonFiniteVertexAndKeyframeValuesAreRefused) {
  const fs::path dir = scratch();
  const float nan = std::numeric_limits<float>::quiet_NaN(),
              inf = std::numeric_limits<float>::infinity();
  // The triangle's last position is NaN, then infinite.
  for (const float bad : {nan, inf}) {
    const fs::path file = writeTriangle(dir, accessor("3"), kView);
    std::string bin = test::readFile(dir / "tri.bin");
    std::memcpy(bin.data() + 32, &bad, 4);
    std::ofstream(dir / "tri.bin", std::ios::binary) << bin;
    EXPECT_TRUE(refused(file, "accessors[0] ("));
    EXPECT_TRUE(refused(file, std::isnan(bad) ? "holds NaN" : "holds an infinity"));
  }
  // An animation's keyframe time: the same reader, the same refusal.
  const float times[2] = {0.0f, inf};
  const float values[6] = {0, 0, 0, 1, 0, 0};
  std::string extraBin(reinterpret_cast<const char*>(times), 8);
  extraBin.append(reinterpret_cast<const char*>(values), 24);
  const fs::path file = writeTriangle(
      dir,
      accessor("3") + R"(, {"bufferView": 1, "componentType": 5126, "type": "SCALAR", "count": 2},
      {"bufferView": 2, "componentType": 5126, "type": "VEC3", "count": 2})",
      R"([{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
          {"buffer": 0, "byteOffset": 44, "byteLength": 24}])",
      R"(, "animations": [{"samplers": [{"input": 1, "output": 2}],
          "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}])",
      extraBin);
  EXPECT_TRUE(refused(file, "accessors[1]"));
  EXPECT_TRUE(refused(file, "holds an infinity"));
}

TEST(GltfHostile, DeepJsonAndDuplicateKeysAreRefusedBeforeParsing) {
  const fs::path dir = scratch();
  std::ofstream(dir / "deep.gltf") << R"({"asset": {"version": "2.0", "extras": )"
                                   << std::string(100000, '[') << std::string(100000, ']') << "}}";
  EXPECT_TRUE(refused(dir / "deep.gltf", "nested more than 256 levels"));
  std::ofstream(dir / "dup.gltf")
      << "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": [],\n \"nodes\": [{}]}";
  EXPECT_TRUE(refused(dir / "dup.gltf", "line 3, column 2: key \"nodes\" appears twice"));
  EXPECT_TRUE(refused(dir / "dup.gltf", "first at line 2, column 2"));
}

TEST(GltfHostile, SceneThatIsNotARegularFile) {
  const fs::path dir = scratch();
  ASSERT_EQ(::mkfifo((dir / "fifo.gltf").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.glb");
  fs::create_directories(dir / "folder.gltf");
  EXPECT_TRUE(refused(dir / "fifo.gltf", "is a FIFO"));
  EXPECT_TRUE(refused(dir / "zero.glb", "is a device"));
  EXPECT_TRUE(refused(dir / "folder.gltf", "is a directory"));
  // A buffer that is a FIFO is refused by the same reader, not waited on.
  writeTriangle(dir, accessor("3"), kView);
  fs::remove(dir / "tri.bin");
  ASSERT_EQ(::mkfifo((dir / "tri.bin").c_str(), 0600), 0);
  EXPECT_TRUE(refused(dir / "tri.gltf", "is a FIFO"));
}

}  // namespace
}  // namespace taa::scene
