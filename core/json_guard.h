// A linear pre-pass over JSON text, run before any parser builds a tree: it bounds the
// nesting depth (parsers and tree walkers that recurse, such as tinygltf's extras reader,
// would otherwise run out of stack) and finds duplicate object keys, which every parser
// the harness uses accepts silently with the last one winning.
#pragma once

#include <string>
#include <string_view>

namespace taa {

// Deep enough for any case, track or glTF file (glTF extras included); shallow enough
// that no recursive reader comes near its stack limit.
inline constexpr int kMaxJsonDepth = 256;

// "" when the text nests at most `maxDepth` arrays and objects and no object repeats a
// key; otherwise the first problem as "line L, column C: ..." naming the key and, for a
// duplicate, where it first appeared. Malformed JSON is left for the real parser to report.
std::string jsonStructureProblem(std::string_view text, int maxDepth = kMaxJsonDepth);

// nlohmann's message for a failed parse (`what`), less what would quote the file: its
// "[json.exception...]" prefix and its "; last read: '...'" tail. A file that fails to parse
// may be no JSON at all (a link to a secret), and no byte of it is ever printed.
std::string jsonErrorWithoutContent(const std::string& what);

}  // namespace taa
