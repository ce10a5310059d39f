#include "case/validate_taa.h"

#include <string>

#include "spec/taa_modes.h"

namespace taa::cases {

namespace {

using namespace spec;

class Rules {
 public:
  Rules(const std::set<std::string>& present) : present_(present) {}
  bool set(const std::string& key) const { return present_.count(key) > 0; }
  std::vector<std::string> keysUnder(const std::string& prefix) const {
    std::vector<std::string> keys;
    for (const auto& k : present_)
      if (k.rfind(prefix, 0) == 0) keys.push_back(k);
    return keys;
  }
  void add(const std::string& key, const std::string& msg) { out.emplace_back(key, msg); }
  // `key` only means something when `condition` holds.
  void needs(const std::string& key, bool condition, const std::string& what) {
    if (set(key) && !condition)
      add(key, "has no effect unless " + what + "; set that or remove the key");
  }
  std::vector<std::pair<std::string, std::string>> out;

 private:
  const std::set<std::string>& present_;
};

// adaptive.* drives the passes after an adaptive resolve; they trace and filter at
// output size, pixel for pixel against the G-buffer, so the render size must match.
void adaptiveRules(Rules& r, const CaseSpec& s, bool resamples) {
  const bool adaptive = modeRule(s.taa.mode).adaptive;
  for (const auto& key : r.keysUnder("adaptive.")) r.needs(key, adaptive, "taa.mode is adaptive");
  if (!adaptive) return;
  if (resamples)
    r.add("taa.mode",
          "adaptive traces and segments at output size against the G-buffer; remove "
          "render.upsample and render.scale_schedule");
  const auto& a = s.adaptive;
  // The segmentation traces pixels the resolve rejected on screen; off-screen history is
  // FXAA's, so without a test that rejects on screen there is nothing to trace.
  const TaaSpec e = effectiveTaa(s.taa);
  const auto onScreen = onScreenRejections(e);
  bool rejectsOnScreen = false;
  std::string either;  // "taa.depth_culling, taa.consistency or taa.anti_ghosting"
  for (size_t i = 0; i < onScreen.size(); ++i) {
    rejectsOnScreen = rejectsOnScreen || onScreen[i].second;
    either += (i == 0 ? "" : i + 1 == onScreen.size() ? " or " : ", ") + onScreen[i].first;
  }
  r.needs("adaptive.trace_disoccluded", rejectsOnScreen,
          either + " is true (the resolve's only on-screen rejections)");
  if (!a.trace_all) return;
  for (const char* key :
       {"adaptive.threshold", "adaptive.weight_normal", "adaptive.weight_depth",
        "adaptive.weight_material", "adaptive.weight_luminance", "adaptive.history_count",
        "adaptive.trace_disoccluded", "adaptive.fxaa_out_of_history"})
    if (r.set(key))
      r.add(key,
            "adaptive.trace_all traces every pixel, so the segmentation settings do nothing; "
            "remove the key or trace_all");
}

// TSCMAA's keys mean nothing to the other modes; stereo output holds two eyes side by
// side, which the per-eye G-buffer captures cannot describe.
void tscmaaRules(Rules& r, const CaseSpec& s) {
  const bool tscmaa = modeRule(s.taa.mode).tscmaa;
  for (const char* key :
       {"tscmaa.edge_threshold", "tscmaa.non_dominant_edge_removal", "tscmaa.blurriness",
        "tscmaa.taa_share", "tscmaa.history_weight", "tscmaa.eyes", "tscmaa.eye_separation"})
    r.needs(key, tscmaa, "taa.mode is tscmaa");
  if (!tscmaa) return;
  r.needs("tscmaa.eye_separation", s.tscmaa.eyes == 2, "tscmaa.eyes is 2");
  if (s.tscmaa.eyes == 2 && !s.output.aux.empty())
    r.add("output.aux",
          "tscmaa.eyes 2 renders the G-buffer once per eye and writes the eyes side by side; the "
          "aux buffers exist per eye only: remove output.aux or render one eye");
  // The eyes are written side by side, so the image is twice render.width wide.
  if (s.tscmaa.eyes == 2 && s.render.width > 4096)
    r.add("tscmaa.eyes", "2 writes the eyes side by side, an image of 2 x render.width = " +
                             std::to_string(2 * s.render.width) +
                             " pixels, over the limit of 8192; set render.width to 4096 or less");
}

// taa.moving: uniforms of the built-in resolve, so its modes and its keys' own modes; the
// float keys take the rules of their still twins (evaluated on the still settings: the
// switches they depend on are the same in both sets).
void movingRules(Rules& r, const CaseSpec& s) {
  if (!r.set("taa.moving")) return;
  const TaaSpec e = effectiveTaa(s.taa);
  const uint32_t bit = modeBit(s.taa.mode);
  r.needs("taa.moving", (bit & kBlending) != 0 && s.taa.shader.empty(),
          modesText(kBlending) + " with the built-in resolve (its float settings are uniforms)");
  auto check = [&](const std::string& key, uint32_t modes, bool holds, const char* what) {
    r.needs(key, (modes & bit) != 0, modesText(modes));
    if (modes & bit) r.needs(key, holds, what);
  };
#define TAA_MOVING_CHECK_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_CHECK_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_CHECK_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  check("taa.moving." #key, modes, rule(e), text);
  TAA_SETTINGS(TAA_MOVING_CHECK_E, TAA_MOVING_CHECK_B, TAA_MOVING_CHECK_F)
#undef TAA_MOVING_CHECK_E
#undef TAA_MOVING_CHECK_B
#undef TAA_MOVING_CHECK_F
  // The ramp and the depth it measures at blend the still settings with the moving ones; with
  // no moving float set both are the same and the blend changes nothing.
  bool blendsSomething = false;
#define TAA_MOVING_SET_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_SET_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_SET_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  blendsSomething = blendsSomething || r.set("taa.moving." #key);
  TAA_SETTINGS(TAA_MOVING_SET_E, TAA_MOVING_SET_B, TAA_MOVING_SET_F)
#undef TAA_MOVING_SET_E
#undef TAA_MOVING_SET_B
#undef TAA_MOVING_SET_F
  for (const char* key : {"taa.moving.from_px", "taa.moving.to_px", "taa.moving.depth"})
    r.needs(key, blendsSomething, "taa.moving.alpha or another float setting of taa.moving is set");
  const auto& m = s.taa.moving;
  if (m.to_px <= m.from_px)
    r.add("taa.moving.to_px", "must be above taa.moving.from_px (the blend ramps between them)");
  if (e.luma_weight && r.set("taa.moving.alpha"))
    r.add("taa.moving.alpha",
          "taa.luma_weight chooses alpha per pixel within [alpha_min, alpha_max]; set "
          "taa.moving.alpha_min / alpha_max instead");
  const float lo = r.set("taa.moving.alpha_min") ? m.alpha_min : s.taa.alpha_min;
  const float hi = r.set("taa.moving.alpha_max") ? m.alpha_max : s.taa.alpha_max;
  if (e.luma_weight && lo > hi)
    r.add("taa.moving.alpha_min", "the moving alpha_min must not exceed the moving alpha_max");
  // An enum or switch inside taa.moving is an unknown key to the reader; it would need
  // another pipeline per frame, which is why the object holds floats only.
}

}  // namespace

void resolveTaaMoving(TaaSpec& taa, const std::set<std::string>& present) {
  taa.moving.active = present.count("taa.moving") > 0;
#define TAA_MOVING_COPY_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_COPY_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_COPY_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  if (!present.count("taa.moving." #key)) taa.moving.key = taa.key;
  TAA_SETTINGS(TAA_MOVING_COPY_E, TAA_MOVING_COPY_B, TAA_MOVING_COPY_F)
#undef TAA_MOVING_COPY_E
#undef TAA_MOVING_COPY_B
#undef TAA_MOVING_COPY_F
}

std::vector<std::pair<std::string, std::string>> taaProblems(const CaseSpec& s,
                                                             const std::set<std::string>& present) {
  Rules r(present);
  const auto& taa = s.taa;
  const ModeRule& rule = modeRule(taa.mode);
  const bool resamples = s.render.upsample != 1.0f || !s.render.scale_schedule.empty();
  if (resamples && !(rule.resolve && rule.path != Resolve::PassThrough))
    r.add(
        "taa.mode",
        std::string("render.upsample / render.scale_schedule need a resolve that reconstructs the "
                    "output size; '") +
            enumToString(taa.mode) + "' cannot: use basic or full");
  tscmaaRules(r, s);
  adaptiveRules(r, s, resamples);
  // Unjittering undoes the jitter of a frame rendered at output size; upsampling places the
  // jittered samples itself, and an unjittered frame has nothing to undo.
  for (const char* key : {"taa.unjitter_current", "taa.unjitter_neighborhood"}) {
    if (resamples && r.set(key))
      r.add(key,
            "rebuilds the pixel centre of a frame at output size, which upsampling already "
            "does its own way; remove the key or render.upsample and render.scale_schedule");
    r.needs(key, s.jitter.pattern != JitterPattern::None && s.jitter.scale > 0.0f,
            "the case jitters (jitter.pattern is not none and jitter.scale above 0)");
  }
  // The rejection and segmentation views are masks of a few flat colours; a scale has nothing
  // to scale there.
  if (s.debug.output == DebugOutput::Rejection || s.debug.output == DebugOutput::Segmentation)
    r.needs("debug.scale", false,
            "debug.output is velocity or clamp_distance (rejection and segmentation are masks)");

  // Each setting of common/taa_settings.h means something only in its modes, and only
  // where its rule holds for the settings the resolve runs with.
  const TaaSpec e = effectiveTaa(taa);
  const uint32_t bit = modeBit(taa.mode);
  auto check = [&](const char* key, uint32_t modes, bool holds, const char* what) {
    if (!(modes & bit))
      r.needs(key, false, modesText(modes));
    else
      r.needs(key, holds, what);
  };
#define TAA_CHECK_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  check("taa." #key, modes, rule(e), text);
#define TAA_CHECK_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  check("taa." #key, modes, rule(e), text);
#define TAA_CHECK_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  check("taa." #key, modes, rule(e), text);
  TAA_SETTINGS(TAA_CHECK_E, TAA_CHECK_B, TAA_CHECK_F)
#undef TAA_CHECK_E
#undef TAA_CHECK_B
#undef TAA_CHECK_F

  movingRules(r, s);

  // Rules between settings.
  if (!(rule.resolve && rule.path == Resolve::Full)) return r.out;
  if (taa.use_velocity == UseVelocity::Off && taa.velocity_sampling == VelocitySampling::Longest3x3)
    r.add("taa.velocity_sampling",
          "longest3x3 picks a velocity, but taa.use_velocity is off; use pixel or "
          "closest3x3 (which picks the nearest depth), or turn velocity on");
  if (rule.accumulate) return r.out;
  if (taa.consistency && r.set("taa.history_filter"))
    r.add("taa.history_filter",
          "taa.consistency resamples the history tap by tap (2x2, then 3x3); a history filter "
          "cannot apply as well: remove one of them");
  if (taa.luma_weight && taa.alpha_min > taa.alpha_max)
    r.add("taa.alpha_min", "alpha_min must not exceed alpha_max");
  if (taa.luma_weight && r.set("taa.alpha"))
    r.add(
        "taa.alpha",
        "taa.luma_weight chooses alpha per pixel within [alpha_min, alpha_max]; remove taa.alpha");
  if (taa.anti_ghosting && s.movers.empty())
    r.add("taa.anti_ghosting", "dynamic anti-ghosting acts on movers only, and the case has none");
  return r.out;
}

}  // namespace taa::cases
