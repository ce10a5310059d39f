// The values the settings audit tries (docs/settings-audit.md): alternatives to a key's value in
// force, and the settings a refused key needs before it can act.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "support/settings_audit.h"

namespace taa::test::audit {

namespace {

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

// The key's value in the audit scene on `path`, else its declared default.
nlohmann::json currentValue(const nlohmann::json& row, const AuditPath& path) {
  nlohmann::json j = nlohmann::json::parse(auditBase());
  j.merge_patch(nlohmann::json::parse(path.patch));
  // The values in force (validate --print): a mode's own defaults included (accumulate's alpha
  // is 0.2), so that no alternative merely restates one.
  try {
    j = cases::resolvedJson(cases::parseCase(j.dump(), "settings_audit.json").spec);
  } catch (const cases::CaseError&) {
    // A path refused as it stands: its own JSON is the best guess.
  }
  std::string key = row["key"];
  if (key.rfind("movers[].", 0) == 0) {
    j = j["movers"][0];
    key = key.substr(9);
  }
  auto pointerOf = [](const std::string& dotted) {
    std::string pointer = "/";
    for (char c : dotted) pointer += c == '.' ? '/' : c;
    return nlohmann::json::json_pointer(pointer);
  };
  if (j.contains(pointerOf(key))) return j[pointerOf(key)];
  // taa.moving is printed only when the case sets it; each of its floats starts at the still one.
  if (key.rfind("taa.moving.", 0) == 0 && j.contains(pointerOf("taa." + key.substr(11))))
    return j[pointerOf("taa." + key.substr(11))];
  return row["default"];
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
    if (value != "set" &&
        (value.find(' ') == std::string::npos || value.find(',') < value.find(' ') ||
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

// Whether `enabler` sets a key `path` does not set yet: retrying with a key the path already
// sets (to another value) would only go round in circles.
bool enablesMore(const AuditPath& path, const nlohmann::json& enabler) {
  const auto set = nlohmann::json::parse(path.patch);
  const auto flat = enabler.flatten();
  for (auto it = flat.begin(); it != flat.end(); ++it)
    if (!set.contains(nlohmann::json::json_pointer(it.key()))) return true;
  return false;
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

nlohmann::json patchFor(const std::string& key, const nlohmann::json& value) {
  // movers[].KEY: the audit scene's one mover with that key changed (a merge patch replaces
  // whole arrays).
  if (key.rfind("movers[].", 0) == 0) {
    auto movers = nlohmann::json::parse(auditBase())["movers"];
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

}  // namespace taa::test::audit
