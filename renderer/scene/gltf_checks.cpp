#include "scene/gltf_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/json_guard.h"
#include "scene/scene_error.h"

namespace taa::scene {
namespace {

using nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Kind {
  Index,         // a whole number in [0, size of `target`)
  IndexList,     // an array of them
  IndexMap,      // an object whose every value is one (primitive attributes)
  IndexMapList,  // an array of such objects (morph targets)
  Whole,         // a whole number in [lo, hi]
  Code,          // a whole number among `codes`
  Name,          // a string among `names`
  Flag,          // true or false
  Number,        // a finite number in [lo, hi]
  Numbers,       // an array of exactly `length` such numbers (`length` 0: any length)
  Text,          // a string
  Object,        // an object, checked by the rules at its path
  Objects,       // an array of objects, each checked by the rules at its path
};

struct Rule {
  std::string_view at;   // the schema path of the object holding `key` ("" for the root)
  std::string_view key;  // the key in that object
  Kind kind;
  bool required = false;
  // Index kinds: the root array indexed; kAnimationSamplers: the enclosing animation's own.
  std::string_view target = {};
  double lo = -kInf, hi = kInf;
  bool aboveLo = false;  // lo itself is outside (a field of view, a near plane)
  size_t length = 0;
  std::vector<int64_t> codes = {};
  std::vector<std::string_view> names = {};

