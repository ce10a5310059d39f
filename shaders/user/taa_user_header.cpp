// Writes a public header of a user's resolve from its template and the harness's tables:
// taa_user.h (GLSL) from taa_user.h.in, taa_user.hlsli (HLSL) from taa_user.hlsli.in. The
// inputs a shader may declare, their TAA_USE_* guards and documentation come from
// common/resolve_inputs.h; the frame constants, the samplers and the capabilities from
// common/user_frame.h. Run by the build:
//   taa_user_header TEMPLATE OUTPUT glsl|hlsl
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "common/resolve_inputs.h"
#include "common/user_frame.h"

namespace {

struct UserInput {
  std::string name, stype, format, filter, source, macro, doc;
  int binding;
};

#define TAA_USER_ROW(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, udoc) \
  {#uname, #stype, #fmt, #filter, #src, #umacro, udoc, ubind},
const UserInput kRows[] = {TAA_RESOLVE_INPUTS(TAA_USER_ROW)};
#undef TAA_USER_ROW

struct FrameMember {
  std::string type, name, doc;
};
#define TAA_USER_MEMBER(type, name, doc) {#type, #name, doc},
const FrameMember kFrame[] = {TAA_USER_FRAME(TAA_USER_MEMBER)};
#undef TAA_USER_MEMBER

struct Capability {
  std::string name, macro, doc;
};
#define TAA_USER_CAPABILITY(name, macro, doc) {#name, #macro, doc},
const Capability kCapabilities[] = {TAA_USER_CAPABILITIES(TAA_USER_CAPABILITY)};
#undef TAA_USER_CAPABILITY

bool always(const UserInput& r) {
  return r.macro == "TAA_USER_ALWAYS";
}

// "<prefix><lead><doc>", the doc wrapped under itself within 94 columns.
std::string docLines(const std::string& prefix, const std::string& lead, const std::string& doc) {
  const std::string indent = prefix + std::string(lead.size(), ' ');
  std::string out = prefix + lead, word;
  size_t column = out.size();
  std::istringstream words(doc);
  bool first = true;
  while (words >> word) {
    if (!first && column + 1 + word.size() > 94) {
      out += "\n" + indent;
      column = indent.size();
      first = true;
    }
    out += (first ? "" : " ") + word;
    column += (first ? 0 : 1) + word.size();
    first = false;
  }
  return out;
}

std::string pad(std::string s, size_t width) {
  if (s.size() < width) s.resize(width, ' ');
  return s + " ";
}

std::string substitute(std::string text, const std::string& marker, const std::string& value) {
  const std::string key = "@" + marker + "@";
  for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
    text.replace(at, key.size(), value);
  return text;
}

// An input's HLSL type: the components its image holds, so `.xy` of the velocity reads as
// in GLSL and a depth reads as one float.
std::string hlslTexture(const UserInput& r) {
  if (r.stype[0] == 'u') return "Texture2D<uint4>";
  if (r.format.rfind("D32", 0) == 0) return "Texture2D<float>";
  if (r.format.rfind("R16G16_", 0) == 0 || r.format.rfind("R32G32_", 0) == 0)
    return "Texture2D<float2>";
  return "Texture2D<float4>";
}

std::string hlslType(const std::string& glslType) {
  if (glslType == "mat4") return "float4x4";
  if (glslType == "vec4") return "float4";
  if (glslType == "uvec4") return "uint4";
  return "?" + glslType;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || (std::string(argv[3]) != "glsl" && std::string(argv[3]) != "hlsl")) {
    std::cerr << "usage: taa_user_header TEMPLATE OUTPUT glsl|hlsl\n";
    return 2;
  }
  const bool hlsl = std::string(argv[3]) == "hlsl";
  std::ifstream in(argv[1]);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) {
    std::cerr << "taa_user_header: cannot read " << argv[1] << "\n";
    return 3;
  }
  std::vector<UserInput> rows;
  for (const UserInput& r : kRows)
    if (r.binding >= 0) rows.push_back(r);
  std::sort(rows.begin(), rows.end(),
            [](const UserInput& a, const UserInput& b) { return a.binding < b.binding; });
  // HLSL samples a texture through a sampler of its choosing: an image two rows offer
  // with two filters (the colour, point and bilinear) is one texture there.
  if (hlsl) {
    std::vector<UserInput> once;
    for (const UserInput& r : rows)
      if (std::none_of(once.begin(), once.end(),
                       [&](const UserInput& o) { return o.source == r.source; }))
        once.push_back(r);
    rows = once;
  }

