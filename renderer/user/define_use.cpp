#include "user/define_use.h"

#include <cctype>
#include <set>

#include "core/closest_match.h"
#include "user/shader_bounds.h"

namespace taa::user {

namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Every identifier of `text`, comments included: a keyword named only in a comment is still
// the author's spelling, and a refusal must never hit a define the shader does test.
void addIdentifiers(const std::string& text, std::set<std::string>& out) {
  for (size_t i = 0; i < text.size();) {
    if (!identifierChar(text[i])) {
      ++i;
      continue;
    }
    const size_t start = i;
    while (i < text.size() && identifierChar(text[i])) ++i;
    if (!std::isdigit(static_cast<unsigned char>(text[start])))
      out.insert(text.substr(start, i - start));
  }
}

}  // namespace

std::vector<std::string> unusedDefineProblems(const std::vector<std::string>& defines,
                                              const std::vector<std::filesystem::path>& files,
                                              const std::string& shader) {
  std::vector<std::string> out;
  if (defines.empty()) return out;
  std::set<std::string> names;
  for (const auto& f : files) addIdentifiers(readShaderText(f, f.string()), names);
  const std::vector<std::string> candidates(names.begin(), names.end());
  for (size_t i = 0; i < defines.size(); ++i) {
    const std::string name = defines[i].substr(0, defines[i].find('='));
    if (names.count(name)) continue;
    const std::string guess = closestMatch(name, candidates);
    out.push_back("taa.shader_defines[" + std::to_string(i) + "]: " + name + " appears in none of " +
                  shader + "'s " + std::to_string(files.size()) +
                  " file(s) (the shader, its includes and the harness's header), so it selects "
                  "nothing" +
                  (guess.empty() ? "; remove it" : "; did you mean '" + guess + "'?"));
  }
  return out;
}

}  // namespace taa::user
