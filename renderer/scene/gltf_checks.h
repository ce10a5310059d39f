// The glTF JSON checked against the glTF 2.0 schema's types and ranges before tinygltf reads
// it: tinygltf takes a fractional, string or null index as "absent", wraps 2^32 + 1 to 1 and
// keeps a 15-number matrix or a 2-number colour, so the file would render as something it
// does not say. One table (gltf_checks.cpp) lists every index, enum, count, flag and
// fixed-length number array the loader reads.
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace taa::scene {

// The glTF JSON text (nesting already bounded by jsonStructureProblem) as a document; throws
// SceneError naming `file` and the parser's position, never the file's bytes, when it is not
// a JSON object.
nlohmann::json parseGltfJson(const std::filesystem::path& file, const std::string& json);

// Throws SceneError naming `file`, the JSON path ("nodes[3].mesh"), the value and the rule
// for the first entry of `doc` that breaks the table: an index that is not a whole number
// inside its array, an enum outside its values, a negative count or offset, a flag that is
// not true or false, a number array of the wrong length or range, or a required key missing.
// Keys the table does not name (extras, unsupported extensions) are not looked at.
void checkGltfDocument(const std::filesystem::path& file, const nlohmann::json& doc);

}  // namespace taa::scene