  // Columns as wide as their longest entry and one more (the template's taa_output line).
  size_t nameWidth = 0, macroWidth = 0;
  for (const UserInput& r : rows) {
    nameWidth = std::max(nameWidth, r.name.size() + 1);
    if (!always(r)) macroWidth = std::max(macroWidth, r.macro.size() + 1);
  }
  std::string alwaysDocs, macroDocs, declarations;
  for (UserInput r : rows) {
    // GLSL binds each input with its row's filter; the template says the rest are point.
    if (!hlsl && r.filter == "LINEAR") r.doc += " (bilinear sampler)";
    const std::string b = std::to_string(r.binding);
    const std::string decl =
        hlsl ? "[[vk::binding(" + b + ", 0)]] " + hlslTexture(r) + " " + r.name + ";\n"
             : "layout(set = 0, binding = " + b + ") uniform " + r.stype + " " + r.name + ";\n";
    if (always(r)) {
      alwaysDocs += (alwaysDocs.empty() ? "" : "\n") + docLines("//   ", pad(r.name, nameWidth), r.doc);
      declarations += decl;
    } else {
      macroDocs += (macroDocs.empty() ? "" : "\n") +
                   docLines("//   ", pad(r.macro, macroWidth) + pad(r.name, nameWidth), r.doc);
      declarations += "#ifdef " + r.macro + "\n" + decl + "#endif\n";
    }
  }
  if (!declarations.empty()) declarations.pop_back();  // the template's line ends it

  std::string members;
  for (const FrameMember& m : kFrame)
    members += (members.empty() ? "" : "\n") + docLines("  // ", "", m.doc) + "\n  " +
               (hlsl ? hlslType(m.type) : m.type) + " " + m.name + ";";
  std::string capabilityDocs, pragmas;
  size_t capWidth = 0;
  for (const Capability& c : kCapabilities) capWidth = std::max(capWidth, c.macro.size() + 1);
  for (const Capability& c : kCapabilities) {
    capabilityDocs += (capabilityDocs.empty() ? "" : "\n") +
                      docLines("//   ", pad(c.macro, capWidth), c.doc);
    // The harness reads what a shader declares from these pragmas in its preprocessed text.
    pragmas += (pragmas.empty() ? "" : "\n") + std::string("#ifdef ") + c.macro +
               "\n#pragma taa_supports(" + c.name + ")\n#endif";
  }

  std::string text = buffer.str();
  text = substitute(text, "TAA_USER_ALWAYS_DOCS", alwaysDocs);
  text = substitute(text, "TAA_USER_MACRO_DOCS", macroDocs);
  text = substitute(text, "TAA_USER_CAPABILITY_DOCS", capabilityDocs);
  text = substitute(text, "TAA_USER_CAPABILITY_PRAGMAS", pragmas);
  text = substitute(text, "TAA_USER_FRAME_MEMBERS", members);
  text = substitute(text, "TAA_USER_INPUT_DECLARATIONS", declarations);
  const std::pair<const char*, int> bindings[] = {
      {"TAA_USER_BINDING_FRAME", TAA_USER_BINDING_FRAME},
      {"TAA_USER_BINDING_OUTPUT", TAA_USER_BINDING_OUTPUT},
      {"TAA_USER_BINDING_HISTORY0_OUT", TAA_USER_BINDING_HISTORY0_OUT},
      {"TAA_USER_BINDING_HISTORY1_OUT", TAA_USER_BINDING_HISTORY1_OUT},
      {"TAA_USER_BINDING_HISTORY0", TAA_USER_BINDING_HISTORY0},
      {"TAA_USER_BINDING_HISTORY1", TAA_USER_BINDING_HISTORY1},
      {"TAA_USER_BINDING_POINT_SAMPLER", TAA_USER_BINDING_POINT_SAMPLER},
      {"TAA_USER_BINDING_LINEAR_SAMPLER", TAA_USER_BINDING_LINEAR_SAMPLER},
      {"TAA_USER_BINDING_PARAMS", TAA_USER_BINDING_PARAMS},
  };
  for (const auto& [marker, value] : bindings) text = substitute(text, marker, std::to_string(value));
  if (text.find('@') != std::string::npos) {
    std::cerr << "taa_user_header: " << argv[1] << " has a marker this tool does not fill\n";
    return 2;
  }
  std::ofstream out(argv[2], std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::cerr << "taa_user_header: cannot write " << argv[2] << "\n";
    return 3;
  }
  return 0;
}
