// The glTF containment check, run on the JSON before tinygltf resolves any uri. A
// second line of defence (file-system callbacks) lives in gltf_loader.cpp.
#include <cctype>
#include <cstring>
#include <string_view>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene_error.h"

namespace taa::scene {
namespace {

uint32_t readU32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 |
         uint32_t(b[at + 3]) << 24;
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string percentDecode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && hexValue(s[i + 1]) >= 0 && hexValue(s[i + 2]) >= 0) {
      out += char(hexValue(s[i + 1]) * 16 + hexValue(s[i + 2]));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

bool startsWithNoCase(const std::string& s, const char* prefix) {
  const size_t n = std::strlen(prefix);
  if (s.size() < n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(s[i])) != prefix[i]) return false;
  return true;
}

// Length of an RFC 3986 scheme ("http" in "http:..."), 0 when there is none.
size_t schemeLength(const std::string& s) {
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) return 0;
  for (size_t i = 1; i < s.size(); ++i) {
    const char c = s[i];
    if (c == ':') return i;
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return 0;
  }
  return 0;
}

// What is wrong with `uri` and how to fix it, or "" when it is acceptable.
std::string uriProblem(const std::string& uri) {
  if (startsWithNoCase(uri, "data:")) return "";
  const std::string path = percentDecode(uri);
  // A NUL would end the path early at the file system ("a.bin%00.png" opens "a.bin").
  for (const char c : path)
    if (static_cast<unsigned char>(c) < 0x20)
      return "holds a control character (a NUL or %00 would cut the path short); rename the "
             "file and refer to it without one";
  const size_t scheme = schemeLength(path);
  if (path.find("://") != std::string::npos || scheme > 1)
    return "is an external URI; only files inside the glTF's folder are read. Download the file "
           "next "
           "to the glTF and refer to it by a relative path, or embed it (data: URI or .glb)";
  if (scheme == 1 || path.starts_with('/') || path.starts_with('\\'))
    return "is an absolute path; refer to the file relative to the glTF's folder, or embed it";
  size_t start = 0;
  while (start <= path.size()) {
    const size_t end = path.find_first_of("/\\", start);
    const std::string part =
        path.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (part == "..")
      return "leaves the glTF's folder; move the file into the glTF's folder (or below it) and "
             "refer "
             "to it without '..', or embed it";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return "";
}

// Every buffer's and image's string "uri", in file order: f(key, index, entry, uri).
template <class F>
void forEachUri(const nlohmann::json& doc, F&& f) {
  if (!doc.is_object()) return;
  for (const char* key : {"buffers", "images"}) {
    const auto list = doc.find(key);
    if (list == doc.end() || !list->is_array()) continue;
    for (size_t i = 0; i < list->size(); ++i) {
      const auto& entry = (*list)[i];
      if (!entry.is_object()) continue;
      const auto uri = entry.find("uri");
      if (uri == entry.end() || !uri->is_string()) continue;
      f(key, i, entry, uri->get_ref<const std::string&>());
    }
  }
}

// tinygltf reads an embedded buffer only when its data URI is base64 of exactly byteLength
// bytes, and says "File not found" or "Failed to decode" with the whole URI (hundreds of KB):
// both are named here, with the numbers, before it runs.
void checkDataBuffer(const std::filesystem::path& file, size_t i, const nlohmann::json& entry,
                     const std::string& value) {
  const std::string key = "buffers[" + std::to_string(i) + "]";
  const size_t comma = value.find(',');
  const size_t marker = value.find(";base64,");
  if (comma == std::string::npos || marker == std::string::npos || marker + 7 != comma)
    throw SceneError(file, key + ".uri is a data URI that is not base64; glTF embeds a buffer "
                                 "as data:application/octet-stream;base64,...; re-export it");
  const size_t chars = value.size() - comma - 1;
  size_t padding = 0;
  while (padding < 2 && padding < chars && value[value.size() - 1 - padding] == '=') ++padding;
  const auto length = entry.find("byteLength");
  if (chars % 4 != 0 || length == entry.end() || !length->is_number_unsigned()) return;
  const uint64_t holds = chars / 4 * 3 - padding, declared = length->get<uint64_t>();
  if (holds != declared)
    throw SceneError(file, key + ".byteLength is " + std::to_string(declared) +
                               ", but its data URI holds " + std::to_string(holds) +
                               " bytes; make them agree or re-export the file");
}

}  // namespace

std::string glbJsonChunk(const std::filesystem::path& file, const std::vector<uint8_t>& bytes) {
  const std::string fix = "; re-export it as glTF 2.0 binary or use the .gltf form";
  if (bytes.size() < 20 || readU32(bytes, 0) != 0x46546C67u)  // "glTF"
    throw SceneError(file, "not a GLB container (missing 'glTF' magic)" + fix);
  if (readU32(bytes, 4) != 2)
    throw SceneError(file, "GLB version " + std::to_string(readU32(bytes, 4)) +
                               " is not supported (glTF 2.0 only)" + fix);
  const uint32_t length = readU32(bytes, 12);
  if (readU32(bytes, 16) != 0x4E4F534Au || size_t(length) + 20 > bytes.size())  // "JSON"
    throw SceneError(file, "GLB's first chunk is not a complete JSON chunk" + fix);
  // tinygltf 2.7 checks the BIN chunk's length without its 8-byte header and would read
  // up to 8 bytes past the file; check the whole layout here (all in 64 bits).
  const uint64_t total = readU32(bytes, 8), binAt = 20 + uint64_t(length);
  if (total > bytes.size() || total < binAt)
    throw SceneError(file, "GLB header gives a total length of " + std::to_string(total) +
                               " bytes, but the file has " + std::to_string(bytes.size()) +
                               " and its JSON chunk ends at byte " + std::to_string(binAt) + fix);
  if (binAt < total && (binAt + 8 > total || binAt + 8 + readU32(bytes, size_t(binAt)) > total))
    throw SceneError(file, "GLB's BIN chunk runs past the end of the file" + fix);
  return std::string(reinterpret_cast<const char*>(bytes.data() + 20), length);
}

std::vector<std::string> gltfFileUris(const nlohmann::json& doc) {
  std::vector<std::string> out;
  forEachUri(doc, [&](const char*, size_t, const nlohmann::json&, const std::string& value) {
    // A refused uri is reported by loading; it names no file that could be read.
    if (!startsWithNoCase(value, "data:") && uriProblem(value).empty())
      out.push_back(percentDecode(value));
  });
  return out;
}

void checkGltfUris(const std::filesystem::path& file, const nlohmann::json& doc) {
  forEachUri(doc, [&](const char* key, size_t i, const nlohmann::json& entry,
                      const std::string& value) {
    if (std::string_view(key) == "buffers" && startsWithNoCase(value, "data:"))
      checkDataBuffer(file, i, entry, value);
    const std::string problem = uriProblem(value);
    if (!problem.empty())
      throw SceneError(
          file, std::string(key) + "[" + std::to_string(i) + "].uri " +
                    nlohmann::json(value.size() > 200 ? value.substr(0, 200) + "..." : value)
                        .dump(-1, ' ', true) +
                    " " + problem);
  });
}

}  // namespace taa::scene
