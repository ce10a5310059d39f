#include "user/glsl_compiler.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <sstream>

#include "api/shader_defines.h"
#include "core/input_file.h"
#include "core/sha256.h"
#include "user/compile_sandbox.h"
#include "user/entry_checks.h"
#include "user/shader_bounds.h"
#include "user/spirv_cache.h"
#include "user/spirv_check.h"
#include "user/user_capabilities.h"
#include "user/user_includer.h"
#include "user/user_interface.h"
#include "vk/pipeline.h"

namespace taa::user {

namespace fs = std::filesystem;

namespace {

// Bumped when what this file passes to glslang, or what a cache entry holds, changes, so older
// cache entries are ignored ("entry2": a constant's id is stored).
constexpr const char* kCompilerTag = "taa-user 3 vulkan1.2 spv1.5 params19 entry2";

// The tag and the version of the glslang this program links: two builds sharing one cache
// folder (a distribution's and a newer glslang's) must not take each other's SPIR-V.
const std::string& compilerKey() {
  static const std::string key = [] {
    const glslang::Version v = glslang::GetVersion();
    return std::string(kCompilerTag) + " glslang " + std::to_string(v.major) + "." +
           std::to_string(v.minor) + "." + std::to_string(v.patch) + v.flavor;
  }();
  return key;
}

void initGlslangOnce() {
  static const bool done = [] {
    glslang::InitializeProcess();
    std::atexit([] { glslang::FinalizeProcess(); });
    return true;
  }();
  (void)done;
}

// What every compile of a language tells glslang besides its text, the one warm-up included.
// `preamble` must outlive the shader's parse: glslang keeps the pointer.
void configureShader(glslang::TShader& shader, const CompileOptions& o, std::string& preamble) {
  preamble = shaderDefinePreamble(o.defines);
  if (o.language == ShaderLanguage::Hlsl) {
    if (!preamble.empty()) shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceHlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    // The SPIR-V keeps the name: glslang given only a source entry point falls back on a
    // function called main, or renames the entry onto one, without a word.
    shader.setEntryPoint(o.entry.c_str());
    shader.setSourceEntryPoint(o.entry.c_str());
  } else {
    // The include extension is on for every user shader, as it is for the built-in ones.
    preamble = "#extension GL_GOOGLE_include_directive : require\n" + preamble;
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
  }
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
}

// HLSL's non-static globals ($Global) moved to the loose uniforms' binding from glslang's
// binding 0 (taa_frame's), so an engine's shader runs with its material properties as they
// are. (glslang's setGlobalUniformBinding reaches only GLSL's relaxed globals, not HLSL's.)
void bindGlobalUniforms(std::vector<unsigned int>& w) {
  constexpr uint32_t kOpName = 5, kOpTypePointer = 32, kOpVariable = 59, kOpDecorate = 71,
                     kDecoBinding = 33;
  auto each = [&](auto&& f) {
    for (size_t i = 5; i < w.size() && (w[i] >> 16) != 0 && i + (w[i] >> 16) <= w.size();
         i += w[i] >> 16)
      f(w[i] & 0xffffu, i);
  };
  uint32_t block = 0;
  each([&](uint32_t op, size_t i) {
    if (op == kOpName && (w[i] >> 16) >= 4 && std::memcmp(&w[i + 2], "$Glo", 4) == 0 &&
        std::memcmp(&w[i + 3], "bal", 4) == 0)
      block = w[i + 1];
  });
  if (block == 0) return;
  std::vector<uint32_t> pointers, variables;
  each([&](uint32_t op, size_t i) {
    if (op == kOpTypePointer && (w[i] >> 16) >= 4 && w[i + 3] == block)
      pointers.push_back(w[i + 1]);
  });
  each([&](uint32_t op, size_t i) {
    if (op == kOpVariable && (w[i] >> 16) >= 4 &&
        std::find(pointers.begin(), pointers.end(), w[i + 1]) != pointers.end())
      variables.push_back(w[i + 2]);
  });
  each([&](uint32_t op, size_t i) {
    if (op == kOpDecorate && (w[i] >> 16) >= 4 && w[i + 2] == kDecoBinding &&
        std::find(variables.begin(), variables.end(), w[i + 1]) != variables.end())
      w[i + 3] = kUserParams;
  });
}

EShMessages messagesFor(ShaderLanguage l) {
  return EShMessages(EShMsgSpvRules | EShMsgVulkanRules |
                     (l == ShaderLanguage::Hlsl ? EShMsgReadHlsl : EShMsgDefault));
}

int versionFor(ShaderLanguage l) { return l == ShaderLanguage::Hlsl ? 100 : 450; }

// glslang parses the declarations of every built-in function into shared tables on a process's
// first compile of a language and version: most of a small shader's compile (about 0.15 s of
// CPU). Every compile runs in a child forked for it, which would build them again and die with
// them. A fixed shader of ours, compiled here in the parent once per language, builds them
// before the first fork, and every child inherits them (a user's shader that declares another
// #version still builds its own in its child). The warm-up's result is not used: only the
// tables it leaves behind. It runs under the sandbox's lock (runSandboxed's inParent): a worker
// forking while another was inside glslang here would give its child glslang's lock, held by a
// thread the child does not have.
void warmBuiltinsOnce(ShaderLanguage language) {
  static std::once_flag glsl, hlsl;
  const bool isHlsl = language == ShaderLanguage::Hlsl;
  std::call_once(isHlsl ? hlsl : glsl, [&] {
    initGlslangOnce();
    CompileOptions o;
    o.language = language;
    o.entry = "main";
    const char* text = isHlsl ? "[numthreads(1, 1, 1)] void main() {}\n"
                              : "#version 450\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
    glslang::TShader shader(EShLangCompute);
    shader.setStrings(&text, 1);
    std::string preamble;
    configureShader(shader, o, preamble);
    shader.parse(GetDefaultResources(), versionFor(language), false, messagesFor(language));
  });
}

// "3 s", "0.25 s".
std::string secondsText(std::chrono::milliseconds d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", double(d.count()) / 1000.0);
  return buf;
}

// glslang's log, less its "ERROR: " prefixes, the trailing "N compilation errors" line,
// lines containing `drop` and the echoes of a #error (it stops the preprocessor, which then
// reports each #if still open as a "missing #endif"), so each line starts with the user's file
// and line. (HLSL's "parsing failed" line stays: it names the top file's line of an include.)
std::string cleanLog(const std::string& log, const std::string& drop = "") {
  std::istringstream in(log);
  std::string line, out;
  bool stopped = false;  // a #error was reported
  while (std::getline(in, line)) {
    if (line.empty() || line.find("compilation errors.") != std::string::npos) continue;
    if (!drop.empty() && line.find(drop) != std::string::npos) continue;
    if (stopped && line.find("'' : missing #endif") != std::string::npos) continue;
    if (line.rfind("ERROR: ", 0) == 0) line = line.substr(7);
    stopped |= line.find("'#error' :") != std::string::npos;
    out += (out.empty() ? "" : "\n") + line;
  }
  return out;
}

struct GlslangOutput {
  std::vector<uint32_t> spirv;
  std::vector<fs::path> includes;
  std::string preprocessed;  // its #pragma taa_supports lines say what the shader declares
};

void appendU32(std::string& out, uint32_t v) {
  out.append(reinterpret_cast<const char*>(&v), 4);
}

void appendString(std::string& out, const std::string& v) {
  appendU32(out, uint32_t(v.size()));
  out += v;
}

uint32_t readU32(const std::string& in, size_t& at) {
  uint32_t v = 0;
  if (at + 4 > in.size()) throw ShaderCompileError("the compiler's child process sent a short reply");
  std::memcpy(&v, in.data() + at, 4);
  at += 4;
  return v;
}

std::string readString(const std::string& in, size_t& at) {
  const uint32_t len = readU32(in, at);
  if (at + len > in.size()) throw ShaderCompileError("the compiler's child process sent a short reply");
  std::string v = in.substr(at, len);
  at += len;
  return v;
}

// The compile itself, in the sandbox's child: preprocess, check the preprocessed text against
// the bounds, parse, link, SPIR-V. Returns 'S', the included files, the preprocessed text and
// the words, or 'E' and the message the user sees. HLSL takes glslang's HLSL front end, the
// entry point the options name (renamed "main" in the SPIR-V) and spirv-opt's legalization,
// which Vulkan needs for HLSL's textures passed to functions; GLSL is compiled unoptimised.
std::string glslangInChild(const fs::path& source, const std::string& text, const fs::path& root,
                           const fs::path& headerDir, const CompileOptions& o) {
  initGlslangOnce();
  const bool hlsl = o.language == ShaderLanguage::Hlsl;
  const std::string name = source.string();
  const char* strings[] = {text.c_str()};
  const int lengths[] = {int(text.size())};
  const char* names[] = {name.c_str()};
  std::string preamble;
  auto configure = [&](glslang::TShader& shader) {
    shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
    configureShader(shader, o, preamble);
  };
  const auto messages = messagesFor(o.language);
  const int version = versionFor(o.language);
  auto fail = [](const UserIncluder& includer, const std::string& log) {
    // After the includer refused, glslang repeats "Could not process include directive" for
    // every include it still meets: the includer's one reason says it.
    std::string msg = cleanLog(log, includer.problem().empty() ? "" : "Could not process include");
    if (!includer.problem().empty()) msg = includer.problem() + (msg.empty() ? "" : "\n" + msg);
    return "E" + msg + "\n(fix the shader; docs/user-taa.md describes the interface)";
  };
  std::string preprocessed;
  {
    // The preprocessor alone first: what the parser would recurse over is bounded before
    // the parser sees it.
    UserIncluder includer(root, headerDir);
    glslang::TShader shader(EShLangCompute);
    configure(shader);
    sandboxCpuBudget(o.preprocessCpu,
                     "E" + name + ": its preprocessor ran more than " +
                         secondsText(o.preprocessCpu) +
                         " of CPU, the bound for macros and includes (a macro that expands "
                         "itself many times over?); simplify the macros");
    const bool preprocessedOk = shader.preprocess(GetDefaultResources(), version, ENoProfile, false,
                                                  false, messages, &preprocessed, includer);
    sandboxCpuBudget({}, "");
    if (!preprocessedOk) return fail(includer, shader.getInfoLog());
    if (preprocessed.size() > kMaxPreprocessedBytes)
      return "E" + name + ": expands to " + std::to_string(preprocessed.size()) +
             " bytes after macros and includes, over the bound of " +
             std::to_string(kMaxPreprocessedBytes >> 20) + " MiB; a macro that expands itself?";
    if (const std::string why = expressionDepthProblem(preprocessed, name); !why.empty())
      return "E" + why;
  }
  UserIncluder includer(root, headerDir);
  glslang::TShader shader(EShLangCompute);
  configure(shader);
  if (!shader.parse(GetDefaultResources(), version, false, messages, includer))
    return fail(includer, shader.getInfoLog());
  if (hlsl && shader.getIntermediate()->getNumEntryPoints() == 0)
    return "E" + name + ": has no function " + o.entry +
           " to run (taa.shader_entry, default main); name the entry point, the function with "
           "[numthreads(X, Y, 1)]";
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) return fail(includer, program.getInfoLog());
  if (const std::string why = entryPointProblem(*program.getIntermediate(EShLangCompute), name,
                                                hlsl ? o.entry : "main");
      !why.empty())
    return "E" + why;
  std::vector<unsigned int> words;
  glslang::SpvOptions options;
  options.generateDebugInfo = false;
  options.disableOptimizer = !hlsl;
  glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), words, &options);
  bindGlobalUniforms(words);
  std::string out = "S";
  appendU32(out, uint32_t(includer.files().size()));
  for (const auto& f : includer.files()) appendString(out, f.string());
  appendString(out, preprocessed);
  out.append(reinterpret_cast<const char*>(words.data()), words.size() * 4);
  return out;
}

