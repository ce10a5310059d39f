#include "user/glsl_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

#include "core/input_file.h"
#include "core/output_file.h"
#include "core/sha256.h"
#include "user/user_capabilities.h"
#include "vk/pipeline.h"

namespace taa::user {

namespace fs = std::filesystem;

namespace {

// A user shader and its headers are small; the bound keeps a wrong path from reading a disk image.
constexpr uint64_t kMaxUserShaderBytes = uint64_t(1) << 20;
constexpr size_t kMaxIncludeDepth = 32;
// Bumped when what this file passes to glslang changes, so older cache entries are ignored.
constexpr const char* kCompilerTag = "taa-user 2 glslang 12 vulkan1.2 spv1.5";

bool isInside(const fs::path& dir, const fs::path& file) {
  if (dir.empty()) return false;
  const auto rel = file.lexically_relative(dir);
  return !rel.empty() && *rel.begin() != "..";
}

std::string readShaderText(const fs::path& file, const std::string& what) {
  try {
    return readInputFile(file, kMaxUserShaderBytes);
  } catch (const InputFileError& e) {
    throw ShaderCompileError(what + ": " + e.what());
  }
}

// Resolves #include against the including file's folder, then the installed headers. A file
// found beside the includer but outside the allowed folders is refused, not skipped, so a
// header can never be taken from somewhere the user did not mean.
class UserIncluder : public glslang::TShader::Includer {
 public:
  UserIncluder(fs::path root, fs::path headerDir)
      : root_(std::move(root)), headerDir_(std::move(headerDir)) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
    return resolve(header, includer, depth, true);
  }
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    return resolve(header, includer, depth, false);
  }
  void releaseInclude(IncludeResult* r) override {
    if (r) delete static_cast<std::string*>(r->userData);
    delete r;
  }

  // A new includer with the same folders, for a second pass over the same text.
  UserIncluder fresh() const { return UserIncluder(root_, headerDir_); }
  const std::vector<fs::path>& files() const { return files_; }
  const std::string& problem() const { return problem_; }

 private:
  IncludeResult* resolve(const char* header, const char* includer, size_t depth, bool local) {
    if (depth > kMaxIncludeDepth) {
      problem_ = std::string(includer) + ": includes nest deeper than " +
                 std::to_string(kMaxIncludeDepth) +
                 " (a header including itself?); break the cycle";
      return nullptr;
    }
    std::vector<fs::path> candidates;
    if (local) candidates.push_back(fs::path(includer).parent_path() / header);
    if (!headerDir_.empty()) candidates.push_back(headerDir_ / header);
    std::error_code ec;
    for (const auto& c : candidates) {
      if (!fs::exists(c, ec)) continue;
      const fs::path real = fs::canonical(c, ec);
      if (ec) continue;
      if (!isInside(rootReal(), real) && !isInside(headerReal(), real)) {
        problem_ = std::string(includer) + ": #include \"" + header + "\" resolves to " +
                   real.string() + ", outside the shader's folder " + rootReal().string() +
                   "; move the header under that folder";
        return nullptr;
      }
      auto* text = new std::string(
          readShaderText(real, std::string(includer) + ": #include \"" + header + "\""));
      files_.push_back(real);
      return new IncludeResult(real.string(), text->data(), text->size(), text);
    }
    // glslang asks the system paths after a failed local lookup: keep the first, sharper reason.
    if (!problem_.empty()) return nullptr;
    problem_ = std::string(includer) + ": #include \"" + header + "\" not found beside it" +
               (headerDir_.empty() ? "" : " nor in " + headerDir_.string()) +
               "; check the name, or put the header in the shader's folder";
    return nullptr;
  }

  const fs::path& rootReal() {
    if (rootReal_.empty()) {
      std::error_code ec;
      rootReal_ = fs::canonical(root_, ec);
    }
    return rootReal_;
  }
  const fs::path& headerReal() {
    if (headerReal_.empty() && !headerDir_.empty()) {
      std::error_code ec;
      headerReal_ = fs::canonical(headerDir_, ec);
    }
    return headerReal_;
  }

  fs::path root_, headerDir_, rootReal_, headerReal_;
  std::vector<fs::path> files_;
  std::string problem_;
};

void initGlslangOnce() {
  static const bool done = [] {
    glslang::InitializeProcess();
    std::atexit([] { glslang::FinalizeProcess(); });
    return true;
  }();
  (void)done;
}

