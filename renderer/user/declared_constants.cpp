#include "user/declared_constants.h"

#include <algorithm>
#include <cctype>
#include <optional>

namespace taa::user {

namespace {

bool identChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// HLSL's and GLSL's spellings of the four types a specialization constant takes.
std::optional<ParamType> constantType(const std::string& word) {
  if (word == "bool") return ParamType::Bool;
  if (word == "int" || word == "int32_t" || word == "min16int") return ParamType::Int;
  if (word == "uint" || word == "uint32_t" || word == "dword" || word == "min16uint")
    return ParamType::Uint;
  if (word == "float" || word == "half" || word == "min16float" || word == "float32_t")
    return ParamType::Float;
  return std::nullopt;
}

// The first of `chars` in s[from, from + window), or npos: a declaration is short, and a
// search bounded by it keeps the scan linear on text made to defeat it.
size_t findWithin(const std::string& s, const char* chars, size_t from, size_t window) {
  const size_t end = std::min(s.size(), from + window);
  for (size_t i = from; i < end; ++i)
    for (const char* c = chars; *c; ++c)
      if (s[i] == *c) return i;
  return std::string::npos;
}

}  // namespace

std::vector<DeclaredConstant> declaredConstants(const std::string& s) {
  static const std::string kKey = "constant_id";
  std::vector<DeclaredConstant> out;
  for (size_t at = s.find(kKey); at != std::string::npos && out.size() < kMaxDeclaredConstants;
       at = s.find(kKey, at + kKey.size())) {
    if ((at > 0 && identChar(s[at - 1])) ||
        (at + kKey.size() < s.size() && identChar(s[at + kKey.size()])))
      continue;  // part of a longer name
    // The qualifier ends at its first ')': `constant_id = 3)` or `constant_id(3)]]`.
    const size_t close = findWithin(s, ")", at, 64);
    if (close == std::string::npos) continue;
    // The declarator ends at its initialiser's `=` (or a `;`); its last two words are the
    // type and the name.
    const size_t end = findWithin(s, "=;", close, 256);
    if (end == std::string::npos) continue;
    std::vector<std::string> words;
    for (size_t i = close + 1; i < end;) {
      if (!identChar(s[i])) {
        ++i;
        continue;
      }
      const size_t from = i;
      while (i < end && identChar(s[i])) ++i;
      words.push_back(s.substr(from, i - from));
    }
    if (words.size() < 2) continue;
    const std::string& name = words.back();
    const auto type = constantType(words[words.size() - 2]);
    if (!type || name.rfind("taa_", 0) == 0 || std::isdigit(static_cast<unsigned char>(name[0])))
      continue;
    // The id: the first number inside the qualifier (`= 3` or `(3)`).
    int64_t id = -1;
    for (size_t i = at + kKey.size(); i < close; ++i)
      if (std::isdigit(static_cast<unsigned char>(s[i]))) {
        id = 0;
        for (; i < close && std::isdigit(static_cast<unsigned char>(s[i])); ++i)
          id = std::min(id * 10 + (s[i] - '0'), kConstantIdCap);
        break;
      }
    out.push_back({name, *type, id});
  }
  return out;
}

}  // namespace taa::user
