#include "user/define_use.h"

#include <cctype>
#include <set>

#include "core/closest_match.h"
#include "user/shader_bounds.h"

namespace taa::user {

namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Every identifier of `text` into `all`, comments included (a keyword named only in a comment
// is still the author's spelling: a refusal must never hit a define the shader does test), and
// those of preprocessor lines into `directives`, where a keyword's right spelling would be.
void addIdentifiers(const std::string& text, std::set<std::string>& all,
                    std::set<std::string>& directives) {
  bool directive = false, lineStart = true;
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (!identifierChar(c)) {
      if (c == '\n') directive = false;
      if (lineStart && c == '#') directive = true;
      lineStart = c == '\n' || (lineStart && (c == ' ' || c == '\t'));
      ++i;
      continue;
    }
    lineStart = false;
    const size_t start = i;
    while (i < text.size() && identifierChar(text[i])) ++i;
    if (std::isdigit(static_cast<unsigned char>(text[start]))) continue;
    const std::string name = text.substr(start, i - start);
    if (directive) directives.insert(name);
    all.insert(name);
  }
}

// A did-you-mean is a few names' work, not a dictionary's: past this many directive names the
// refusal goes without one.
constexpr size_t kMaxGuessCandidates = 4096;

}  // namespace

std::vector<std::string> unusedDefineProblems(const std::vector<std::string>& defines,
                                              const std::vector<std::filesystem::path>& files,
                                              const std::string& shader) {
  std::vector<std::string> out;
  if (defines.empty()) return out;
  std::set<std::string> names, directives;
  for (const auto& f : files) addIdentifiers(readShaderText(f, f.string()), names, directives);
  const std::vector<std::string> candidates =
      directives.size() <= kMaxGuessCandidates
          ? std::vector<std::string>(directives.begin(), directives.end())
          : std::vector<std::string>();
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
