#include "case/validate_inputs.h"

#include <nlohmann/json.hpp>

namespace taa::cases {

KeyProblems controlCharacterProblems(const nlohmann::json& root) {
  KeyProblems out;
  // An explicit stack: nesting is bounded (jsonStructureProblem) but need not be shallow.
  std::vector<std::pair<const nlohmann::json*, std::string>> pending{{&root, ""}};
  while (!pending.empty() && out.size() < 16) {
    const auto [node, path] = pending.back();
    pending.pop_back();
    if (node->is_object()) {
      for (const auto& item : node->items())
        pending.emplace_back(&item.value(), path.empty() ? item.key() : path + "." + item.key());
    } else if (node->is_array()) {
      for (size_t i = 0; i < node->size(); ++i)
        pending.emplace_back(&(*node)[i], path + "[" + std::to_string(i) + "]");
    } else if (node->is_string()) {
      const std::string& s = node->get_ref<const std::string&>();
      for (size_t i = 0; i < s.size(); ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 || c == '\t' || c == '\n' || c == '\r') continue;
        char code[8];
        std::snprintf(code, sizeof(code), "U+%04X", c);
        out.emplace_back(path, std::string("holds the control character ") + code +
                                   " at character " + std::to_string(i) +
                                   " (a NUL would cut a path short); remove it");
        break;
      }
    }
  }
  return out;
}

KeyProblems emptyPathProblems(const spec::CaseSpec& spec, const std::set<std::string>& present) {
  std::vector<std::pair<std::string, const std::string*>> keys = {
      {"scene.gltf", &spec.scene.gltf},
      {"taa.shader", &spec.taa.shader},
      {"camera.track", &spec.camera.track},
      {"debug.image", &spec.debug.image}};
  for (size_t i = 0; i < spec.movers.size(); ++i) {
    const std::string at = "movers[" + std::to_string(i) + "].";
    keys.emplace_back(at + "gltf", &spec.movers[i].gltf);
    keys.emplace_back(at + "track", &spec.movers[i].track);
  }
  KeyProblems out;
  for (const auto& [key, value] : keys)
    if (present.count(key) && value->empty())
      out.emplace_back(key, "is an empty path; name a file relative to the case's folder, or "
                            "remove the key for the default");
  return out;
}

KeyProblems outputVolumeProblems(const spec::CaseSpec& spec) {
  KeyProblems out;
  const auto& frames = spec.output.frames;
  std::set<int> seen;
  for (size_t i = 0; i < frames.size(); ++i)
    if (!seen.insert(frames[i]).second)
      out.emplace_back("output.frames[" + std::to_string(i) + "]",
                       "frame " + std::to_string(frames[i]) + " is listed twice; remove one");
  // Per frame: the EXR (4 half samples a pixel), the PNG (3 bytes) and each aux buffer
  // (4 floats); the estimate ignores compression, which a hostile image defeats.
  const uint64_t pixels = uint64_t(spec.render.width) * uint64_t(spec.render.height) *
                          uint64_t(spec.tscmaa.eyes > 1 ? spec.tscmaa.eyes : 1);
  const uint64_t perFrame = pixels * (8 + 3 + 16 * uint64_t(spec.output.aux.size()));
  const uint64_t count = frames.empty() ? 1 : seen.size();
  const uint64_t total = perFrame * count;
  if (total > kMaxCaseOutputBytes) {
    char figure[64];
    std::snprintf(figure, sizeof(figure), "%.1f GiB", double(total) / double(uint64_t(1) << 30));
    out.emplace_back("output.frames",
                     std::to_string(count) + " frames of " + std::to_string(spec.render.width) +
                         "x" + std::to_string(spec.render.height) + " would write about " +
                         figure + ", over the bound of " +
                         std::to_string(kMaxCaseOutputBytes >> 30) +
                         " GiB per case; list fewer frames or render smaller");
  }
  return out;
}

}  // namespace taa::cases
