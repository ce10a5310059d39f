#include "support/settings_audit.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "case/case_error.h"
#include "case/case_loader.h"
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

nlohmann::json patchFor(const std::string& key, const nlohmann::json& value) {
  // movers[].KEY: the audit scene's one mover with that key changed (a merge patch replaces
  // whole arrays).
  if (key.rfind("movers[].", 0) == 0) {
    auto movers = nlohmann::json::parse(kAuditBase)["movers"];
    movers[0][key.substr(9)] = value;
    return {{"movers", movers}};
  }
  nlohmann::json patch = value;
  std::string rest = key;
  std::vector<std::string> parts;
  for (size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1))
    parts.push_back(rest.substr(0, dot));
  parts.push_back(rest);
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) patch = nlohmann::json{{*it, patch}};
  return patch;
}

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
        !bitIdentical(x.color, y.color))
      return "frame " + std::to_string(i) + " colour";
    if (x.stats != y.stats) return "frame " + std::to_string(i) + " stats";
  }
  return "";
}

bool inRange(const nlohmann::json& row, double v) {
  if (!row.contains("range")) return true;
  return v >= row["range"][0].get<double>() && v <= row["range"][1].get<double>();
}

std::vector<nlohmann::json> numberCandidates(const nlohmann::json& row,
                                             const nlohmann::json& current) {
  const bool isInt = row["type"] == "int";
  const double d = current.get<double>();
  std::vector<double> tries = {d * 2, d / 2};
  if (row.contains("range")) {
    const double lo = row["range"][0].get<double>(), hi = row["range"][1].get<double>();
    tries.insert(tries.end(), {lo, hi, (d + hi) / 2, (d + lo) / 2});
  } else {
    tries.insert(tries.end(), {d + 1, d - 1});
  }
  std::vector<nlohmann::json> out;
  std::vector<double> taken;
  for (double t : tries) {
    if (isInt) t = std::round(t);
    if (t == d || !inRange(row, t) || std::find(taken.begin(), taken.end(), t) != taken.end())
      continue;
    taken.push_back(t);
    out.push_back(isInt ? nlohmann::json(int(t)) : nlohmann::json(float(t)));
    if (out.size() == 3) break;
  }
  return out;
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

// The key's value in the audit scene on `path`, else its declared default.
nlohmann::json currentValue(const nlohmann::json& row, const AuditPath& path) {
  nlohmann::json j = nlohmann::json::parse(kAuditBase);
  j.merge_patch(nlohmann::json::parse(path.patch));
  const std::string key = row["key"];
  if (key.rfind("movers[].", 0) == 0) j = j["movers"][0];
  const std::string dotted = key.rfind("movers[].", 0) == 0 ? key.substr(9) : key;
  std::string pointer;
  for (char c : dotted) pointer += c == '.' ? '/' : c;
  const auto ptr = nlohmann::json::json_pointer("/" + pointer);
  return j.contains(ptr) ? j[ptr] : row["default"];
}

const nlohmann::json& schemaRows() {
  static const nlohmann::json rows = cases::settingsSchema();
  return rows;
}

// Keys whose value the audit chooses itself: lists (a frame, a pixel, an offset, a path through
// the fence), MSAA at a count lavapipe offers (4; it has no 2), and a visible near plane.
nlohmann::json chosenValue(const std::string& key) {
  if (key == "render.msaa") return 4;
  // A near plane that cuts into the floor before the camera: smaller ones change only depth
  // precision, which basic and off never read.
  if (key == "camera.near") return 2.0;
  if (key == "script.reset_history_at" || key == "inject.frames")
    return nlohmann::json::parse("[4]");
  if (key == "inject.pixels") return nlohmann::json::parse("[[20, 20], [40, 30]]");
  if (key == "jitter.points") return nlohmann::json::parse("[[0.25, -0.25], [-0.25, 0.25]]");
  if (key == "camera.path.points")
    return nlohmann::json::parse("[[0, 1.6, 6], [1, 1.6, 5], [2, 1.8, 4], [3, 1.8, 3]]");
  return nullptr;
}

}  // namespace

std::vector<nlohmann::json> alternatives(const nlohmann::json& row, const AuditPath& path) {
  const std::string type = row["type"];
  const auto d = currentValue(row, path);
  if (const auto chosen = chosenValue(row["key"]); !chosen.is_null()) return {chosen};
  if (type == "bool") return {!d.get<bool>()};
  if (type == "enum") {
    std::vector<nlohmann::json> out;
    for (const auto& a : row["allowed"])
      if (a != d) out.push_back(a);
    return out;
  }
  if (type == "int" || type == "number") return numberCandidates(row, d);
  if (type == "vec3") {
    // Shift every component: a colour gets redder and less blue, a position or direction moves.
    return {nlohmann::json::array(
        {d[0].get<float>() + 0.3f, d[1].get<float>() - 0.2f, d[2].get<float>() + 0.1f})};
  }
  if (type == "list of enum") {
    // One channel, buffer... instead of the default's list.
    for (const auto& a : row["allowed"])
      if (d.size() != 1 || d[0] != a) return {nlohmann::json::array({d.size() > 1 ? d[1] : a})};
  }
  return {};
}

