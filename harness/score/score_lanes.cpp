// The scorecard's lanes as a user names them (a shader and its parameters on the command
// line, or a lanes file), and its convergence rule.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "report/text_util.h"
#include "run/timing.h"
#include "score/score.h"

namespace taa::score {

namespace fs = std::filesystem;

namespace {

std::string fixed4(double v) {
  return report::formatFixed(v, 4);
}

}  // namespace

Convergence convergence(const std::vector<double>& e) {
  Convergence c;
  const size_t n = e.size();
  if (n < 4) {
    c.why = "fewer than 4 frames";
    return c;
  }
  const size_t tail = std::max<size_t>(1, n / 4);
  const double level = run::mean(std::vector<double>(e.end() - long(tail), e.end()));
  const double fall = e.front() - level;
  // The first frame from which every later frame stays at or under `bound`.
  auto settledFrom = [&](double bound) {
    size_t first = n;
    for (size_t f = n; f-- > 0 && e[f] <= bound;) first = f;
    return first;
  };
  if (level <= kFloorFlip) {
    // At the reference's floor: nothing left to fall to.
    const size_t f = settledFrom(kFloorFlip + std::max(0.0, kSettleShare * fall));
    if (f + tail <= n) {
      c.frame = int(f);
      return c;
    }
  }
  if (fall < kSettleShare * e.front()) {
    c.why = std::string(fall < 0.0 ? "error rose" : "error fell less than 10%") + " (" +
            fixed4(e.front()) + " at frame 0, " + fixed4(level) + " over the last quarter)";
    return c;
  }
  const size_t f = settledFrom(level + kSettleShare * fall);
  if (f + tail > n) {
    c.why = "still settling in the last quarter (" + fixed4(e.front()) + " at frame 0, " +
            fixed4(level) + " over the last quarter)";
    return c;
  }
  c.frame = int(f);
  return c;
}

// "clip.hlsl alpha=0.2 clip=true -DUSE_YCOCG": a lane's taa section for the legend, by name and
// typed value whether it came from --params or a lanes file (its other keys follow as key=value).
std::string describeLane(const nlohmann::json& taa) {
  std::string out = taa.value("shader", std::string());
  const auto add = [&](const std::string& item) { out += (out.empty() ? "" : " ") + item; };
  if (const auto it = taa.find("shader_params"); it != taa.end() && it->is_array())
    for (const auto& p : *it)
      if (p.is_object()) add(p.value("name", std::string("?")) + "=" + p.value("value", nlohmann::json()).dump());
  // Keywords as a compiler's command line writes them: two variants of one shader differ here.
  if (const auto it = taa.find("shader_defines"); it != taa.end() && it->is_array())
    for (const auto& d : *it) add("-D" + (d.is_string() ? d.get<std::string>() : d.dump()));
  for (const auto& [key, value] : taa.items())
    if (key != "shader" && key != "shader_params" && key != "shader_defines")
      add(key + "=" + value.dump());
  return out;
}

LaneSpec shaderLane(const fs::path& shader, const std::string& params, const std::string& name,
                    bool qualify) {
  LaneSpec l;
  l.shaderRoot = fs::absolute(shader).parent_path();
  l.taa = {{"shader", shader.filename().string()}};
  auto list = nlohmann::json::array();
  std::stringstream in(params);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) continue;
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw cases::CaseError({"--params " + params + ": '" + item +
                              "' is not NAME=VALUE; give e.g. --params alpha=0.2,clip=true"});
    const std::string key = item.substr(0, eq), text = item.substr(eq + 1);
    nlohmann::json value;
    try {
      value = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception&) {
      value = nullptr;
    }
    if (!value.is_number() && !value.is_boolean())
      throw cases::CaseError({"--params " + params + ": " + key + "'s value '" + text +
                              "' is not a number, true or false"});
    list.push_back({{"name", key}, {"value", value}});
  }
  if (!list.empty()) l.taa["shader_params"] = list;
  l.describe = describeLane(l.taa);
  l.name = !name.empty() ? name : shader.stem().string();
  if (name.empty() && qualify && !list.empty()) l.name += "[" + params + "]";
  return l;
}

std::vector<LaneSpec> loadLanes(const fs::path& file) {
  const nlohmann::json j = cases::readJsonFile(file);
  if (!j.is_object() || j.empty())
    throw cases::CaseError({file.string() +
                            ": expected lanes {\"name\": {\"shader\": \"x.hlsl\", \"shader_params\": "
                            "[...]}, ...}"});
  if (j.size() > kMaxLanes)
    throw cases::CaseError({file.string() + ": " + std::to_string(j.size()) +
                            " lanes, over the limit of " + std::to_string(kMaxLanes) +
                            " (each lane renders every case); split the file (docs/trust.md)"});
  std::vector<LaneSpec> out;
  for (const auto& [name, taa] : j.items()) {
    // A lane's name heads its row and names its files: printable, and short.
    if (name.empty() || name.size() > kMaxLaneNameBytes ||
        std::any_of(name.begin(), name.end(),
                    [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
      throw cases::CaseError({file.string() + ": lane " +
                              nlohmann::json(name.substr(0, 40)).dump() +
                              ": a lane's name is 1 to " + std::to_string(kMaxLaneNameBytes) +
                              " bytes without control characters; rename it"});
    if (!taa.is_object())
      throw cases::CaseError({file.string() + ": " + name +
                              ": a lane is a taa section, e.g. {\"shader\": \"x.hlsl\"}"});
    if (const auto it = taa.find("shader"); it != taa.end() && !it->is_string())
      throw cases::CaseError({file.string() + ": " + name +
                              ".shader: not a string; give the shader's file, e.g. \"x.hlsl\""});
    if (const auto it = taa.find("shader_params"); it != taa.end() && !it->is_array())
      throw cases::CaseError(
          {file.string() + ": " + name +
           ".shader_params: not a list; give [{\"name\": ..., \"value\": ...}]"});
    LaneSpec l;
    l.name = name;
    l.taa = taa;
    if (taa.contains("shader")) l.shaderRoot = fs::absolute(file).parent_path();
    l.describe = describeLane(taa);
    out.push_back(std::move(l));
  }
  return out;
}

}  // namespace taa::score
