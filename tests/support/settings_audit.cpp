#include "support/settings_audit.h"

#include <cmath>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "case/case_error.h"
#include "scene/scene_error.h"
#include "support/effects.h"
#include "support/gpu.h"

namespace taa::test::audit {

namespace {

// 96x54, eight frames: the camera strafes past the fence (thin geometry) at a few pixels a
// frame and turns back, a spinning cube crosses it and reaches its end (disocclusion, repeat),
// a sphere gives smoothly varying normals, and a strong light on a shiny floor gives HDR
// highlights.
const char* kAuditBase = R"({
  "scene": {"builtin": "fence"},
  "render": {"width": 96, "height": 54},
  "script": {"frames": 8},
  "lighting": {"intensity": 12, "specular": 2, "shininess": 64},
  "camera": {"strafe": {"speed": 30, "distance": 1}},
  "movers": [{"shape": "cube", "start": [-2, 0.5, 1], "end": [2, 0.5, 1], "speed": 45,
              "rotation_speed_deg": 90},
             {"shape": "sphere", "start": [1.5, 0.8, 2], "end": [1.5, 0.8, 2], "speed": 0}]
})";

struct AuditRun {
  bool refused = false;
  std::string message;
  std::vector<FrameRecord> frames;
};

AuditRun renderPatched(const AuditPath& path, const nlohmann::json& keyPatch) {
  nlohmann::json j = nlohmann::json::parse(kAuditBase);
  j.merge_patch(nlohmann::json::parse(path.patch));
  j.merge_patch(keyPatch);
  AuditRun run;
  spec::CaseSpec spec;
  try {
    spec = caseFromJson(j.dump(), "settings_audit");
  } catch (const cases::CaseError& e) {
    run.refused = true;
    for (const auto& p : e.problems()) run.message += (run.message.empty() ? "" : "; ") + p;
    return run;
  }
  RenderOptions options;
  options.hashEveryFrame = true;  // every frame's colour, not only the last
  try {
    run.frames = renderCase(spec, {}, options);
  } catch (const scene::SceneError& e) {
    // Rules that need the loaded scene (a normal map, an alpha-tested texture): exit 2 too.
    run.refused = true;
    run.message = e.what();
  }
  return run;
}

const AuditRun& baseline(const AuditPath& path) {
  static std::map<std::string, std::unique_ptr<AuditRun>> cache;
  auto& slot = cache[path.name + '\n' + path.patch];
  if (!slot) slot = std::make_unique<AuditRun>(renderPatched(path, nlohmann::json::object()));
  return *slot;
}

// "" when every frame's colour and stats are bit-identical, else the first difference.
std::string firstDifference(const AuditRun& a, const AuditRun& b) {
  if (a.frames.size() != b.frames.size())
    return std::to_string(b.frames.size()) + " frames instead of " +
           std::to_string(a.frames.size());
  for (size_t i = 0; i < a.frames.size(); ++i) {
    const auto &x = a.frames[i], &y = b.frames[i];
    if (x.color.width != y.color.width || x.color.height != y.color.height ||
        !sameBits(x.color, y.color))
      return "frame " + std::to_string(i) + " colour";
    if (x.stats != y.stats) return "frame " + std::to_string(i) + " stats";
  }
  return "";
}

}  // namespace

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::Refused:
      return "refused";
    case Verdict::Acts:
      return "acts";
    case Verdict::Allowed:
      return "allowed";
    case Verdict::Identical:
      return "IGNORED";
    case Verdict::Failed:
      return "FAILED";
  }
  return "?";
}

std::string auditBase() {
  return kAuditBase;
}

