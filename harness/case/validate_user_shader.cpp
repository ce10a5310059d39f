#include "case/validate_user_shader.h"

#include <filesystem>

#include "api/shader_defines.h"
#include "api/user_shader.h"
#include "case/case_validate.h"
#include "spec/taa_modes.h"

namespace taa::cases {

std::vector<std::pair<std::string, std::string>> userShaderProblems(
    const spec::CheckedCase& spec, const std::set<std::string>& present) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto& t = spec.taa;
  if (t.shader.empty()) {
    for (const char* k : {"taa.shader_params", "taa.shader_defines", "taa.shader_clamps",
                          "taa.shader_language", "taa.shader_entry"})
      if (present.count(k))
        out.emplace_back(k, "applies only to a user's resolve; set taa.shader or remove it");
    return out;
  }
  if (const std::string why = assetPathProblem(t.shader); !why.empty()) {
    // A lane's or preset's shader resolves beside the file that names it, not beside the case.
    out.emplace_back("taa.shader",
                     t.shader_root.empty()
                         ? why
                         : "'" + t.shader + "' leaves " + t.shader_root +
                               ", the folder of the lanes or presets file that names it; give a "
                               "path under that folder");
    return out;
  }
  if (!spec::modeRule(t.mode).standIn)
    out.emplace_back(
        "taa.mode",
        std::string("a user's resolve (taa.shader) replaces the full resolve, but taa.mode is ") +
            spec::enumToString(t.mode) + "; set taa.mode to " +
            spec::modeNames(spec::modesWhere(&spec::ModeRule::standIn)) + " or remove taa.shader");
  // The built-in resolve's settings would be accepted and ignored.
  for (const auto& key : present) {
    if (key.rfind("taa.", 0) != 0 || key == "taa.mode" || key.rfind("taa.shader", 0) == 0) continue;
    out.emplace_back(
        key,
        "is a setting of the built-in resolve, which taa.shader replaces; remove it "
        "(or give your shader a specialization constant and set it in taa.shader_params)");
  }
  if (spec.debug.output != spec::DebugOutput::None)
    out.emplace_back("debug.output",
                     "debug views come from the built-in resolve; remove it with taa.shader");
  if (present.count("taa.shader_entry") && !userShaderIsHlsl(t))
    out.emplace_back("taa.shader_entry",
                     "names an HLSL entry point, but " + t.shader +
                         " is GLSL (whose entry is main); remove it, or set taa.shader_language "
                         "to hlsl if the file is HLSL");
  if (t.shader_entry.empty())
    out.emplace_back("taa.shader_entry", "is empty; name the HLSL function to run, or remove it");
  // Bounded before anything looks at them in pairs (10,000 entries once took 4.6 GB of
  // messages): no shader declares more specialization constants than this.
  if (t.shader_params.size() > kMaxShaderParams) {
    out.emplace_back("taa.shader_params",
                     std::to_string(t.shader_params.size()) + " entries, over the limit of " +
                         std::to_string(kMaxShaderParams) +
                         "; give one entry per specialization constant of the shader");
    return out;
  }
  // A missing value would silently be 0.
  for (size_t i = 0; i < t.shader_params.size(); ++i) {
    const std::string key = "taa.shader_params[" + std::to_string(i) + "]";
    for (const char* k : {".name", ".value"})
      if (!present.count(key + k))
        out.emplace_back(key + k, std::string("is missing; give the constant's ") + (k + 1));
  }
  for (const auto& p : user::shaderDefineProblems(t.shader_defines)) {
    const auto colon = p.find(": ");
    out.emplace_back(p.substr(0, colon), p.substr(colon + 2));
  }
  if (!out.empty()) return out;
  try {
    const LoadedUserShader shader(spec);
    auto problems = shader.paramProblems(t);
    for (auto& p : shader.defineProblems(t)) problems.push_back(std::move(p));
    for (const auto& p : problems) {
      const auto colon = p.find(": ");
      out.emplace_back(p.substr(0, colon), p.substr(colon + 2));
    }
    if (!t.shader_capabilities_unchecked)
      for (const auto& why : shader.missingCapabilities(spec))
        out.emplace_back("taa.shader", why);
    // Array lengths the case's values give: the default passed when the shader loaded.
    if (out.empty())
      if (const std::string why = shader.memoryProblem(t); !why.empty())
        out.emplace_back("taa.shader_params", "with these values " + shader.file().string() + ": " + why);
  } catch (const user::ShaderCompileError& e) {
    out.emplace_back("taa.shader", std::string("does not compile:\n") + e.what());
  }
  return out;
}

}  // namespace taa::cases
