// One fuzz input through each reader, shared by the libFuzzer targets (fuzz_*.cpp) and by
// fuzz_regressions_test.cpp, which replays the checked-in corpus in every build. An input
// must be read or refused with the reader's own error (bad input, exit 2); any other
// exception, a crash, a hang or a sanitizer report is a bug.
#pragma once

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "api/reference_store.h"
#include "api/scene_loading.h"
#include "case/case_error.h"
#include "case/case_loader.h"
#include "case/coverage.h"
#include "cli/options.h"
#include "core/exr_codec.h"
#include "core/image_io.h"
#include "core/json_guard.h"
#include "core/png_codec.h"
#include "golden/manifest.h"
#include "run/merge.h"
#include "run/run_folder.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "scene/scene_error.h"
#include "score/score.h"
#include "script/track.h"
#include "script/track_csv.h"
#include "script/track_json.h"
#include "user/glsl_compiler.h"
#include "user/spirv_cache.h"
#include "user/spirv_check.h"
#include "user/user_interface.h"
#include "vk/driver_manifests.h"

namespace taa::fuzz {

// The case reader. The folder does not exist, so references to scenes and tracks are
// refused as missing instead of reading whatever the input names.
inline void readCase(const std::string& text) {
  try {
    cases::parseCase(text, "/nonexistent-taa-fuzz/case.json");
  } catch (const cases::CaseError&) {
  }
}

// A results.json as another run's folder gives it: as the folder's one reader parses it for
// `run --verdict-from`, `merge`, `bless --from` and `coverage --results`, then merge's checks
// of one shard and of its image paths, and coverage's check of the logs. Refusals are
// RunFolderError (MergeError is one) or coverage's invalid_argument.
inline void readResults(const std::string& text) {
  try {
    const run::RunResults r = run::RunFolder("fuzz").parseResults(text, "fix");
    try {
      (void)run::mergeShards({{"fuzz", r}});
    } catch (const run::MergeError&) {
    }
    std::vector<std::pair<std::string, std::vector<std::string>>> logs;
    for (const auto& c : r.cases) {
      (void)run::imagePathsOf(c);
      logs.emplace_back(c.name, c.log);
    }
    (void)cases::checkedRunLogs(logs);
  } catch (const run::RunFolderError&) {
  } catch (const std::invalid_argument&) {
  }
}

// A folder of this process's own under the temp folder: readers that take a path get their
// input there, and two fuzzers (or a fuzzer and its replay) never share one.
inline std::filesystem::path privateFuzzDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() /
                 ("taa-fuzz-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d;
}

// A golden manifest as run and bless read it: goldens come in pull requests and copies, so its
// text is as untrusted as a run folder's (case_file is read as a name, never as a path).
inline void readGoldenManifest(const std::string& text) {
  static const std::filesystem::path file = privateFuzzDir("manifest") / "manifest.json";
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  try {
    (void)golden::readManifest(file);
  } catch (const golden::GoldenError&) {
  }
}

// The JSON a run or goldens folder holds: the same bytes through both readers.
inline void readFolderJson(const std::string& text) {
  readResults(text);
  readGoldenManifest(text);
  (void)vk::isLavapipeManifest(text);  // a Vulkan driver manifest (vk/driver_manifests.h)
}

// A lanes file (score --lanes): read from a private folder, as the loader reads a file.
inline void readLanes(const std::string& bytes) {
  static const std::filesystem::path file = privateFuzzDir("lanes") / "lanes.json";
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  try {
    (void)score::loadLanes(file);
  } catch (const cases::CaseError&) {
  }
}

// The JSON track reader for input starting with '{', else the CSV one.
inline void readTrack(const std::string& text) {
  try {
    if (!text.empty() && text[0] == '{') {
      script::parseJsonTrack(text, "fuzz.track.json");
    } else {
      script::checkTrack(script::parseCsvTrack(text, "fuzz.csv", script::TrackSubject::Camera));
    }
  } catch (const script::TrackError&) {
  }
}

// The glTF loader (.glb when the input has the GLB magic), posed at t = 0.5 s. The loader
// reads files, so the input goes to a private folder first.
inline void readGltf(const std::string& bytes) {
  static const std::filesystem::path dir = privateFuzzDir("gltf");
  const bool glb = bytes.rfind("glTF", 0) == 0;
  const std::filesystem::path file = dir / (glb ? "in.glb" : "in.gltf");
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  (void)gltfReferencedFiles(file, bytes);  // the case's input hash and the reference key read these
  scene::Scene s;
  try {
    s.models.push_back(scene::loadGltf(file, s));
    scene::poseModel(s, 0, 0.5);
  } catch (const scene::SceneError&) {
  }
}

// A reference cache entry (api/reference_store.h) as a store reads it, under the key the
// corpus's entries were written for: a complete, verified entry or nothing, never a throw.
inline constexpr const char* kFuzzReferenceKey =
    "0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef";
inline void readReferenceEntry(const std::string& bytes) {
  if (auto image = decodeReferenceEntry(bytes, kFuzzReferenceKey))
    if (image->data.size() != image->pixelCount() * size_t(image->channels)) std::abort();
}

// The image codecs as `compare` and the golden reader use them: OpenEXR (channels by
// name, then in the golden reader's order) or PNG, by the first bytes.
inline void readImageBytes(const std::string& bytes) {
  try {
    if (exr::hasExrMagic(bytes)) {
      const std::string layer;
      (void)exr::decode(bytes, kMaxImageSamples, &layer);
      (void)exr::decode(bytes, kMaxImageSamples);
    } else {
      (void)png::decode(bytes, kMaxImageSamples);
    }
  } catch (const exr::ExrError&) {
  } catch (const png::PngError&) {
  }
}

// A SPIR-V cache entry (user/spirv_cache.h) as a compile reads it: the input is KEY.deps, beside
// a fixed KEY.spv (the four bytes of kFuzzSpirvWord). The reader parses every line, checks each
// include the input names and the words' hash, and gives a whole entry or a miss, never a throw;
// the corpus's hit names that hash, so the fuzzer starts from lines that reach the end.
inline constexpr char kFuzzSpirvWord[] = "\x03\x02\x23\x07";
inline bool readSpirvCacheEntry(const std::string& deps) {
  static const std::filesystem::path dir = [] {
    const auto d = privateFuzzDir("spirv");
    std::ofstream(d / "k.spv", std::ios::binary | std::ios::trunc) << kFuzzSpirvWord;
    return d;
  }();
  std::ofstream(dir / "k.deps", std::ios::binary | std::ios::trunc) << deps;
  user::CompiledShader out;
  std::string why;
  const bool hit = user::readSpirvCache(dir, "k", out, why);
  if (hit && (out.spirv.size() != 1 || !out.fromCache)) std::abort();
  return hit;
}

// A user's HLSL resolve through the compile (glslang in its sandboxed child, the entry point's
// rules, spirv-val and the interface check) and the reflection, as `validate` runs them; the
// bytes themselves also go to the SPIR-V check as words. Each file of the input's folder is
// its own, and the SPIR-V cache is private to the process.
inline void compileHlsl(const std::string& text) {
  static const std::filesystem::path dir = [] {
    const auto d = privateFuzzDir("shader");
    std::filesystem::create_directories(d / "src");
    return d;
  }();
  std::vector<uint32_t> words(text.size() / 4);
  if (!words.empty()) std::memcpy(words.data(), text.data(), words.size() * 4);  // no null source
  (void)user::userSpirvProblem(words, "fuzz.spv");
  const std::filesystem::path file = dir / "src" / "in.hlsl";
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  user::CompileOptions o;
  o.root = dir / "src";
  o.cacheDir = dir / "cache";
  o.language = user::ShaderLanguage::Hlsl;
  try {
    const user::CompiledShader c = user::compileComputeShader(file, o);
    (void)user::reflectUserInterface(c.spirv, file.string());
  } catch (const user::ShaderCompileError&) {
  }
}

}  // namespace taa::fuzz