// glslang's log, less its "ERROR: " prefixes and the trailing "N compilation errors" line,
// so each line starts with the user's file and line.
std::string cleanLog(const std::string& log) {
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.empty() || line.find("compilation errors.") != std::string::npos) continue;
    if (line.rfind("ERROR: ", 0) == 0) line = line.substr(7);
    out += (out.empty() ? "" : "\n") + line;
  }
  return out;
}

// The text is preprocessed first (its #pragma taa_supports lines say what it declares), then
// parsed and linked. HLSL takes glslang's HLSL front end, the entry point the options name
// (renamed "main" in the SPIR-V) and spirv-opt's legalization, which Vulkan needs for
// HLSL's textures passed to functions; GLSL is compiled as it always was.
std::vector<uint32_t> runGlslang(const fs::path& source, const std::string& text,
                                 UserIncluder& includer, const CompileOptions& o,
                                 std::string& preprocessed) {
  initGlslangOnce();
  const bool hlsl = o.language == ShaderLanguage::Hlsl;
  const std::string name = source.string();
  const char* strings[] = {text.c_str()};
  const int lengths[] = {int(text.size())};
  const char* names[] = {name.c_str()};
  auto configure = [&](glslang::TShader& shader) {
    shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
    if (hlsl) {
      shader.setEnvInput(glslang::EShSourceHlsl, EShLangCompute, glslang::EShClientVulkan, 100);
      // The SPIR-V keeps the name: glslang given only a source entry point falls back on a
      // function called main, or renames the entry onto one, without a word.
      shader.setEntryPoint(o.entry.c_str());
      shader.setSourceEntryPoint(o.entry.c_str());
    } else {
      // The include extension is on for every user shader, as it is for the built-in ones.
      shader.setPreamble("#extension GL_GOOGLE_include_directive : require\n");
      shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    }
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
  };
  const auto messages =
      EShMessages(EShMsgSpvRules | EShMsgVulkanRules | (hlsl ? EShMsgReadHlsl : EShMsgDefault));
  const int version = hlsl ? 100 : 450;
  auto fail = [&](const UserIncluder& inc, const std::string& log) {
    std::string msg = cleanLog(log);
    if (!inc.problem().empty()) msg = inc.problem() + (msg.empty() ? "" : "\n" + msg);
    throw ShaderCompileError(msg + "\n(fix the shader; docs/user-taa.md describes the interface)");
  };
  {
    UserIncluder pre = includer.fresh();
    glslang::TShader shader(EShLangCompute);
    configure(shader);
    if (!shader.preprocess(GetDefaultResources(), version, ENoProfile, false, false, messages,
                           &preprocessed, pre))
      fail(pre, shader.getInfoLog());
  }
  glslang::TShader shader(EShLangCompute);
  configure(shader);
  if (!shader.parse(GetDefaultResources(), version, false, messages, includer))
    fail(includer, shader.getInfoLog());
  if (hlsl && shader.getIntermediate()->getNumEntryPoints() == 0)
    throw ShaderCompileError(name + ": has no function " + o.entry +
                             " to run (taa.shader_entry, default main); name the entry point, the "
                             "function with [numthreads(X, Y, 1)]");
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) fail(includer, program.getInfoLog());
  std::vector<unsigned int> words;
  glslang::SpvOptions options;
  options.generateDebugInfo = false;
  options.disableOptimizer = !hlsl;
  glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), words, &options);
  return {words.begin(), words.end()};
}

std::string fileSha(const fs::path& file) {
  const std::string bytes = readShaderText(file, file.string());
  return sha256Hex(bytes.data(), bytes.size());
}

