#include "user/user_capabilities.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "script/frame_state.h"
#include "user/glsl_compiler.h"

namespace taa::user {

namespace {

// Why the case needs capability `name`, or "" when it does not. Every row of
// kCapabilities has a branch here (a unit test checks each against a case that needs it).
std::string capabilityNeed(const std::string& name, const spec::CaseSpec& s) {
  const glm::ivec2 output{s.render.width, s.render.height};
  glm::ivec2 first{0}, smallest = output;
  bool changes = false;
  for (int f = 0; f < std::max(1, s.script.frames); ++f) {
    const glm::ivec2 size = script::renderSizeFor(s.render, script::renderScaleAt(s.render, f));
    if (f == 0) first = size;
    changes |= size != first;
    smallest = glm::min(smallest, size);
  }
  std::ostringstream why;
  if (name == "upsampling") {
    if (smallest == output) return "";
    why << "the case renders at " << smallest.x << "x" << smallest.y << " under its "
        << output.x << "x" << output.y << " output (";
    if (s.render.upsample != 1.0f)
      why << "render.upsample " << s.render.upsample << ")";
    else
      why << "render.scale_schedule)";
    return why.str();
  }
  if (name == "dynamic_resolution") {
    if (!changes) return "";
    return "the case's render size changes from frame to frame (render.scale_schedule)";
  }
  throw std::logic_error("user_capabilities.cpp: no rule for capability " + name);
}

}  // namespace

std::vector<std::string> declaredCapabilities(const std::string& preprocessed,
                                              const std::string& file) {
  std::vector<std::string> out;
  std::istringstream in(preprocessed);
  const std::string lead = "taa_supports(";
  for (std::string line; std::getline(in, line);) {
    const size_t hash = line.find_first_not_of(" \t");
    if (hash == std::string::npos || line.compare(hash, 7, "#pragma") != 0) continue;
    // glslang writes a pragma's tokens without the spaces between them.
    std::string tokens;
    for (char c : line.substr(hash + 7))
      if (c != ' ' && c != '\t') tokens += c;
    if (tokens.rfind(lead, 0) != 0 || tokens.back() != ')') continue;
    const std::string name = tokens.substr(lead.size(), tokens.size() - lead.size() - 1);
    const bool known = std::any_of(std::begin(kCapabilities), std::end(kCapabilities),
                                   [&](const CapabilityInfo& c) { return name == c.name; });
    if (!known) {
      std::string names;
      for (const auto& c : kCapabilities) names += (names.empty() ? "" : ", ") + std::string(c.name);
      throw ShaderCompileError(file + ": #pragma taa_supports(" + name +
                               ") names no capability the harness knows (" + names +
                               "); define the header's TAA_SUPPORTS_* macro instead");
    }
    out.push_back(name);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::string> missingCapabilities(const spec::CaseSpec& spec,
                                             const std::vector<std::string>& declared,
                                             const std::string& shader) {
  std::vector<std::string> out;
  for (const CapabilityInfo& c : kCapabilities) {
    const std::string why = capabilityNeed(c.name, spec);
    if (why.empty() || std::find(declared.begin(), declared.end(), c.name) != declared.end())
      continue;
    out.push_back(why + ", and " + shader + " does not declare " + c.name + " (" + c.doc +
                  "; once it does, #define " + c.macro + " before including the header)");
  }
  return out;
}

}  // namespace taa::user
