#include "api/shader_defines.h"

#include <cctype>
#include <set>

namespace taa::user {

namespace {

bool identifier(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (const char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// "NAME=VALUE" -> NAME and VALUE ("1" when there is no '=').
std::pair<std::string, std::string> split(const std::string& d) {
  const size_t eq = d.find('=');
  if (eq == std::string::npos) return {d, "1"};
  return {d.substr(0, eq), d.substr(eq + 1)};
}

}  // namespace

std::vector<std::string> shaderDefineProblems(const std::vector<std::string>& defines) {
  std::vector<std::string> out;
  if (defines.size() > kMaxShaderDefines) {
    out.push_back("taa.shader_defines: has " + std::to_string(defines.size()) +
                  " entries, over the bound of " + std::to_string(kMaxShaderDefines) +
                  "; a variant needs a few keywords, put the rest in a header");
    return out;
  }
  std::set<std::string> seen;
  for (size_t i = 0; i < defines.size(); ++i) {
    const std::string key = "taa.shader_defines[" + std::to_string(i) + "]: ";
    const std::string& d = defines[i];
    if (d.size() > kMaxShaderDefineBytes) {
      out.push_back(key + "is " + std::to_string(d.size()) + " bytes long, over the bound of " +
                    std::to_string(kMaxShaderDefineBytes) + "; put a long value in a header");
      continue;
    }
    const auto [name, value] = split(d);
    // Shown without what could be a control character: the name is the user's own text.
    std::string shown;
    for (const char c : name.substr(0, 64))
      shown += std::iscntrl(static_cast<unsigned char>(c)) ? '?' : c;
    if (!identifier(name) || name.rfind("GL_", 0) == 0 || name.rfind("__", 0) == 0) {
      out.push_back(key + "'" + shown +
                    "' is not a name a define can have; give \"NAME\" or \"NAME=VALUE\" with "
                    "NAME of letters, digits and _, not starting with a digit, GL_ or __");
      continue;
    }
    bool control = false;
    for (const char c : value) control |= std::iscntrl(static_cast<unsigned char>(c)) != 0;
    if (control) {
      out.push_back(key + name +
                    "'s value holds a line break or control character; a define's "
                    "value is one line");
      continue;
    }
    if (!seen.insert(name).second) out.push_back(key + name + " is defined twice; remove one");
  }
  return out;
}

std::string shaderDefinePreamble(const std::vector<std::string>& defines) {
  std::string out;
  for (const auto& d : defines) {
    const auto [name, value] = split(d);
    out += "#define " + name + " " + value + "\n";
  }
  return out;
}

}  // namespace taa::user