// glslang in a child process under compileLimits(): a shader that would crash it, exhaust
// memory or never finish is refused naming the bound, and the harness carries on.
GlslangOutput runGlslang(const fs::path& source, const std::string& text, const fs::path& root,
                         const fs::path& headerDir, const CompileOptions& options) {
  const SandboxLimits limits = compileLimits();
  const SandboxOutcome o = runSandboxed(
      [&] { return glslangInChild(source, text, root, headerDir, options); }, limits,
      [&] { warmBuiltinsOnce(options.language); });
  if (o.end == SandboxEnd::Unavailable)
    throw EnvironmentError("cannot start the shader compiler's child process: " + o.detail);
  if (o.end != SandboxEnd::Done || o.output.empty())
    throw ShaderCompileError(
        source.string() + ": compiling it took " + describeSandboxEnd(o, limits) +
        ", past the bounds of one shader's compile (" + std::to_string(limits.cpuSeconds) +
        " s of CPU, " + std::to_string(limits.memoryBytes >> 20) +
        " MiB); simplify it (macros that expand into huge code, deep recursion of expressions)");
  if (o.output[0] == 'E') throw ShaderCompileError(o.output.substr(1));
  GlslangOutput out;
  size_t at = 1;
  const uint32_t count = readU32(o.output, at);
  for (uint32_t i = 0; i < count; ++i) out.includes.emplace_back(readString(o.output, at));
  out.preprocessed = readString(o.output, at);
  out.spirv.resize((o.output.size() - at) / 4);
  std::memcpy(out.spirv.data(), o.output.data() + at, out.spirv.size() * 4);
  return out;
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
  if (const auto problems = shaderDefineProblems(o.defines); !problems.empty())
    throw ShaderCompileError(source.string() + ": " + problems.front());
  Sha256 h;
  for (const std::string& part :
       {compilerKey(), std::string(languageName(o.language)), o.entry, real.string(),
        fs::weakly_canonical(headerDir).string(), fs::weakly_canonical(o.root).string(),
        shaderDefinePreamble(o.defines), text}) {
    h.update(part.data(), part.size());
    h.update("\0", 1);
  }
  const auto digest = h.finish();
  const std::string key = toHex(digest.data(), digest.size());

  CompiledShader out;
  std::string miss;
  // Cached or fresh, no driver sees SPIR-V the validator has not passed.
  auto checked = [&](CompiledShader& c) -> CompiledShader& {
    if (const std::string why = userSpirvProblem(c.spirv, source.string()); !why.empty())
      throw ShaderCompileError(why);
    return c;
  };
  if (readSpirvCache(cacheDir, key, out, miss)) {
    out.provenance = provenanceOf(key, "from the cache", false);
    return checked(out);
  }
  out = CompiledShader{};
  GlslangOutput g = runGlslang(source, text, o.root, headerDir, o);
  out.spirv = std::move(g.spirv);
  out.includes = std::move(g.includes);
  out.capabilities = declaredCapabilities(g.preprocessed, source.string());
  out.constants = declaredConstants(g.preprocessed);
  // Checked on the source too: HLSL's compile removes a constant it never reads, id and all.
  for (const auto& c : out.constants)
    if (c.id > int64_t(kMaxUserConstantId))
      throw ShaderCompileError(source.string() + ": specialization constant " + c.name +
                               " has constant_id " + std::to_string(c.id) +
                               "; taa_user.h allows 0 to " + std::to_string(kMaxUserConstantId));
  checked(out);
  const std::string notCached = writeSpirvCache(cacheDir, key, out);  // said in the run log
  out.provenance = provenanceOf(
      key,
      (miss.empty() ? "compiled by glslang: no cache entry" : "recompiled by glslang: " + miss) +
          (notCached.empty() ? "" : "; not cached: " + notCached),
      true);
  return out;
}

}  // namespace taa::user
