#include "core/json_guard.h"

#include <map>
#include <vector>

namespace taa {
namespace {

struct Position {
  size_t line = 1, column = 1;
  std::string text() const {
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
  }
};

// One open array or object; an object remembers its keys and where each appeared.
struct Level {
  bool object = false;
  bool expectKey = false;
  std::map<std::string, Position> keys;
};

void appendUtf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += char(cp);
  } else if (cp < 0x800) {
    out += char(0xC0 | (cp >> 6));
    out += char(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += char(0xE0 | (cp >> 12));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  } else {
    out += char(0xF0 | (cp >> 18));
    out += char(0x80 | ((cp >> 12) & 0x3F));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  }
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Shown in messages: keys are the file's own names, but keep a hostile one short.
std::string shown(const std::string& key) {
  std::string out;
  for (char c : key.substr(0, 64)) out += (static_cast<unsigned char>(c) < 0x20) ? '?' : c;
  return key.size() > 64 ? out + "..." : out;
}

class Scanner {
 public:
  Scanner(std::string_view text, int maxDepth) : s_(text), maxDepth_(maxDepth) {}

  std::string run() {
    std::vector<Level> stack;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '"') {
        const Position at = pos_;
        std::string value = string();
        if (!stack.empty() && stack.back().object && stack.back().expectKey) {
          stack.back().expectKey = false;
          auto [it, fresh] = stack.back().keys.emplace(std::move(value), at);
          if (!fresh)
            return at.text() + ": key \"" + shown(it->first) +
                   "\" appears twice in one object (first at " + it->second.text() +
                   "); remove one, only one value can be in force";
        }
        continue;
      }
      if (c == '{' || c == '[') {
        if (int(stack.size()) >= maxDepth_)
          return pos_.text() + ": nested more than " + std::to_string(maxDepth_) +
                 " levels deep; flatten the data (see docs/trust.md for the limits)";
        stack.push_back(Level{c == '{', c == '{', {}});
      } else if (c == '}' || c == ']') {
        if (!stack.empty()) stack.pop_back();
      } else if (c == ',') {
        if (!stack.empty() && stack.back().object) stack.back().expectKey = true;
      }
      advance();
    }
    return "";
  }

 private:
  void advance() {
    if (s_[i_] == '\n') {
      ++pos_.line;
      pos_.column = 1;
    } else {
      ++pos_.column;
    }
    ++i_;
  }

  // Reads a string starting at the opening quote and returns its decoded value; stops at
  // the end of the text when it is unterminated.
  std::string string() {
    std::string out;
    advance();
    while (i_ < s_.size() && s_[i_] != '"') {
      if (s_[i_] != '\\') {
        out += s_[i_];
        advance();
        continue;
      }
      advance();
      if (i_ >= s_.size()) break;
      const char e = s_[i_];
      advance();
      switch (e) {
        case 'n':
          out += '\n';
          break;
        case 't':
          out += '\t';
          break;
        case 'r':
          out += '\r';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'u':
          out += codePoint();
          break;
        default:
          out += e;  // \" \\ \/ (and anything malformed, for the parser to report)
      }
    }
    if (i_ < s_.size()) advance();
    return out;
  }

  // The character of a \u escape (the "\u" already read), joining surrogate pairs.
  std::string codePoint() {
    auto hex4 = [&](uint32_t& v) {
      v = 0;
      for (int k = 0; k < 4; ++k) {
        if (i_ >= s_.size() || hexDigit(s_[i_]) < 0) return false;
        v = v * 16 + uint32_t(hexDigit(s_[i_]));
        advance();
      }
      return true;
    };
    uint32_t cp = 0;
    if (!hex4(cp)) return "?";
    if (cp >= 0xD800 && cp < 0xDC00 && i_ + 1 < s_.size() && s_[i_] == '\\' && s_[i_ + 1] == 'u') {
      advance();
      advance();
      uint32_t low = 0;
      if (hex4(low) && low >= 0xDC00 && low < 0xE000)
        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    }
    std::string out;
    appendUtf8(out, cp);
    return out;
  }

  std::string_view s_;
  int maxDepth_;
  size_t i_ = 0;
  Position pos_;
};

}  // namespace

std::string jsonStructureProblem(std::string_view text, int maxDepth) {
  return Scanner(text, maxDepth).run();
}

std::string jsonErrorWithoutContent(const std::string& what) {
  std::string s = what;
  if (s.rfind("[json.exception.", 0) == 0) {
    const size_t close = s.find("] ");
    if (close != std::string::npos) s = s.substr(close + 2);
  }
  const size_t quoted = s.find("; last read:");
  if (quoted != std::string::npos) s = s.substr(0, quoted);
  // "number overflow parsing '1e999...'" quotes the token: keep the kind of error only.
  const size_t token = s.find(" parsing '");
  if (token != std::string::npos) s = s.substr(0, token);
  // Lexer messages name characters by code ("control character U+0000"), never quote them;
  // anything else from the file would sit after "last read".
  return s;
}

}  // namespace taa
