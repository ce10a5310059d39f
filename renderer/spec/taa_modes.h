// The one place that says what each taa.mode runs: which passes replace or follow the
// resolve, which path of taa_resolve.comp it takes, and which settings it fixes. Pass
// planning (renderer/frame/pass_plan.cpp), the renderer, the resolve pass and validation
// (harness/case/validate_taa.cpp) ask here instead of testing modes themselves.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "spec/taa_spec.h"

namespace taa::spec {

struct ModeRule {
  TaaMode mode;
  bool resolve;     // runs taa_resolve.comp ...
  Resolve path;     // ... on this path
  bool tscmaa;      // TSCMAA's passes replace the resolve
  bool adaptive;    // segmentation and ray tracing follow the resolve (and its mask view)
  bool accumulate;  // consistency is the only history validation (see effectiveTaa)
  float alpha;      // taa.alpha when the case leaves it out (0: the declared default)
  bool history;     // keeps a temporal history (invariants that judge one apply)
  bool debugViews;  // the full resolve's debug.output views can replace the output
  // The output is the full resolve's blend of a rectified history, nothing after it
  // changed: history_bounded can check it against the box, and it reads the speed motion
  // blur packs into alpha (taa.velocity_in_alpha).
  bool plainFull;
  // Another resolve can stand in for this one: a user's resolve (taa.shader) or a score
  // lane replaces exactly the full resolve run with the case's settings as written.
  bool standIn;
  // debug.image's still image, written over the raster's colour, is all the output sees:
  // the tracer shades the hidden scene, accumulation's consistency test weighs taps by its
  // depth and normals, and TSCMAA is not held to it (seed 18C).
  bool stillImage;
};

// Temporal accumulation's published blend weight is 0.2 (seed 003).
// clang-format off
inline constexpr ModeRule kModeRules[] = {
  // mode               resolve path                  tscmaa adaptive accum  alpha  history views  plainFull standIn still
    {TaaMode::Off,         false, Resolve::PassThrough, false, false, false, 0.0f, false, false, false, false, true},
    {TaaMode::PassThrough, true,  Resolve::PassThrough, false, false, false, 0.0f, false, false, false, false, true},
    {TaaMode::Basic,       true,  Resolve::Basic,       false, false, false, 0.0f, true,  false, false, false, true},
    {TaaMode::Full,        true,  Resolve::Full,        false, false, false, 0.0f, true,  true,  true,  true,  true},
    {TaaMode::Accumulate,  true,  Resolve::Full,        false, false, true,  0.2f, true,  false, false, false, false},
    {TaaMode::Tscmaa,      false, Resolve::PassThrough, true,  false, false, 0.0f, true,  false, false, false, false},
    {TaaMode::Adaptive,    true,  Resolve::Full,        false, true,  false, 0.0f, true,  true,  false, false, false},
};
// clang-format on

// A temporal resolve of some kind runs (material.lod_bias_taa_only applies the bias).
constexpr bool runsTaa(const ModeRule& r) {
  return r.resolve || r.tscmaa;
}

constexpr const ModeRule& modeRule(TaaMode m) {
  for (const auto& r : kModeRules)
    if (r.mode == m) return r;
  return kModeRules[0];
}

constexpr uint32_t modeBit(TaaMode m) {
  return 1u << unsigned(m);
}

// The modes whose rule sets `column`, as modeBit()s.
constexpr uint32_t modesWhere(bool ModeRule::*column) {
  uint32_t bits = 0;
  for (const auto& r : kModeRules)
    if (r.*column) bits |= modeBit(r.mode);
  return bits;
}

// Which taa.mode values a setting may be set in (the `modes` column of taa_settings.h).
inline constexpr uint32_t kFullOnly = modeBit(TaaMode::Full) | modeBit(TaaMode::Adaptive);
inline constexpr uint32_t kReprojecting = kFullOnly | modeBit(TaaMode::Accumulate);
inline constexpr uint32_t kBlendingNotAccumulate = kFullOnly | modeBit(TaaMode::Basic);
inline constexpr uint32_t kBlending = kReprojecting | modeBit(TaaMode::Basic);

// The modes whose resolve takes `path`: a setting reaches that path's shader only if
// its modes meet these.
constexpr uint32_t pathModes(Resolve path) {
  uint32_t bits = 0;
  for (const auto& r : kModeRules)
    if (r.resolve && r.path == path) bits |= modeBit(r.mode);
  return bits;
}

// The `rule` of a setting that means something whenever its mode allows it.
constexpr bool kAlways(const TaaSpec&) {
  return true;
}

// "basic, full or adaptive": the modes of a mask, in words.
inline std::string modeNames(uint32_t modes) {
  std::string names;
  int count = 0, seen = 0;
  for (const auto& n : enumNames(TaaMode{}))
    if (modes & modeBit(n.value)) ++count;
  for (const auto& n : enumNames(TaaMode{})) {
    if (!(modes & modeBit(n.value))) continue;
    ++seen;
    if (seen > 1) names += seen == count ? " or " : ", ";
    names += n.name;
  }
  return names;
}

// "taa.mode is basic, full or adaptive".
inline std::string modesText(uint32_t modes) {
  return "taa.mode is " + modeNames(modes);
}

// The settings the resolve runs with: a setting outside its modes keeps its default
// (validation refuses to set it), and accumulation, the full resolve with per-tap
// geometric consistency as its only history validation and no colour rectification,
// turns consistency on and rectification off.
inline TaaSpec effectiveTaa(const TaaSpec& user) {
#define TAA_RESET_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  if (!(modes & bit)) t.key = defaults.key;
#define TAA_RESET_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  if (!(modes & bit)) t.key = defaults.key;
#define TAA_RESET_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  if (!(modes & bit)) t.key = defaults.key;
  TaaSpec t = user;
  const TaaSpec defaults;
  const uint32_t bit = modeBit(user.mode);
  TAA_SETTINGS(TAA_RESET_E, TAA_RESET_B, TAA_RESET_F)
  if (modeRule(user.mode).accumulate) {
    t.consistency = true;
    t.rectify = Rectify::None;
  }
  return t;
#undef TAA_RESET_E
#undef TAA_RESET_B
#undef TAA_RESET_F
}

// The rejection tests that judge history on screen (TAA_ON_SCREEN_REJECTIONS,
// common/taa_settings.h) as ("taa.KEY", whether `t` sets it), in the list's order: what
// validation checks and names.
inline std::vector<std::pair<std::string, bool>> onScreenRejections(const TaaSpec& t) {
#define TAA_ON_SCREEN_ROW(key) {"taa." #key, t.key},
  return {TAA_ON_SCREEN_REJECTIONS(TAA_ON_SCREEN_ROW)};
#undef TAA_ON_SCREEN_ROW
}

}  // namespace taa::spec