  Rule& req() { return required = true, *this; }
  Rule& into(std::string_view list) { return target = list, *this; }
  Rule& from(double l, double h = kInf) { return lo = l, hi = h, *this; }
  Rule& above(double l) { return lo = l, aboveLo = true, *this; }
  Rule& count(size_t n) { return length = n, *this; }
  Rule& among(std::vector<int64_t> c) { return codes = std::move(c), *this; }
  Rule& oneOf(std::vector<std::string_view> n) { return names = std::move(n), *this; }
};

Rule rule(std::string_view at, std::string_view key, Kind kind) {
  return Rule{at, key, kind};
}

constexpr std::string_view kAnimationSamplers = "samplers of animation";

// Every key of glTF 2.0's core schema that the loader reads, and the indices of the
// compression extensions it supports, with its type and range.
std::vector<Rule> makeRules() {
  using K = Kind;
  const std::vector<int64_t> wraps = {33071, 33648, 10497};
  std::vector<Rule> r = {
      rule("", "asset", K::Object).req(),
      rule("", "scene", K::Index).into("scenes"),
      rule("asset", "version", K::Text).req(),
      rule("accessors", "bufferView", K::Index).into("bufferViews"),
      rule("accessors", "byteOffset", K::Whole).from(0),
      rule("accessors", "componentType", K::Code).req().among({5120, 5121, 5122, 5123, 5125, 5126}),
      rule("accessors", "normalized", K::Flag),
      rule("accessors", "count", K::Whole).req().from(1),
      rule("accessors", "type", K::Name)
          .req()
          .oneOf({"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"}),
      rule("accessors", "max", K::Numbers),
      rule("accessors", "min", K::Numbers),
      rule("accessors", "sparse", K::Object),
      rule("accessors.sparse", "count", K::Whole).req().from(1),
      rule("accessors.sparse", "indices", K::Object).req(),
      rule("accessors.sparse", "values", K::Object).req(),
      rule("accessors.sparse.indices", "bufferView", K::Index).req().into("bufferViews"),
      rule("accessors.sparse.indices", "byteOffset", K::Whole).from(0),
      rule("accessors.sparse.indices", "componentType", K::Code).req().among({5121, 5123, 5125}),
      rule("accessors.sparse.values", "bufferView", K::Index).req().into("bufferViews"),
      rule("accessors.sparse.values", "byteOffset", K::Whole).from(0),
      rule("animations", "channels", K::Objects).req(),
      rule("animations", "samplers", K::Objects).req(),
      rule("animations.channels", "sampler", K::Index).req().into(kAnimationSamplers),
      rule("animations.channels", "target", K::Object).req(),
      rule("animations.channels.target", "node", K::Index).into("nodes"),
      rule("animations.channels.target", "path", K::Name)
          .req()
          .oneOf({"translation", "rotation", "scale", "weights"}),
      rule("animations.samplers", "input", K::Index).req().into("accessors"),
      rule("animations.samplers", "output", K::Index).req().into("accessors"),
      rule("animations.samplers", "interpolation", K::Name)
          .oneOf({"LINEAR", "STEP", "CUBICSPLINE"}),
      rule("buffers", "uri", K::Text),
      rule("buffers", "byteLength", K::Whole).req().from(1),
      rule("bufferViews", "buffer", K::Index).req().into("buffers"),
      rule("bufferViews", "byteOffset", K::Whole).from(0),
      rule("bufferViews", "byteLength", K::Whole).req().from(1),
      rule("bufferViews", "byteStride", K::Whole).from(4, 252),
      rule("bufferViews", "target", K::Code).among({34962, 34963}),
      rule("bufferViews", "extensions", K::Object),
      rule("bufferViews.extensions", "EXT_meshopt_compression", K::Object),
      rule("bufferViews.extensions.EXT_meshopt_compression", "buffer", K::Index)
          .req()
          .into("buffers"),
      rule("cameras", "type", K::Name).req().oneOf({"perspective", "orthographic"}),
      rule("cameras", "perspective", K::Object),
      rule("cameras", "orthographic", K::Object),
      rule("cameras.perspective", "yfov", K::Number).req().above(0),
      rule("cameras.perspective", "znear", K::Number).req().above(0),
      rule("cameras.perspective", "zfar", K::Number).above(0),
      rule("cameras.perspective", "aspectRatio", K::Number).above(0),
      rule("cameras.orthographic", "xmag", K::Number).req(),
      rule("cameras.orthographic", "ymag", K::Number).req(),
      rule("cameras.orthographic", "zfar", K::Number).req().above(0),
      rule("cameras.orthographic", "znear", K::Number).req().from(0),
      rule("images", "uri", K::Text),
      rule("images", "mimeType", K::Text),
      rule("images", "bufferView", K::Index).into("bufferViews"),
      rule("materials", "pbrMetallicRoughness", K::Object),
      rule("materials", "normalTexture", K::Object),
      rule("materials", "occlusionTexture", K::Object),
      rule("materials", "emissiveTexture", K::Object),
      rule("materials", "emissiveFactor", K::Numbers).from(0, 1).count(3),
      rule("materials", "alphaMode", K::Name).oneOf({"OPAQUE", "MASK", "BLEND"}),
      rule("materials", "alphaCutoff", K::Number).from(0),
      rule("materials", "doubleSided", K::Flag),
      rule("materials.pbrMetallicRoughness", "baseColorFactor", K::Numbers).from(0, 1).count(4),
      rule("materials.pbrMetallicRoughness", "baseColorTexture", K::Object),
      rule("materials.pbrMetallicRoughness", "metallicFactor", K::Number).from(0, 1),
      rule("materials.pbrMetallicRoughness", "roughnessFactor", K::Number).from(0, 1),
      rule("materials.pbrMetallicRoughness", "metallicRoughnessTexture", K::Object),
      rule("materials.normalTexture", "scale", K::Number),
      rule("materials.occlusionTexture", "strength", K::Number).from(0, 1),
      rule("meshes", "primitives", K::Objects).req(),
      rule("meshes", "weights", K::Numbers),
      rule("meshes.primitives", "attributes", K::IndexMap).req().into("accessors"),
      rule("meshes.primitives", "indices", K::Index).into("accessors"),
      rule("meshes.primitives", "material", K::Index).into("materials"),
      rule("meshes.primitives", "mode", K::Code).among({0, 1, 2, 3, 4, 5, 6}),
      rule("meshes.primitives", "targets", K::IndexMapList).into("accessors"),
      rule("meshes.primitives", "extensions", K::Object),
      rule("meshes.primitives.extensions", "KHR_draco_mesh_compression", K::Object),
      rule("meshes.primitives.extensions.KHR_draco_mesh_compression", "bufferView", K::Index)
          .req()
          .into("bufferViews"),
      rule("nodes", "camera", K::Index).into("cameras"),
      rule("nodes", "children", K::IndexList).into("nodes"),
      rule("nodes", "skin", K::Index).into("skins"),
      rule("nodes", "matrix", K::Numbers).count(16),
      rule("nodes", "mesh", K::Index).into("meshes"),
      rule("nodes", "rotation", K::Numbers).from(-1, 1).count(4),
      rule("nodes", "scale", K::Numbers).count(3),
      rule("nodes", "translation", K::Numbers).count(3),
      rule("nodes", "weights", K::Numbers),
      rule("samplers", "magFilter", K::Code).among({9728, 9729}),
      rule("samplers", "minFilter", K::Code).among({9728, 9729, 9984, 9985, 9986, 9987}),
      rule("samplers", "wrapS", K::Code).among(wraps),
      rule("samplers", "wrapT", K::Code).among(wraps),
      rule("scenes", "nodes", K::IndexList).into("nodes"),
      rule("skins", "inverseBindMatrices", K::Index).into("accessors"),
      rule("skins", "skeleton", K::Index).into("nodes"),
      rule("skins", "joints", K::IndexList).req().into("nodes"),
      rule("textures", "sampler", K::Index).into("samplers"),
      rule("textures", "source", K::Index).into("images"),
  };
  for (const char* list :
       {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
        "meshes", "nodes", "samplers", "scenes", "skins", "textures"})
    r.push_back(rule("", list, K::Objects));
  for (const char* info :
       {"materials.pbrMetallicRoughness.baseColorTexture",
        "materials.pbrMetallicRoughness.metallicRoughnessTexture", "materials.normalTexture",
        "materials.occlusionTexture", "materials.emissiveTexture"}) {
    r.push_back(rule(info, "index", K::Index).req().into("textures"));
    r.push_back(rule(info, "texCoord", K::Whole).from(0, 31));
  }
  return r;
}

// The rules by the schema path they apply at.
const std::multimap<std::string_view, Rule>& rulesByPath() {
  static const std::vector<Rule> rules = makeRules();
  static const std::multimap<std::string_view, Rule> byPath = [] {
    std::multimap<std::string_view, Rule> m;
    for (const Rule& r : rules) m.emplace(r.at, r);
    return m;
  }();
  return byPath;
}

// A JSON value named in a message: numbers and short strings as written, the rest by type.
// The file parsed, so this quotes a value the file holds, never bytes around it.
std::string shown(const json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean() || v.is_number()) return v.dump();
  if (v.is_string()) {
    const std::string s = v.dump(-1, ' ', true);  // quoted, escaped, ASCII only
    return s.size() <= 40 ? "the string " + s
                          : "a string of " + std::to_string(s.size() - 2) + " characters";
  }
  return v.is_array() ? "an array" : "an object";
}

std::string rangeText(double lo, double hi, bool aboveLo) {
  // Most bounds are whole numbers: "at least 0", not "at least 0.0".
  auto n = [](double d) {
    return d == std::floor(d) && std::fabs(d) < 1e15 ? std::to_string(int64_t(d)) : json(d).dump();
  };
  if (hi == kInf) return (aboveLo ? "above " : "at least ") + n(lo);
  if (lo == -kInf) return "at most " + n(hi);
  return "from " + n(lo) + " to " + n(hi);
}

template <class List>
std::string listText(const List& list) {
  std::string out;
  for (const auto& v : list) {
    std::ostringstream s;
    s << v;
    out += (out.empty() ? "" : ", ") + s.str();
  }
  return out;
}

struct Place {
  const json* value;
  std::string schema;     // "meshes.primitives"
  std::string path;       // "meshes[2].primitives[0]"
  const json* animation;  // the enclosing animation, for its samplers
  // An array of objects (`value`) whose elements from `next` on are still to visit: one
  // pending entry per array rather than per element, so 100,000 nodes queue one place.
  bool elements = false;
  size_t next = 0;
};

class Checker {
 public:
  Checker(const std::filesystem::path& file, const json& doc) : file_(file), doc_(doc) {}