namespace {

// Validation's "has no effect unless COND; set that" (Rules::needs), as a merge patch that makes
// COND hold: "taa.rectify is clamp or clip and taa.color_space is ycocg" gives rectify clamp and
// color_space ycocg; of "a, b or c is true" the first. Null when COND is not of that form or
// is a taa.mode (the paths are the modes).
nlohmann::json enablerFor(const std::string& refusal, const AuditPath& path) {
  const std::string lead = "has no effect unless ";
  const size_t at = refusal.find(lead);
  if (at == std::string::npos) return nullptr;
  std::string cond = refusal.substr(at + lead.size());
  cond = cond.substr(0, std::min(cond.find("; set that"), cond.find(" (")));
  nlohmann::json patch = nlohmann::json::object();
  for (size_t from = 0; from <= cond.size();) {
    size_t to = cond.find(" and ", from);
    if (to == std::string::npos) to = cond.size();
    const std::string clause = cond.substr(from, to - from);
    from = to + 5;
    const size_t is = clause.find(" is ");
    if (is == std::string::npos) return nullptr;
    std::string key = clause.substr(0, is), value = clause.substr(is + 4);
    key = key.substr(0, std::min(key.find(','), key.find(" or ")));
    if (key == "taa.mode") continue;  // the paths are the modes
    if (key.find(' ') != std::string::npos) return nullptr;
    nlohmann::json v;
    if (value != "set" && (value.find(' ') == std::string::npos || value.find(',') < value.find(' ') ||
                           value.find(" or ") == value.find(' '))) {
      value = value.substr(0, std::min(value.find(','), value.find(" or ")));
      v = value;
      if (value == "true" || value == "false") v = value == "true";
      if (!value.empty() && std::isdigit(static_cast<unsigned char>(value[0])) != 0) {
        const double n = std::stod(value);
        v = n == std::floor(n) ? nlohmann::json(int(n)) : nlohmann::json(n);
      }
    } else {
      // "is set", "is above 0", "is not 0": the value the audit would try for that key.
      for (const auto& row : schemaRows())
        if (row["key"] == key)
          if (const auto alts = alternatives(row, path); !alts.empty()) v = alts[0];
      if (v.is_null()) return nullptr;
    }
    patch.merge_patch(patchFor(key, v));
  }
  return patch.empty() ? nullptr : patch;
}

// `path` with `enabler` merged in, named after it: "full+taa.consistency=true".
AuditPath enabledPath(const AuditPath& path, const nlohmann::json& enabler) {
  nlohmann::json j = nlohmann::json::parse(path.patch);
  j.merge_patch(enabler);
  std::string name = path.name;
  const auto flat = enabler.flatten();
  for (auto it = flat.begin(); it != flat.end(); ++it) {
    std::string key = it.key().substr(1);
    for (char& c : key) c = c == '/' ? '.' : c;
    name += "+" + key + "=" + it.value().dump();
  }
  return {name, j.dump()};
}

void auditValue(const std::string& key, const nlohmann::json& value, const AuditPath& path,
                bool more, std::vector<AuditRow>& rows, int depth) {
  AuditRow r{key, path.name, value.dump(), Verdict::Acts, ""};
  try {
    const AuditRun& base = baseline(path);
    if (const auto enabler = base.refused ? enablerFor(base.message, path) : nullptr;
        !enabler.is_null() && depth < 3) {
      // The enabling setting needs one of its own (motion_adaptive_gamma needs variance_clip).
      if (const AuditPath next = enabledPath(path, enabler); next.patch != path.patch) {
        auditValue(key, value, next, more, rows, depth + 1);
        return;
      }
    }
    if (base.refused) {
      // The path refuses the key's default (lod_bias needs lod_bias_taa_only false in mode off):
      // the key acts if another value is accepted there, and is refused if not.
      const AuditRun run = renderPatched(path, patchFor(key, value));
      r.verdict = run.refused ? Verdict::Refused : Verdict::Acts;
      r.message = run.refused ? run.message : "accepted where the default is refused: " + base.message;
    } else if (const AuditRun run = renderPatched(path, patchFor(key, value)); run.refused) {
      r.verdict = Verdict::Refused;
      r.message = run.message;
      // Refused for want of another setting: also try it with that setting, where it is accepted.
      if (const auto enabler = enablerFor(run.message, path); !enabler.is_null() && depth < 3)
        if (const AuditPath next = enabledPath(path, enabler); next.patch != path.patch) {
          rows.push_back(r);
          auditValue(key, value, next, more, rows, depth + 1);
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