// The cache entry KEY.deps lists the SPIR-V's hash, each include's real path and hash and
// the capabilities the shader declares; KEY.spv holds the words. A hit needs every include
// unchanged and the words intact; on a miss `why` says what changed ("" when there is no
// entry at all).
bool readCache(const fs::path& dir, const std::string& key, CompiledShader& out, std::string& why) {
  std::ifstream deps(dir / (key + ".deps"));
  if (!deps) return false;
  why = "the cache entry was damaged";
  std::string kind, sha, spvSha;
  std::vector<fs::path> includes;
  std::vector<std::string> capabilities;
  std::string line;
  while (std::getline(deps, line)) {
    std::istringstream l(line);
    l >> kind >> sha;
    std::string path;
    std::getline(l >> std::ws, path);
    if (kind == "spv") {
      spvSha = sha;
    } else if (kind == "cap") {
      capabilities.push_back(sha);
    } else if (kind == "inc") {
      std::error_code ec;
      if (!fs::is_regular_file(path, ec)) {
        why = path + " is gone since it was cached";
        return false;
      }
      try {
        if (fileSha(path) != sha) {
          why = path + " changed since it was cached";
          return false;
        }
      } catch (const ShaderCompileError&) {
        why = path + " cannot be read";
        return false;
      }
      includes.emplace_back(path);
    } else {
      return false;
    }
  }
  if (spvSha.empty()) return false;
  std::string bytes;
  try {
    bytes = readInputFile(dir / (key + ".spv"), kMaxUserShaderBytes * 16);
  } catch (const InputFileError&) {
    return false;
  }
  if (bytes.size() % 4 != 0 || sha256Hex(bytes.data(), bytes.size()) != spvSha) return false;
  out.spirv.resize(bytes.size() / 4);
  std::memcpy(out.spirv.data(), bytes.data(), bytes.size());
  out.includes = std::move(includes);
  out.capabilities = std::move(capabilities);
  out.fromCache = true;
  return true;
}

void writeCache(const fs::path& dir, const std::string& key, const CompiledShader& c) {
  createOutputDirectory(dir);
  const std::string_view bytes(reinterpret_cast<const char*>(c.spirv.data()), c.spirv.size() * 4);
  // Words first: a deps file never names SPIR-V that is not there.
  writeFileAtomically(dir / (key + ".spv"), bytes);
  std::string deps = "spv " + sha256Hex(bytes.data(), bytes.size()) + "\n";
  for (const auto& inc : c.includes) deps += "inc " + fileSha(inc) + " " + inc.string() + "\n";
  for (const auto& cap : c.capabilities) deps += "cap " + cap + "\n";
  writeFileAtomically(dir / (key + ".deps"), deps);
}

// What this process last did to get each cache key's SPIR-V (CompiledShader::provenance).
std::string provenanceOf(const std::string& key, const std::string& happened, bool compiled) {
  static std::mutex mutex;
  static std::map<std::string, std::string> last;
  const std::lock_guard<std::mutex> lock(mutex);
  if (compiled) return last[key] = happened;
  const auto it = last.find(key);
  return it == last.end() ? happened : it->second;
}

}  // namespace

const char* languageName(ShaderLanguage l) {
  return l == ShaderLanguage::Hlsl ? "hlsl" : "glsl";
}

ShaderLanguage languageOf(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".hlsl" ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl;
}

fs::path userHeaderDir() {
  return fs::path(vk::shaderDir()) / "include";
}

fs::path userShaderCacheDir() {
  if (const char* env = std::getenv("TAA_SHADER_CACHE"); env && *env) return env;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return fs::path(xdg) / "taa-harness" / "spirv";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "taa-harness" / "spirv";
  return fs::temp_directory_path() / "taa-harness-spirv";
}

CompiledShader compileComputeShader(const fs::path& source, const CompileOptions& o) {
  const fs::path headerDir = o.headerDir.empty() ? userHeaderDir() : o.headerDir;
  const fs::path cacheDir = o.cacheDir.empty() ? userShaderCacheDir() : o.cacheDir;
  fs::path real;
  try {
    real = containedRealPath(o.root, source, "the resolve shader");
  } catch (const InputFileError& e) {
    throw ShaderCompileError(e.what());
  }
  const std::string text = readShaderText(real, source.string());
  Sha256 h;
  for (const std::string& part :
       {std::string(kCompilerTag), std::string(languageName(o.language)), o.entry, real.string(),
        fs::weakly_canonical(headerDir).string(), fs::weakly_canonical(o.root).string(), text}) {
    h.update(part.data(), part.size());
    h.update("\0", 1);
  }
  const auto digest = h.finish();
  const std::string key = toHex(digest.data(), digest.size());

  CompiledShader out;
  std::string miss;
  if (readCache(cacheDir, key, out, miss)) {
    out.provenance = provenanceOf(key, "from the cache", false);
    return out;
  }
  UserIncluder includer(o.root, headerDir);
  std::string preprocessed;
  out = CompiledShader{};
  out.spirv = runGlslang(source, text, includer, o, preprocessed);
  out.includes = includer.files();
  out.capabilities = declaredCapabilities(preprocessed, source.string());
  writeCache(cacheDir, key, out);
  out.provenance = provenanceOf(
      key, miss.empty() ? "compiled by glslang: no cache entry" : "recompiled by glslang: " + miss,
      true);
  return out;
}

}  // namespace taa::user
