#include "case/validate_inert.h"

#include "spec/taa_modes.h"

namespace taa::cases {

namespace {

using InertList = std::vector<std::pair<std::string, std::string>>;

// The message of Rules::needs (validate_taa.cpp), so that every "needs" refusal reads alike.
void inertNeeds(InertList& out, const std::set<std::string>& present, const std::string& key,
                bool condition, const std::string& what) {
  if (present.count(key) && !condition)
    out.emplace_back(key, "has no effect unless " + what + "; set that or remove the key");
}

}  // namespace

InertList inertProblems(const spec::CaseSpec& s, const std::set<std::string>& present) {
  InertList out;
  const auto& cam = s.camera;
  // The curve settings shape a path through camera.path.points; with none there is no path.
  for (const char* key : {"camera.path.type", "camera.path.duration_s",
                          "camera.path.constant_speed", "camera.path.look", "camera.path.cyclic"})
    inertNeeds(out, present, key, !cam.path.points.empty(), "camera.path.points is set");
  inertNeeds(out, present, "camera.bob.frequency_hz", cam.bob.amplitude > 0.0f,
             "camera.bob.amplitude is above 0");
  inertNeeds(out, present, "camera.strafe.distance", cam.strafe.speed > 0.0f,
             "camera.strafe.speed is above 0");
  for (size_t i = 0; i < s.movers.size(); ++i) {
    const std::string key = "movers[" + std::to_string(i) + "]";
    const bool rotates = s.movers[i].rotation_speed_deg != 0.0f;
    for (const char* k : {".rotation_axis", ".continuous_rotation"})
      inertNeeds(out, present, key + k, rotates, key + ".rotation_speed_deg is not 0");
  }
  // A reset empties a history; off and pass_through keep none.
  if (!s.script.reset_history_at.empty() && !spec::modeRule(s.taa.mode).history)
    out.emplace_back("script.reset_history_at",
                     "resets the temporal history, which taa.mode " +
                         std::string(spec::enumToString(s.taa.mode)) +
                         " does not keep; remove the key or set taa.mode to " +
                         spec::modeNames(spec::modesWhere(&spec::ModeRule::history)));
  // The bias applies whenever a temporal resolve runs; lod_bias_taa_only only decides whether
  // it applies without one.
  inertNeeds(
      out, present, "material.lod_bias_taa_only",
      s.material.lod_bias != 0.0f && !spec::runsTaa(spec::modeRule(s.taa.mode)),
      "material.lod_bias is not 0 and taa.mode is off (with a temporal resolve the bias applies "
      "either way)");
  inertNeeds(out, present, "material.alpha_cutoff", s.material.alpha_mode == spec::AlphaMode::Mask,
             "material.alpha_mode is mask");
  return out;
}

}  // namespace taa::cases
