#include "scene/gltf_loader.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <fstream>

#include "core/input_file.h"
#include "core/json_guard.h"
#include "scene/gltf_checks.h"
#include "scene/gltf_convert.h"
#include "scene/gltf_images.h"
#include "scene/scene_error.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

// File-system callbacks that confine tinygltf to the glTF's folder even if a uri slipped
// past checkGltfUris, and that replace its default path expansion (wordexp, which
// would expand '~' and environment variables in a uri).
struct Jail {
  fs::path root;                     // canonical folder of the glTF file
  std::vector<std::string> refused;  // paths in the folder leading out, for the error message
  static bool inside(const fs::path& p, const fs::path& folder) {
    const fs::path rel = p.lexically_relative(folder);
    return !rel.empty() && *rel.begin() != ".." && !rel.is_absolute();
  }
  bool contains(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::path(path), ec);
    if (!ec && inside(p, root)) return true;
    // A path in the folder that resolves outside leads out through a link: refused whether
    // or not its target exists, and without saying where it points. tinygltf's other probes
    // (the working directory) are left out silently.
    if (inside(fs::absolute(fs::path(path), ec).lexically_normal(), root))
      refused.push_back(path);
    return false;
  }
  // Why loading failed when the cause was a refusal, else "".
  std::string explain() const {
    if (refused.empty()) return "";
    return "'" + refused.front() +
           "' leads outside the glTF's folder (through a symbolic link); put the file itself "
           "inside the glTF's folder";
  }
};

// Anything that exists counts, so a FIFO or directory reaches jailRead and its refusal
// names what it is instead of "not found".
bool jailExists(const std::string& path, void* user) {
  std::error_code ec;
  return static_cast<Jail*>(user)->contains(path) && fs::exists(path, ec);
}

std::string jailExpand(const std::string& path, void*) {
  return path;
}

bool jailRead(std::vector<unsigned char>* out, std::string* err, const std::string& path,
              void* user) {
  if (!static_cast<Jail*>(user)->contains(path)) {
    if (err) *err += "refused to read '" + path + "': outside the glTF's folder\n";
    return false;
  }
  try {
    *out = readInputBytes(path, kMaxSceneFileBytes);
  } catch (const InputFileError& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
  return true;
}

bool jailWrite(std::string* err, const std::string& path, const std::vector<unsigned char>&,
               void*) {
  if (err) *err += "refused to write '" + path + "': the scene loader never writes\n";
  return false;
}

std::vector<uint8_t> readFile(const fs::path& file) {
  try {
    return readInputBytes(file, kMaxSceneFileBytes);
  } catch (const InputFileError& e) {
    throw SceneError(e.what());
  }
}

// tinygltf's message on one line, at most kMaxMessageBytes: it quotes a failing data URI whole,
// which made a 200 KB buffer a 267 KB error line.
constexpr size_t kMaxMessageBytes = 1000;
std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (auto& c : s)
    if (c == '\n') c = ' ';
  if (s.size() > kMaxMessageBytes)
    s = s.substr(0, kMaxMessageBytes) + "... (" + std::to_string(s.size() - kMaxMessageBytes) +
        " more bytes)";
  return s;
}

}  // namespace

Model loadGltf(const fs::path& file, Scene& scene) {
  std::vector<uint8_t> bytes = readFile(file);
  const bool binary =
      bytes.size() >= 4 && bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T' && bytes[3] == 'F';
  std::string json =
      binary ? glbJsonChunk(file, bytes) : std::string(bytes.begin(), bytes.end());
  if (!binary) std::vector<uint8_t>().swap(bytes);  // the text is the only copy kept
  if (const std::string problem = jsonStructureProblem(json); !problem.empty())
    throw SceneError(file, problem);
  DracoIndices dracoIndices;
  std::vector<GltfNode> nodes;
  {
    // The one parse before tinygltf's: every check reads this document, which is gone
    // before tinygltf builds its own.
    nlohmann::json doc = parseGltfJson(file, json);
    checkGltfDocument(file, doc);
    checkGltfUris(file, doc);
    const std::string note = checkGltfExtensions(file, doc);
    if (!note.empty() &&
        std::find(scene.notes.begin(), scene.notes.end(), note) == scene.notes.end())
      scene.notes.push_back(note);
    // tinygltf is given the document without its nodes, which are read here once (a file
    // of many nodes is mostly nodes); the text goes first, as the document holds it all.
    const bool hadNodes = doc.contains("nodes");
    nodes = takeGltfNodes(doc);
    bool changed = fillMeshoptFallbacks(doc) || hadNodes;
    dracoIndices = detachDracoIndices(doc, changed);
    if (changed) {
      std::string().swap(json);
      json = doc.dump();
      if (binary) bytes = glbWithJson(bytes, json);
    }
  }

  std::error_code ec;
  Jail jail{fs::weakly_canonical(fs::absolute(file, ec).parent_path(), ec), {}};
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&jailExists, &jailExpand, &jailRead, &jailWrite, &jail});
  tinygltf::Model gltf;
  ImageLoadState images{&gltf, 0};
  loader.SetImageLoader(&loadCheckedImage, &images);
  std::string err, warn;
  const std::string base = jail.root.string();
  const bool ok = binary
                      ? loader.LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(),
                                                    static_cast<unsigned int>(bytes.size()), base)
                      : loader.LoadASCIIFromString(&gltf, &err, &warn, json.data(),
                                                   static_cast<unsigned int>(json.size()), base);
  if (!jail.explain().empty()) throw SceneError(file, jail.explain());
  if (!ok)
    throw SceneError(file, "tinygltf cannot load it: " + trimmed(err) +
                               "; check the file with the Khronos glTF validator or re-export it");
  std::string().swap(json);  // tinygltf holds everything it read
  std::vector<uint8_t>().swap(bytes);
  decodeMeshopt(file, gltf);
  decodeDraco(file, gltf, dracoIndices);
  return convertGltf(file, gltf, nodes, trimmed(warn), scene);
}

}  // namespace taa::scene