  void run() {
    std::vector<Place> pending{{&doc_, "", "", nullptr}};
    while (!pending.empty()) {
      Place p = std::move(pending.back());
      pending.pop_back();
      if (p.elements) {
        const json& list = *p.value;
        const size_t i = p.next;
        std::string at = p.path + "[" + std::to_string(i) + "]";
        if (!list[i].is_object()) fail(at, "is " + shown(list[i]) + ", not an object");
        if (i + 1 < list.size())
          pending.push_back({p.value, p.schema, p.path, p.animation, true, i + 1});
        pending.push_back({&list[i], std::move(p.schema), std::move(at), p.animation});
        continue;
      }
      if (p.schema == "animations") p.animation = p.value;
      const auto [first, last] = rulesByPath().equal_range(p.schema);
      for (auto it = first; it != last; ++it) check(it->second, p, pending);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw SceneError(file_, where + " " + problem +
                                "; fix the exporter or the file (the Khronos glTF validator "
                                "reports it too)");
  }

  size_t targetSize(const Rule& r, const Place& p) const {
    const json* list = nullptr;
    if (r.target == kAnimationSamplers) {
      if (const auto it = p.animation->find("samplers"); it != p.animation->end()) list = &*it;
    } else if (const auto it = doc_.find(std::string(r.target)); it != doc_.end()) {
      list = &*it;
    }
    return list && list->is_array() ? list->size() : 0;
  }

  // What is wrong with `v` under the scalar rule `r`, "" when nothing.
  std::string problem(const Rule& r, const Place& p, const json& v) const {
    switch (r.kind) {
      case Kind::Index:
      case Kind::IndexList:
      case Kind::IndexMap:
      case Kind::IndexMapList: {
        const size_t size = targetSize(r, p);
        if (v.is_number_unsigned() && v.get<uint64_t>() < size) return "";
        const std::string list(r.target);
        const std::string range =
            size == 0 ? "there are no " + list
                      : list + " has " + std::to_string(size) +
                            (size == 1 ? " entry, index 0"
                                       : " entries, indexed 0 to " + std::to_string(size - 1));
        return "is " + shown(v) + (v.is_number_integer() ? ", but " : ", not an index; ") + range;
      }
      case Kind::Whole: {
        const bool ok = v.is_number_unsigned()
                            ? double(v.get<uint64_t>()) >= r.lo && double(v.get<uint64_t>()) <= r.hi
                            : v.is_number_integer() && double(v.get<int64_t>()) >= r.lo &&
                                  double(v.get<int64_t>()) <= r.hi;
        return ok ? ""
                  : "is " + shown(v) + "; it must be a whole number " +
                        rangeText(r.lo, r.hi, false);
      }
      case Kind::Code:
        if (v.is_number_unsigned() && v.get<uint64_t>() < (uint64_t(1) << 31) &&
            std::find(r.codes.begin(), r.codes.end(), v.get<int64_t>()) != r.codes.end())
          return "";
        return "is " + shown(v) + ", which glTF 2.0 does not define here (one of " +
               listText(r.codes) + ")";
      case Kind::Name:
        if (v.is_string() && std::find(r.names.begin(), r.names.end(),
                                       v.get_ref<const std::string&>()) != r.names.end())
          return "";
        return "is " + shown(v) + ", which glTF 2.0 does not define here (one of " +
               listText(r.names) + ")";
      case Kind::Flag:
        return v.is_boolean() ? "" : "is " + shown(v) + ", not true or false";
      case Kind::Number:
      case Kind::Numbers: {
        if (!v.is_number() || !std::isfinite(v.get<double>()))
          return "is " + shown(v) + ", not a number";
        const double d = v.get<double>();
        if (d < r.lo || d > r.hi || (r.aboveLo && d == r.lo))
          return "is " + v.dump() + ", outside its range (" + rangeText(r.lo, r.hi, r.aboveLo) +
                 ")";
        return "";
      }
      case Kind::Text:
        return v.is_string() ? "" : "is " + shown(v) + ", not a string";
      case Kind::Object:
      case Kind::Objects:
        break;
    }
    return "";
  }

  // Every value of the object `map` (an attribute set) checked as an index.
  void indexMap(const Rule& r, const Place& p, const json& map, const std::string& where) const {
    if (!map.is_object()) fail(where, "is " + shown(map) + ", not an object of accessor indices");
    for (const auto& [name, value] : map.items())
      if (const std::string why = problem(r, p, value); !why.empty()) fail(where + "." + name, why);
  }

  void check(const Rule& r, const Place& p, std::vector<Place>& pending) const {
    if (!p.value->is_object()) return;  // the parent's rule reported it
    const auto found = p.value->find(std::string(r.key));
    auto where = [&] {
      return p.path.empty() ? std::string(r.key) : p.path + "." + std::string(r.key);
    };
    if (found == p.value->end()) {
      if (r.required)
        fail(p.path.empty() ? "the file" : p.path,
             "has no \"" + std::string(r.key) + "\", which glTF 2.0 requires there");
      return;
    }
    const json& v = *found;
    auto element = [&](size_t i) { return where() + "[" + std::to_string(i) + "]"; };
    auto schema = [&] {
      return p.schema.empty() ? std::string(r.key) : p.schema + "." + std::string(r.key);
    };
    switch (r.kind) {
      case Kind::IndexList:
      case Kind::Numbers:
        if (!v.is_array())
          fail(where(), "is " + shown(v) + ", not an array of " +
                            (r.kind == Kind::Numbers ? "numbers" : "indices"));
        if (r.length && v.size() != r.length)
          fail(where(), "has " + std::to_string(v.size()) + " numbers; glTF 2.0 gives it " +
                            std::to_string(r.length));
        for (size_t i = 0; i < v.size(); ++i)
          if (const std::string why = problem(r, p, v[i]); !why.empty()) fail(element(i), why);
        break;
      case Kind::IndexMap:
        indexMap(r, p, v, where());
        break;
      case Kind::IndexMapList:
        if (!v.is_array()) fail(where(), "is " + shown(v) + ", not an array");
        for (size_t i = 0; i < v.size(); ++i) indexMap(r, p, v[i], element(i));
        break;
      case Kind::Object:
        if (!v.is_object()) fail(where(), "is " + shown(v) + ", not an object");
        pending.push_back({&v, schema(), where(), p.animation});
        break;
      case Kind::Objects:
        if (!v.is_array()) fail(where(), "is " + shown(v) + ", not an array of objects");
        if (!v.empty()) pending.push_back({&v, schema(), where(), p.animation, true, 0});
        break;
      default:
        if (const std::string why = problem(r, p, v); !why.empty()) fail(where(), why);
    }
  }

  const std::filesystem::path& file_;
  const json& doc_;
};

}  // namespace

json parseGltfJson(const std::filesystem::path& file, const std::string& text) {
  try {
    json doc = json::parse(text);
    if (!doc.is_object()) throw SceneError(file, "is JSON but not a glTF object ({...})");
    return doc;
  } catch (const json::exception& e) {
    throw SceneError(file, "is not valid glTF JSON (" + jsonErrorWithoutContent(e.what()) +
                               "); check the file with the Khronos glTF validator");
  }
}

void checkGltfDocument(const std::filesystem::path& file, const json& doc) {
  Checker(file, doc).run();
  // glTF 1.0 files parse too, but mean other things by the same keys: asset.version is
  // "MAJOR.MINOR", and only major version 2 is read (the checker made sure it is a string).
  const std::string version = doc.at("asset").at("version").get<std::string>();
  if (version.rfind("2.", 0) != 0 || version.size() < 3 ||
      version.find_first_not_of("0123456789", 2) != std::string::npos)
    throw SceneError(file,
                     "asset.version is " + shown(doc.at("asset").at("version")) +
                         ", not glTF 2.x; convert the file to glTF 2.0 (e.g. with the Khronos "
                         "glTF converters) and set asset.version to \"2.0\"");
}

}  // namespace taa::scene