std::vector<AuditPath> auditPaths(bool full) {
  std::vector<AuditPath> paths = {{"full", "{}"}};
  if (!full) return paths;
  paths.insert(paths.end(),
               {
                   {"off", R"({"taa": {"mode": "off"}})"},
                   {"pass_through", R"({"taa": {"mode": "pass_through"}})"},
                   {"basic", R"({"taa": {"mode": "basic"}})"},
                   {"accumulate", R"({"taa": {"mode": "accumulate"}})"},
                   {"adaptive", R"({"taa": {"mode": "adaptive"}})"},
                   {"tscmaa", R"({"taa": {"mode": "tscmaa"}})"},
                   {"tscmaa_eyes2", R"({"taa": {"mode": "tscmaa"}, "tscmaa": {"eyes": 2}})"},
                   {"velocity_off", R"({"taa": {"use_velocity": "off"}})"},
                   {"upsample2", R"({"render": {"upsample": 2}})"},
                   {"deferred", R"({"render": {"path": "deferred"}})"},
               });
  return paths;
}

namespace {

void auditValue(const std::string& key, const nlohmann::json& value, const AuditPath& path,
                bool more, std::vector<AuditRow>& rows, int depth) {
  AuditRow r{key, path.name, value.dump(), Verdict::Acts, ""};
  try {
    const AuditRun& base = baseline(path);
    if (const auto enabler = base.refused ? enablerFor(base.message, path) : nullptr;
        !enabler.is_null() && depth < 3 && enablesMore(path, enabler)) {
      // The enabling setting needs one of its own (motion_adaptive_gamma needs variance_clip).
      auditValue(key, value, enabledPath(path, enabler), more, rows, depth + 1);
      return;
    }
    if (base.refused) {
      // The path refuses the key's default (lod_bias needs lod_bias_taa_only false in mode off):
      // the key acts if another value is accepted there, and is refused if not.
      const AuditRun run = renderPatched(path, patchFor(key, value));
      r.verdict = run.refused ? Verdict::Refused : Verdict::Acts;
      r.message =
          run.refused ? run.message : "accepted where the default is refused: " + base.message;
    } else if (const AuditRun run = renderPatched(path, patchFor(key, value)); run.refused) {
      r.verdict = Verdict::Refused;
      r.message = run.message;
      // Refused for want of another setting: also try it with that setting, where it is accepted.
      if (const auto enabler = enablerFor(run.message, path);
          !enabler.is_null() && depth < 3 && enablesMore(path, enabler)) {
        rows.push_back(r);
        auditValue(key, value, enabledPath(path, enabler), more, rows, depth + 1);
        return;
      }
    } else if (const std::string diff = firstDifference(base, run); !diff.empty()) {
      r.message = diff + " differs";
    } else if (more) {
      r.verdict = Verdict::Identical;
      r.message = "";  // the caller tries the next candidate
    } else if (const Allowance* a = allowed(key, path.name.substr(0, path.name.find('+')))) {
      r.verdict = Verdict::Allowed;
      r.message = std::string(a->why) + " (proved by " + a->provedBy + ")";
    } else {
      r.verdict = Verdict::Identical;
      r.message = "accepted, and every frame's colour and stats are bit-identical";
    }
  } catch (const std::exception& e) {
    r.verdict = Verdict::Failed;
    r.message = e.what();
  }
  rows.push_back(r);
}

}  // namespace

std::vector<AuditRow> auditKey(const nlohmann::json& row, const AuditPath& path) {
  const std::string key = row["key"];
  std::vector<AuditRow> rows;
  const auto values = alternatives(row, path);
  const bool number = row["type"] == "int" || row["type"] == "number";
  for (size_t i = 0; i < values.size(); ++i) {
    // A number acts if any of its candidates does: the first may happen to be the value the
    // path already uses (accumulate's alpha is 0.2).
    const bool more = number && i + 1 < values.size();
    std::vector<AuditRow> tried;
    auditValue(key, values[i], path, more, tried, 0);
    if (more && tried.back().verdict == Verdict::Identical && tried.back().message.empty())
      continue;
    rows.insert(rows.end(), tried.begin(), tried.end());
    if (number) break;
  }
  return rows;
}

std::string table(const std::vector<AuditRow>& rows) {
  std::ostringstream out;
  for (const auto& r : rows) {
    std::string message = r.message;
    if (message.size() > 160) message = message.substr(0, 157) + "...";
    out << r.key << " | " << r.path << " | " << r.value << " | " << verdictName(r.verdict) << " | "
        << message << "\n";
  }
  return out.str();
}

}  // namespace taa::test::audit
