#include "user/shader_bounds.h"

#include <algorithm>
#include <cctype>
#include <unordered_map>
#include <unordered_set>

#include "api/loader_errors.h"
#include "core/input_file.h"

namespace taa::user {

std::string readShaderText(const std::filesystem::path& file, const std::string& what) {
  std::string text;
  try {
    text = readInputFile(file, kMaxShaderFileBytes);
  } catch (const InputFileError& e) {
    throw ShaderCompileError(what + ": " + e.what());
  }
  // Editors on Windows (and Unity's own files) start UTF-8 text with a byte-order mark, which
  // glslang's preprocessor takes for a token before the first `#`. It carries no line, so
  // dropping it keeps every line number the user sees.
  if (text.rfind(kUtf8ByteOrderMark, 0) == 0) text.erase(0, kUtf8ByteOrderMark.size());
  return text;
}

namespace {

// One bracket level of a statement: the operators of its current comma-separated group,
// the deepest bracket inside that group, and the deepest finished group.
struct DepthFrame {
  int ops = 0, child = 0, group = 0;
  int depth() const { return std::max(group, ops + child); }
};

bool isIdentStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isIdentChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// `#line N` or `#line N "file"` / `#line N S` (glslang writes both): the next line's number
// and, when named, its file.
void readLineDirective(const std::string& s, size_t at, size_t end, size_t& line,
                       std::string& file) {
  while (at < end && (s[at] == ' ' || s[at] == '\t')) ++at;
  if (s.compare(at, 4, "line") != 0) return;
  at += 4;
  while (at < end && (s[at] == ' ' || s[at] == '\t')) ++at;
  size_t n = 0;
  bool any = false;
  while (at < end && std::isdigit(static_cast<unsigned char>(s[at])) && n < 100000000) {
    n = n * 10 + size_t(s[at++] - '0');
    any = true;
  }
  if (!any) return;
  line = n > 0 ? n - 1 : 0;  // the directive names the line after it
  while (at < end && (s[at] == ' ' || s[at] == '\t')) ++at;
  if (at < end && s[at] == '"') {
    const size_t close = s.find('"', at + 1);
    if (close != std::string::npos && close < end) file = s.substr(at + 1, close - at - 1);
  }
}

uint64_t saturatingMul(uint64_t a, uint64_t b) {
  constexpr uint64_t kCap = uint64_t(1) << 48;
  if (a == 0 || b == 0) return 0;
  return a > kCap / b ? kCap : std::min(kCap, a * b);
}

}  // namespace

SandboxLimits compileLimits() {
  SandboxLimits l;
  l.cpuSeconds = 20;
  l.wallSeconds = 60;
  l.memoryBytes = uint64_t(1) << 30;
  l.stackBytes = uint64_t(64) << 20;
  return l;
}

std::string expressionDepthProblem(const std::string& s, const std::string& mainFile) {
  std::vector<DepthFrame> stack(1);
  std::string file = mainFile, statementFile = mainFile;
  size_t line = 1, statementLine = 1;
  bool statementStarted = false;
  // Closes every open bracket of the statement: an upper bound even when they do not balance
  // (a for header's semicolons end statements inside its brackets).
  auto finish = [&]() -> std::string {
    while (stack.size() > 1) {
      const int d = stack.back().depth() + 1;
      stack.pop_back();
      stack.back().child = std::max(stack.back().child, d);
    }
    const int depth = stack[0].depth();
    stack[0] = DepthFrame{};
    statementStarted = false;
    if (depth <= kMaxExpressionDepth) return {};
    return statementFile + ":" + std::to_string(statementLine) + ": a statement nests " +
           std::to_string(depth) + " operators and brackets deep, over the bound of " +
           std::to_string(kMaxExpressionDepth) +
           " (glslang recurses once per level); split the expression into named temporaries";
  };
  bool lineStart = true;
  for (size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
      lineStart = true;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (lineStart && c == '#') {
      size_t end = s.find('\n', i);
      if (end == std::string::npos) end = s.size();
      readLineDirective(s, i + 1, end, line, file);
      i = end;
      continue;
    }
    lineStart = false;
    if (!statementStarted) {
      statementStarted = true;
      statementFile = file;
      statementLine = line;
    }
    if (isIdentStart(c)) {
      while (i < s.size() && isIdentChar(s[i])) ++i;
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      while (i < s.size() && (isIdentChar(s[i]) || s[i] == '.' ||
                              ((s[i] == '+' || s[i] == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
        ++i;
      continue;
    }
    ++i;
    switch (c) {
      case '(':
      case '[':
        stack.emplace_back();
        break;
      case ')':
      case ']':
        if (stack.size() > 1) {
          const int d = stack.back().depth() + 1;
          stack.pop_back();
          stack.back().child = std::max(stack.back().child, d);
        }
        break;
      case ',': {
        DepthFrame& f = stack.back();
        f.group = std::max(f.group, f.ops + f.child);
        f.ops = f.child = 0;
        break;
      }
      case ';':
      case '{':
      case '}':
        if (std::string why = finish(); !why.empty()) return why;
        break;
      default:
        ++stack.back().ops;
        // Checked as it grows too: an unterminated statement still ends the scan early.
        if (stack.back().ops > kMaxExpressionDepth) return finish();
        break;
    }
  }
  return finish();
}

std::string spirvMemoryProblem(const std::vector<uint32_t>& w,
                               const std::map<uint32_t, uint32_t>& specValues) {
  // SPIR-V opcodes, storage classes and the SpecId decoration (specification, section 3).
  constexpr uint32_t kTypeBool = 20, kTypeInt = 21, kTypeFloat = 22, kTypeVector = 23,
                     kTypeMatrix = 24, kTypeImage = 25, kTypeSampler = 26,
                     kTypeSampledImage = 27, kTypeArray = 28, kTypeStruct = 30,
                     kTypePointer = 32, kConstant = 43, kConstantComposite = 44,
                     kSpecConstant = 50, kSpecConstantComposite = 51,
                     kSpecConstantOp = 52, kVariable = 59, kDecorate = 71;
  constexpr uint32_t kDecoSpecId = 1;
  constexpr uint32_t kStorageWorkgroup = 4, kStoragePrivate = 6, kStorageFunction = 7;
  constexpr uint64_t kUnknown = uint64_t(1) << 48;  // a length that cannot be evaluated
  std::unordered_map<uint32_t, uint64_t> bytes, value, numbers;  // numbers: scalars per type
  std::unordered_set<uint32_t> arrays;
  uint64_t constantNumbers = 0;
  std::unordered_map<uint32_t, uint32_t> pointee, specIdOf;
  uint64_t priv = 0, shared = 0;
  bool unknownLength = false;
  auto sizeOf = [&](uint32_t id) {
    const auto it = bytes.find(id);
    return it == bytes.end() ? uint64_t(0) : it->second;
  };
  auto numbersOf = [&](uint32_t id) {
    const auto it = numbers.find(id);
    return it == numbers.end() ? uint64_t(0) : it->second;
  };
  for (size_t i = 5; i < w.size();) {
    const uint32_t count = w[i] >> 16, opcode = w[i] & 0xffffu;
    if (count == 0 || i + count > w.size()) break;  // reflection reports the malformed module
    const uint32_t* o = w.data() + i + 1;  // one past the end when the instruction has no operands
    const size_t n = count - 1;
    i += count;
    switch (opcode) {
      case kDecorate:
        if (n >= 3 && o[1] == kDecoSpecId) specIdOf[o[0]] = o[2];
        break;
      case kTypeBool:
        if (n >= 1) bytes[o[0]] = 4, numbers[o[0]] = 1;
        break;
      case kTypeInt:
      case kTypeFloat:
        if (n >= 2) bytes[o[0]] = o[1] / 8, numbers[o[0]] = 1;
        break;
      case kTypeVector:
      case kTypeMatrix:
        if (n >= 3) {
          bytes[o[0]] = saturatingMul(sizeOf(o[1]), o[2]);
          numbers[o[0]] = saturatingMul(numbersOf(o[1]), o[2]);
        }
        break;
      case kTypeImage:
      case kTypeSampler:
      case kTypeSampledImage:
        if (n >= 1) bytes[o[0]] = 8;
        break;
      case kTypeArray:
        if (n >= 3) {
          const auto len = value.find(o[2]);
          const uint64_t length = len == value.end() ? kUnknown : len->second;
          if (length == kUnknown) unknownLength = true;
          bytes[o[0]] = saturatingMul(sizeOf(o[1]), length);
          numbers[o[0]] = saturatingMul(numbersOf(o[1]), length);
          arrays.insert(o[0]);
        }
        break;
      case kTypeStruct: {
        uint64_t sum = 0, scalars = 0;
        for (size_t k = 1; k < n; ++k) {
          sum = std::min(kUnknown, sum + sizeOf(o[k]));
          scalars = std::min(kUnknown, scalars + numbersOf(o[k]));
        }
        if (n >= 1) bytes[o[0]] = sum, numbers[o[0]] = scalars;
        break;
      }
      case kTypePointer:
        if (n >= 3) {
          pointee[o[0]] = o[2];
          bytes[o[0]] = 8;
        }
        break;
      case kConstant:
        if (n >= 3) value[o[1]] = o[2];
        break;
      case kConstantComposite:
      case kSpecConstantComposite:
        if (n >= 1 && arrays.count(o[0]))
          constantNumbers = std::min(kUnknown, constantNumbers + numbersOf(o[0]));
        break;
      case kSpecConstant:
        if (n >= 3) {
          const auto sid = specIdOf.find(o[1]);
          const auto set = sid == specIdOf.end() ? specValues.end() : specValues.find(sid->second);
          value[o[1]] = set != specValues.end() ? set->second : o[2];
        }
        break;
      case kSpecConstantOp:
        // Array lengths computed from specialization constants: the integer arithmetic
        // (IAdd, ISub, IMul, UDiv, SDiv) on lengths; anything else is not evaluated.
        if (n >= 5) {
          const auto a = value.find(o[3]), b = value.find(o[4]);
          if (a == value.end() || b == value.end()) break;
          const int64_t x = int32_t(a->second), y = int32_t(b->second);
          int64_t r = 0;
          switch (o[2]) {
            case 128: r = x + y; break;
            case 130: r = x - y; break;
            case 132: r = x * y; break;
            case 134:
            case 135: r = y != 0 ? x / y : 0; break;
            default: continue;
          }
          value[o[1]] = r < 0 ? 0 : uint64_t(std::min<int64_t>(r, int64_t(kUnknown)));
        }
        break;
      case kVariable:
        if (n >= 3) {
          const auto p = pointee.find(o[0]);
          const uint64_t b = p == pointee.end() ? 0 : sizeOf(p->second);
          if (o[2] == kStoragePrivate || o[2] == kStorageFunction) priv = std::min(kUnknown, priv + b);
          if (o[2] == kStorageWorkgroup) shared = std::min(kUnknown, shared + b);
        }
        break;
      default:
        break;
    }
  }
  auto amount = [&](uint64_t v) {
    return v >= kUnknown ? std::string("an amount the harness cannot evaluate") +
                               (unknownLength ? " (an array sized by an expression it does not "
                                                "evaluate)"
                                              : "")
                         : std::to_string(v) + " bytes";
  };
  if (constantNumbers > kMaxConstantArrayNumbers)
    return "its constant arrays hold " + std::to_string(constantNumbers) +
           " numbers, over the bound of " + std::to_string(kMaxConstantArrayNumbers) +
           " (Mesa's compiler takes minutes on large lookup tables); use a smaller table or "
           "compute its values";
  if (priv > kMaxPrivateBytes)
    return "its variables take " + amount(priv) + " of private memory per invocation, over the "
           "bound of " + std::to_string(kMaxPrivateBytes) +
           " bytes; keep large data in a history target (TAA_HISTORY0_FORMAT) instead";
  if (shared > kMaxSharedBytes)
    return "its shared variables take " + amount(shared) + ", over the bound of " +
           std::to_string(kMaxSharedBytes) +
           " bytes (Vulkan's guaranteed maxComputeSharedMemorySize); use a smaller tile";
  return {};
}

}  // namespace taa::user
