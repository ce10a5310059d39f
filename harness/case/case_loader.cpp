#include "case/case_loader.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include "api/scene_loading.h"
#include "api/user_shader.h"
#include "case/case_error.h"
#include "case/case_validate.h"
#include "case/json_reader.h"
#include "case/json_writer.h"
#include "case/validate_inputs.h"
#include "case/validate_report.h"
#include "core/input_file.h"
#include "core/json_guard.h"
#include "core/sha256.h"
#include "invariants/registry.h"

namespace taa::cases {

namespace fs = std::filesystem;

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string formatNumber(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

namespace {

// The files a user's shader read to compile: itself, then every include inside its folder,
// by path relative to that folder (the installed taa_user.h is the harness's, not the case's).
std::vector<std::pair<std::string, std::string>> shaderInputs(const spec::CaseSpec& spec) {
  const LoadedUserShader shader(spec);
  std::vector<std::pair<std::string, std::string>> out{{"taa.shader", spec.taa.shader}};
  std::error_code ec;
  const fs::path root = fs::canonical(shader.root(), ec);
  for (const auto& inc : shader.includes()) {
    const fs::path rel = inc.lexically_relative(root);
    if (ec || rel.empty() || *rel.begin() == "..") continue;
    out.emplace_back("taa.shader (#include)", rel.generic_string());
  }
  return out;
}

// The case file's bytes, then each file it references (scene, mover models and the buffers
// and images each glTF names, tracks, a user's shader and its includes, the still image) by
// its relative path and bytes: editing any of them makes blessed goldens stale and an earlier
// run's verdict (run --verdict-from) another case's. Each is read as an input file: inside its
// folder after resolving links, regular, bounded.
std::string inputsSha256(const spec::CaseSpec& spec, const std::string& text) {
  const fs::path dir = spec.file.parent_path();
  struct Ref {
    std::string key, path;
    fs::path folder;
  };
  std::vector<Ref> refs;
  if (!spec.scene.gltf.empty()) refs.push_back({"scene.gltf", spec.scene.gltf, dir});
  if (!spec.camera.track.empty()) refs.push_back({"camera.track", spec.camera.track, dir});
  if (!spec.debug.image.empty()) refs.push_back({"debug.image", spec.debug.image, dir});
  if (!spec.taa.shader.empty()) {
    const fs::path root = spec.taa.shader_root.empty() ? dir : fs::path(spec.taa.shader_root);
    try {
      for (const auto& [key, ref] : shaderInputs(spec)) refs.push_back({key, ref, root});
    } catch (const user::ShaderCompileError& e) {
      throw CaseError({spec.file.string() + ": taa.shader: does not compile:\n" + e.what()});
    }
  }
  for (size_t i = 0; i < spec.movers.size(); ++i) {
    const std::string at = "movers[" + std::to_string(i) + "].";
    if (!spec.movers[i].gltf.empty()) refs.push_back({at + "gltf", spec.movers[i].gltf, dir});
    if (!spec.movers[i].track.empty()) refs.push_back({at + "track", spec.movers[i].track, dir});
  }
  Sha256 h;
  h.update(text.data(), text.size());
  auto add = [&h](const std::string& ref, const std::string& bytes) {
    h.update("\0", 1);
    h.update(ref.data(), ref.size());
    h.update("\0", 1);
    h.update(bytes.data(), bytes.size());
  };
  for (const auto& [key, ref, folder] : refs) {
    std::string b;
    try {
      containedRealPath(folder, folder / ref, key);
      b = readInputFile(folder / ref, kMaxSceneFileBytes);
    } catch (const InputFileError& e) {
      throw CaseError({spec.file.string() + ": " + key + ": " + e.what()});
    }
    add(ref, b);
    if (key != "scene.gltf" && !key.ends_with("].gltf")) continue;
    // A glTF's buffers and images, read from its own folder as loading reads them. One that
    // cannot be read is hashed as such (loading then refuses the scene, naming it); none of
    // them is refused here, so `validate` and a render report it as before.
    const fs::path gltfDir = (folder / ref).parent_path();
    for (const auto& uri : gltfReferencedFiles(folder / ref, b)) {
      const std::string name = (fs::path(ref).parent_path() / uri).generic_string();
      std::string bytes;
      try {
        containedRealPath(gltfDir, gltfDir / uri, key + " (" + uri + ")");
        bytes = readInputFile(gltfDir / uri, kMaxSceneFileBytes);
      } catch (const InputFileError&) {
        add(name, std::string("\0unreadable", 11));
        continue;
      }
      add(name, bytes);
    }
  }
  const auto digest = h.finish();
  return toHex(digest.data(), digest.size());
}

}  // namespace

std::string referencedFilesSha256(const spec::CaseSpec& spec) {
  const fs::path dir = spec.file.parent_path();
  std::vector<std::pair<std::string, fs::path>> files;  // (key, file)
  auto gltf = [&](const std::string& key, const std::string& ref) {
    files.emplace_back(key, dir / ref);
    const fs::path folder = (dir / ref).parent_path();
    std::string bytes;  // one that cannot be read lists no files (its load names why)
    try {
      bytes = readInputFile(dir / ref, kMaxSceneFileBytes);
    } catch (const InputFileError&) {
    }
    for (const auto& uri : gltfReferencedFiles(dir / ref, bytes))
      files.emplace_back(key + " " + uri, folder / uri);
  };
  if (!spec.scene.gltf.empty()) gltf("scene.gltf", spec.scene.gltf);
  if (!spec.camera.track.empty()) files.emplace_back("camera.track", dir / spec.camera.track);
  if (!spec.debug.image.empty()) files.emplace_back("debug.image", dir / spec.debug.image);
  for (size_t i = 0; i < spec.movers.size(); ++i) {
    const std::string at = "movers[" + std::to_string(i) + "].";
    if (!spec.movers[i].gltf.empty()) gltf(at + "gltf", spec.movers[i].gltf);
    if (!spec.movers[i].track.empty()) files.emplace_back(at + "track", dir / spec.movers[i].track);
  }
  Sha256 h;
  for (const auto& [key, file] : files) {
    // A file that cannot be read fails the case's scene load, which names it; here it is a
    // part of the key like any other.
    std::string b;
    try {
      b = readInputFile(file, kMaxSceneFileBytes);
    } catch (const InputFileError&) {
      b = "unreadable";
    }
    const uint64_t n[2] = {key.size(), b.size()};
    h.update(n, sizeof(n));  // lengths delimit the parts
    h.update(key.data(), key.size());
    h.update(b.data(), b.size());
  }
  const auto digest = h.finish();
  return toHex(digest.data(), digest.size());
}

namespace {

// A user's resolve in force: none of the built-in resolve's settings (it replaces them), and
// every constant the shader declares with its typed value, given or default.
nlohmann::json userShaderJson(const spec::CheckedCase& spec, const nlohmann::json& taa) {
  nlohmann::json out;
  for (const char* key : {"mode", "shader", "shader_language", "shader_clamps"}) out[key] = taa[key];
  const LoadedUserShader shader(spec);
  if (shader.hlsl()) out["shader_entry"] = taa["shader_entry"];
  auto params = nlohmann::json::array();
  for (const auto& v : shader.paramValues(spec.taa)) {
    params.push_back({{"name", v.name},
                      {"value", toJson(v.value)},
                      {"type", user::paramTypeName(v.type)},
                      {"given", v.given}});
    // Only a constant the compile removed says so: every other case prints as it did.
    if (v.unread) params.back()["unread"] = "not read by the shader's code";
  }
  out["shader_params"] = params;
  // Only a shader with loose uniforms has the key: every other case prints as it did.
  if (const std::string line = shader.uniformsLine(spec.taa); !line.empty())
    out["shader_uniforms"] = line;
  if (!spec.taa.shader_defines.empty()) out["shader_defines"] = taa["shader_defines"];
  return out;
}

}  // namespace

nlohmann::json readJsonFile(const std::filesystem::path& file) {
  std::string text;
  try {
    text = readInputFile(file, kMaxCaseFileBytes);
  } catch (const InputFileError& e) {
    throw CaseError({e.what()});
  }
  if (const std::string problem = jsonStructureProblem(text); !problem.empty())
    throw CaseError({file.string() + ": " + problem});
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw CaseError({file.string() + ": not valid JSON (" + jsonErrorWithoutContent(e.what()) + ")"});
  }
}

LoadedCase parseCase(const std::string& text, const std::filesystem::path& file) {
  return parseCase(text, file, {});
}

LoadedCase parseCase(const std::string& text, const std::filesystem::path& file,
                     const LaneParse& lane) {
  const std::string where = file.string();
  if (const std::string problem = jsonStructureProblem(text); !problem.empty())
    throw CaseError({where + ": " + problem});
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into line:column for the user.
    const size_t offset = std::min<size_t>(e.byte, text.size());
    int line = 1, column = 1;
    for (size_t i = 0; i + 1 < offset; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw CaseError({where + ":" + std::to_string(line) + ":" + std::to_string(column) +
                     ": not valid JSON (" + jsonErrorWithoutContent(e.what()) + "); fix the syntax at that position"});
  } catch (const nlohmann::json::exception&) {  // found by fuzz_case: 1e999 overflows a double
    throw CaseError({where + ": a number is too large for a double (over about 1.8e308); fix the number"});
  }
  if (!root.is_object()) throw CaseError({where + ": the case must be a JSON object {...}"});
  if (const auto bad = controlCharacterProblems(root); !bad.empty()) {
    std::vector<std::string> problems;
    for (const auto& [key, msg] : bad) problems.push_back(where + ": " + key + ": " + msg);
    throw CaseError(problems);
  }

  LoadedCase out;
  out.spec.file = file;
  out.spec.name = file.stem().string();
  ReadContext ctx{where, {}, {}};
  JsonReader reader(root, "", ctx);
  fields(reader, out.spec);
  reader.finish();
  if (!ctx.problems.empty()) throw CaseError(ctx.problems);
  out.present = std::move(ctx.present);
  if (!lane.shaderRoot.empty())
    out.spec.taa.shader_root = fs::absolute(lane.shaderRoot).lexically_normal().string();
  out.spec.taa.shader_capabilities_unchecked = lane.capabilitiesUnchecked;
  validateCase(out.spec, out.present);
  out.sha256 = inputsSha256(out.spec, text);
  out.abCase = abCaseJson(root, out.spec);
  return out;
}

LoadedCase loadCase(const std::filesystem::path& file) {
  try {
    return parseCase(readInputFile(file, kMaxCaseFileBytes), file);
  } catch (const InputFileError& e) {
    throw CaseError({std::string(e.what())});
  }
}

nlohmann::json resolvedJson(const spec::CheckedCase& spec) {
  nlohmann::json out;
  JsonWriter writer(out);
  auto copy = spec;
  fields(writer, copy);
  // taa.moving is a second parameter set only when the case gives one.
  if (!spec.taa.moving.active) out["taa"].erase("moving");
  if (!spec.taa.shader.empty()) out["taa"] = userShaderJson(spec, out["taa"]);
  return out;
}

nlohmann::json settingsSchema() {
  auto rows = nlohmann::json::array();
  SchemaLister lister(rows, "");
  spec::CheckedCase defaults;
  fields(lister, defaults);
  // The spec holds invariant names as strings (the renderer does not know the harness's
  // invariants); their allowed values come from the invariant table.
  for (auto& row : rows)
    if (row["key"] == "checks.invariants") {
      row["type"] = "list of enum";
      row["allowed"] = invariants::invariantNames();
    }
  return rows;
}

}  // namespace taa::cases
