// The glTF index and enum checks, by generator: one document that uses every kind of
// reference glTF 2.0 has, and every whole number in it replaced in turn by each value a
// hostile or broken exporter writes (negative, fractional, string, null, a flag, 2^31,
// 2^32 + 1, one past its array). Each must be refused naming that value's JSON path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "scene/gltf_checks.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "scene/scene_error.h"

namespace taa::scene {
namespace {

using Doc = nlohmann::json;
namespace fs = std::filesystem;

// Every array of objects that an index can point into has two entries, so "one past the
// end" (2) and a valid index other than 0 (1) are both in play.
const Doc& fullDocument() {
  static const Doc doc = Doc::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0,
    "scenes": [{"nodes": [0]}, {"nodes": [1]}],
    "nodes": [{"mesh": 0, "children": [1], "skin": 0, "camera": 1,
               "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]},
              {"mesh": 1, "translation": [0,1,0], "rotation": [0,0,0,1], "scale": [1,1,1]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 1,
                                "material": 1, "mode": 4,
                                "targets": [{"POSITION": 1}]}], "weights": [0.5]},
               {"primitives": [{"attributes": {"POSITION": 1}}]}],
    "accessors": [{"bufferView": 0, "byteOffset": 4, "componentType": 5126, "count": 3,
                   "type": "VEC3", "max": [1,1,1], "min": [-1,-1,-1]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR",
                   "sparse": {"count": 1,
                              "indices": {"bufferView": 1, "componentType": 5121},
                              "values": {"bufferView": 0, "byteOffset": 0}}}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48, "byteStride": 12,
                     "target": 34962},
                    {"buffer": 1, "byteLength": 8, "target": 34963}],
    "buffers": [{"byteLength": 48, "uri": "a.bin"}, {"byteLength": 8, "uri": "b.bin"}],
    "materials": [{"doubleSided": true, "alphaMode": "MASK", "alphaCutoff": 0.5},
                  {"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1],
                                            "baseColorTexture": {"index": 1, "texCoord": 0},
                                            "metallicFactor": 0.0, "roughnessFactor": 1.0},
                   "normalTexture": {"index": 0, "scale": 1.0},
                   "emissiveFactor": [0, 0, 0]}],
    "textures": [{"source": 0, "sampler": 1}, {"source": 1}],
    "images": [{"uri": "a.png"}, {"bufferView": 1, "mimeType": "image/png"}],
    "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 33071},
                 {}],
    "skins": [{"joints": [0, 1], "skeleton": 0, "inverseBindMatrices": 0}, {"joints": [1]}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
                {"type": "orthographic",
                 "orthographic": {"xmag": 1.0, "ymag": 1.0, "znear": 0.0, "zfar": 10.0}}],
    "animations": [{"channels": [{"sampler": 1, "target": {"node": 1, "path": "rotation"}}],
                    "samplers": [{"input": 0, "output": 1},
                                 {"input": 1, "output": 0, "interpolation": "STEP"}]},
                   {"channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}],
                    "samplers": [{"input": 0, "output": 0}]}]
  })");
  return doc;
}

const fs::path kFile = "hostile.gltf";

// "" when `doc` passes, else the message.
std::string refusal(const Doc& doc) {
  try {
    checkGltfDocument(kFile, doc);
    return "";
  } catch (const SceneError& e) {
    return e.what();
  }
}

// A JSON pointer ("/meshes/0/primitives/0/mode") as the checker writes the place
// ("meshes[0].primitives[0].mode").
std::string dotted(Doc::json_pointer p) {
  std::vector<std::string> parts;
  for (; !p.empty(); p.pop_back()) parts.insert(parts.begin(), p.back());
  std::string out;
  for (const std::string& part : parts) {
    const bool index = part.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + part + "]" : (out.empty() ? "" : ".") + part;
  }
  return out;
}

// Number arrays (positions, factors, bounds) hold values that may be anything finite;
// every other whole number in the document is an index, enum, count or offset.
bool inNumberArray(const Doc::json_pointer& p) {
  static const std::set<std::string> numbers = {"matrix", "translation", "rotation", "scale",
                                                "weights", "max", "min", "baseColorFactor",
                                                "emissiveFactor"};
  Doc::json_pointer parent = p;
  parent.pop_back();
  return !parent.empty() && numbers.count(parent.back()) > 0;
}

// The whole numbers of the document that are indices into an array of two entries.
bool isIndex(const Doc::json_pointer& p) {
  static const std::set<std::string> keys = {
      "scene", "mesh", "skin", "camera", "material", "indices", "bufferView", "buffer", "index",
      "source", "sampler", "input", "output", "node", "skeleton", "inverseBindMatrices"};
  Doc::json_pointer parent = p;
  parent.pop_back();
  const std::string up = parent.empty() ? "" : parent.back();
  if (up == "attributes" || up == "children" || up == "nodes" || up == "joints") return true;
  Doc::json_pointer grand = parent;
  if (!grand.empty()) grand.pop_back();
  if (!grand.empty() && grand.back() == "targets") return true;  // targets[i].POSITION
  return keys.count(p.back()) > 0;
}

TEST(GltfChecks, TheFullDocumentPasses) { EXPECT_EQ(refusal(fullDocument()), ""); }

TEST(GltfChecks, EveryWholeNumberRefusesEveryHostileValue) {
  const Doc flat = fullDocument().flatten();
  const std::vector<Doc> anyWhole = {-1, 0.5, "0", nullptr, true, Doc::array()};
  const std::vector<Doc> anyIndex = {2, int64_t(1) << 31, (int64_t(1) << 32) + 1,
                                      uint64_t(1) << 63, 1e300};
  int places = 0, indices = 0;
  for (const auto& [key, value] : flat.items()) {
    const Doc::json_pointer at(key);
    if (!value.is_number_integer() || inNumberArray(at)) continue;
    ++places;
    std::vector<Doc> variants = anyWhole;
    if (isIndex(at)) {
      ++indices;
      variants.insert(variants.end(), anyIndex.begin(), anyIndex.end());
    }
    for (const Doc& v : variants) {
      Doc doc = fullDocument();
      doc[at] = v;
      const std::string why = refusal(doc);
      EXPECT_NE(why.find("hostile.gltf: " + dotted(at) + " "), std::string::npos)
          << key << " = " << v.dump() << ": " << why;
    }
  }
  // The document really exercises the table: every kind of reference and enum.
  EXPECT_GE(places, 60);
  EXPECT_GE(indices, 40);
}

TEST(GltfChecks, TheIssuesExamplesAreRefusedWithTheirPath) {
  struct Example {
    const char* pointer;
    Doc value;
    const char* expected;
  };
  const std::vector<Example> examples = {
      {"/accessors/0/byteOffset", -4, "accessors[0].byteOffset is -4; it must be a whole number"},
      {"/nodes/0/matrix", Doc::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0}),
       "nodes[0].matrix has 15 numbers; glTF 2.0 gives it 16"},
      {"/materials/1/pbrMetallicRoughness/baseColorFactor", Doc::array({1, 1}),
       "baseColorFactor has 2 numbers; glTF 2.0 gives it 4"},
      {"/materials/0/doubleSided", "yes",
       "materials[0].doubleSided is the string \"yes\", not true or false"},
      {"/samplers/0/wrapS", 12345, "samplers[0].wrapS is 12345, which glTF 2.0 does not define"},
      {"/meshes/0/primitives/0/mode", 7, "mode is 7, which glTF 2.0 does not define"},
      {"/accessors/0/type", "VEC5", "accessors[0].type is the string \"VEC5\""},
      {"/nodes/1/rotation/0", 2, "nodes[1].rotation[0] is 2, outside its range"},
      {"/cameras/0/perspective/yfov", 0, "yfov is 0, outside its range (above 0)"},
      {"/animations/0/channels/0/target/path", "color", "path is the string \"color\""},
      {"/nodes/0/mesh", (int64_t(1) << 32) + 1,
       "nodes[0].mesh is 4294967297, but meshes has 2 entries, indexed 0 to 1"},
      {"/nodes/0/mesh", 0.5, "nodes[0].mesh is 0.5, not an index"},
  };
  for (const Example& e : examples) {
    Doc doc = fullDocument();
    doc[Doc::json_pointer(e.pointer)] = e.value;
    EXPECT_NE(refusal(doc).find(e.expected), std::string::npos)
        << e.pointer << ": " << refusal(doc);
  }
  Doc noAsset = fullDocument();
  noAsset.erase("asset");
  EXPECT_NE(refusal(noAsset).find("the file has no \"asset\""), std::string::npos);
  Doc textAsString = fullDocument();
  textAsString["nodes"][0]["children"] = "1";
  EXPECT_NE(refusal(textAsString).find("nodes[0].children is the string \"1\", not an array"),
            std::string::npos);
}

// An array of objects is walked by one queued cursor: every element is still visited, in file
// order (the first defect is the one named), and one that is not an object is named by index.
TEST(GltfChecks, EveryElementOfAnArrayIsVisitedInFileOrder) {
  Doc doc = fullDocument();
  for (int i = 0; i < 1000; ++i) doc["nodes"].push_back(Doc::object());
  EXPECT_EQ(refusal(doc), "");
  Doc last = doc;
  last["nodes"][1001]["mesh"] = 7;
  EXPECT_NE(refusal(last).find("nodes[1001].mesh is 7"), std::string::npos) << refusal(last);
  Doc notObject = doc;
  notObject["nodes"][600] = 3;
  EXPECT_NE(refusal(notObject).find("nodes[600] is 3, not an object"), std::string::npos)
      << refusal(notObject);
  notObject["nodes"][500]["camera"] = -1;
  EXPECT_NE(refusal(notObject).find("nodes[500].camera is -1"), std::string::npos)
      << refusal(notObject);
}

TEST(GltfChecks, AValueIsNamedNeverTheBytesAroundIt) {
  Doc doc = fullDocument();
  doc["nodes"][0]["mesh"] = std::string(5000, 'A') + "TOKEN";
  const std::string why = refusal(doc);
  EXPECT_NE(why.find("a string of 5005 characters"), std::string::npos) << why;
  EXPECT_EQ(why.find("TOKEN"), std::string::npos);
  EXPECT_THROW(parseGltfJson(kFile, "[1, 2]"), SceneError);
  try {
    parseGltfJson(kFile, R"({"asset": {"version": "2.0"}, "secret": "TOKEN)");
    FAIL() << "unterminated string accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).find("TOKEN"), std::string::npos) << e.what();
  }
}

// The checks run in the loader, before tinygltf would wrap 2^32 + 1 to 1.
TEST(GltfChecks, TheLoaderRefusesBeforeTinygltfWraps) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "gltf_checks";
  fs::create_directories(dir);
  std::ifstream in(fs::path(TAA_SOURCE_DIR) / "cases/scenes/quantized_quad.gltf");
  Doc doc = Doc::parse(in);
  const fs::path file = dir / "wrapped_index.gltf";
  Scene ok;
  std::ofstream(file) << doc.dump();
  EXPECT_NO_THROW(loadGltf(file, ok));
  doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = (int64_t(1) << 32) + 1;
  std::ofstream(file) << doc.dump();
  Scene scene;
  try {
    loadGltf(file, scene);
    FAIL() << "index 2^32 + 1 accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "meshes[0].primitives[0].attributes.POSITION is 4294967297, but accessors"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace taa::scene
