#include "case/case_validate.h"
#include "case/validate_user_shader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>

#include "case/case_error.h"
#include "case/validate_inert.h"
#include "case/validate_inputs.h"
#include "case/validate_invariants.h"
#include "case/validate_report.h"
#include "case/validate_taa.h"
#include "case/validate_tracks.h"
#include "spec/taa_modes.h"

namespace taa::cases {

namespace {

using namespace taa::spec;

class Problems {
 public:
  explicit Problems(std::string file) : file_(std::move(file)) {}
  void add(const std::string& key, const std::string& msg) { list_.push_back(file_ + ": " + key + ": " + msg); }
  void throwIfAny() {
    if (!list_.empty()) throw CaseError(list_);
  }

 private:
  std::string file_;
  std::vector<std::string> list_;
};

void checkAssetPath(Problems& p, const std::string& key, const std::string& value) {
  if (const std::string why = assetPathProblem(value); !why.empty()) p.add(key, why);
}

template <class T>
void checkFrames(Problems& p, const std::string& key, const std::vector<T>& frames, int count) {
  for (size_t i = 0; i < frames.size(); ++i)
    if (frames[i] >= count)
      p.add(key + "[" + std::to_string(i) + "]",
            "frame " + std::to_string(frames[i]) + " is past the last frame " + std::to_string(count - 1) +
                "; lower it or raise script.frames");
}

void validateCamera(Problems& p, CameraSpec& cam, int frames) {
  if (cam.near_plane >= cam.far_plane)
    p.add("camera.near", "near (" + std::to_string(cam.near_plane) + ") must be below far (" +
                             std::to_string(cam.far_plane) + ")");
  if (glm::length(cam.target - cam.position) <= 0.0f)
    p.add("camera.target", "target equals position; the view direction is undefined");
  const auto& path = cam.path;
  const size_t n = path.points.size();
  const size_t needed = path.type == CurveType::BSpline3 ? 4 : path.type == CurveType::BSpline2 ? 3 : 2;
  if (n > 0 && n < needed)
    p.add("camera.path.points", std::to_string(n) + " points given; a " + enumToString(path.type) +
                                    " path needs at least " + std::to_string(needed));
  for (size_t i = 0; i < cam.cuts.size(); ++i) {
    const auto& c = cam.cuts[i];
    const std::string key = "camera.cuts[" + std::to_string(i) + "]";
    if (c.frame >= frames) p.add(key + ".frame", "past the last frame; lower it or raise script.frames");
    if (i > 0 && c.frame <= cam.cuts[i - 1].frame)
      p.add(key + ".frame", "cuts must be listed in increasing frame order");
    if (glm::length(c.target - c.position) <= 0.0f) p.add(key + ".target", "target equals position");
  }
}

void validateMovers(Problems& p, std::vector<MoverSpec>& movers, const std::set<std::string>& present) {
  for (size_t i = 0; i < movers.size(); ++i) {
    const auto& m = movers[i];
    const std::string key = "movers[" + std::to_string(i) + "]";
    if (m.shape == MoverShape::Gltf && m.gltf.empty())
      p.add(key + ".gltf", "shape is gltf but no file is given; set gltf to a .gltf/.glb path");
    if (m.shape != MoverShape::Gltf && !m.gltf.empty())
      p.add(key + ".gltf", "a file is given but shape is '" + std::string(enumToString(m.shape)) +
                               "'; set shape to gltf or remove gltf");
    if (!m.gltf.empty()) checkAssetPath(p, key + ".gltf", m.gltf);
    for (const char* k : {".animation_speed", ".animation_offset_s", ".animations"})
      if (present.count(key + k) && m.shape != MoverShape::Gltf)
        p.add(key + k, "only glTF movers have animations; remove it");
    if (m.rotation_speed_deg != 0.0f && glm::length(m.rotation_axis) <= 0.0f)
      p.add(key + ".rotation_axis", "a zero axis cannot rotate; give a non-zero axis");
  }
}

void validateJitter(Problems& p, JitterSpec& j, const std::set<std::string>& present) {
  if (j.pattern == JitterPattern::Manual && j.points.empty())
    p.add("jitter.points", "the manual pattern needs at least one point, e.g. [[0.25, -0.25]]");
  if (j.pattern != JitterPattern::Manual && present.count("jitter.points"))
    p.add("jitter.points", "points are used only by the manual pattern; set jitter.pattern to manual");
  if (j.pattern != JitterPattern::Halton && present.count("jitter.length"))
    p.add("jitter.length", "length applies only to the halton pattern; remove it");
  for (size_t i = 0; i < j.points.size(); ++i)
    if (std::fabs(j.points[i].x) > 0.5f || std::fabs(j.points[i].y) > 0.5f)
      p.add("jitter.points[" + std::to_string(i) + "]", "offsets are in pixels and must lie in [-0.5, 0.5]");
}

void validateRender(Problems& p, RenderSpec& r) {
  const auto renderW = static_cast<int>(std::lround(float(r.width) / r.upsample));
  const auto renderH = static_cast<int>(std::lround(float(r.height) / r.upsample));
  if (renderW < 1 || renderH < 1)
    p.add("render.upsample", "renders below one pixel; lower upsample or raise the resolution");
  if (r.msaa != 1 && r.msaa != 2 && r.msaa != 4 && r.msaa != 8)
    p.add("render.msaa", "a sample count is 1, 2, 4 or 8; set one of them");
  // The lighting pass reads one albedo, normal and depth per pixel; lighting each sample
  // would be a per-sample deferred path, which the renderer does not have.
  if (r.msaa > 1 && r.path == RenderPath::Deferred)
    p.add("render.msaa",
          "multisampling needs forward shading (the deferred lighting pass reads one sample "
          "per pixel); set render.path: forward or remove render.msaa");
  for (size_t i = 1; i < r.scale_schedule.size(); ++i)
    if (r.scale_schedule[i].frame <= r.scale_schedule[i - 1].frame)
      p.add("render.scale_schedule[" + std::to_string(i) + "].frame", "keys must be in increasing frame order");
}

// Velocity in alpha is seed 001's colour-only resolve: motion blur writes the speed, the
// full resolve reads it with last frame's colour at the same pixel, and nothing else. So
// every setting that needs depth, velocity or ids is refused beside it; with motion blur
// off it falls back to the velocity buffer, as the seed's TAA does (docs/techniques.md).
void validateVelocityInAlpha(Problems& p, const CaseSpec& s, const std::set<std::string>& present) {
  const std::string key = "taa.velocity_in_alpha";
  const auto& t = s.taa;
  if (!modeRule(t.mode).plainFull)
    p.add(key,
          "only the full resolve reads the speed (anything else would pass it on as "
          "alpha); set taa.mode: full or remove it");
  if (!t.velocity_alpha && !t.velocity_attenuation)
    p.add(key,
          "the speed only drives taa.velocity_alpha and taa.velocity_attenuation; set "
          "taa.velocity_alpha: true (or taa.velocity_attenuation: true) or remove it");
  if (!s.post.motion_blur) {
    if (t.use_velocity == UseVelocity::Off)
      p.add(key,
            "with post.motion_blur off it falls back to the velocity buffer, which "
            "taa.use_velocity: off does not read; set taa.use_velocity: all (or movers), "
            "or post.motion_blur: true");
    return;
  }
  if (t.use_velocity != UseVelocity::Off)
    p.add(key,
          "the resolve reads colour only and takes the speed from alpha; set "
          "taa.use_velocity: off or remove taa.velocity_in_alpha");
  const std::string colourOnly = "needs depth, velocity or ids, and with " + key +
                                 " the resolve reads colour only (seed 001); ";
  for (const auto& [name, on] : spec::onScreenRejections(t))
    if (on) p.add(name, colourOnly + "set it false or remove " + key);
  for (const char* name : {"taa.velocity_sampling", "taa.reject_offscreen"})
    if (present.count(name))
      p.add(name, std::string("has no effect: the resolve does not reproject with ") + key +
                      " (seed 001 blends last frame's colour at the same pixel); remove it");
  if (s.debug.output == DebugOutput::Velocity)
    p.add("debug.output", "the velocity view shows the reprojection's motion, and " + key +
                              " has only a speed; choose another view or remove " + key);
}

// Post passes: settings that would silently do nothing are errors.
void validatePost(Problems& p, const CaseSpec& s, const std::set<std::string>& present) {
  const auto& post = s.post;
  if (present.count("post.sharpen_amount") && post.sharpen == Sharpen::None)
    p.add("post.sharpen_amount",
          "set but post.sharpen is none; set post.sharpen to gradient or cas, or remove it");
  for (const char* key : {"post.motion_blur_samples", "post.motion_blur_scale"})
    if (present.count(key) && !post.motion_blur)
      p.add(key, "set but post.motion_blur is off; set post.motion_blur: true or remove it");
  if (s.taa.velocity_in_alpha) validateVelocityInAlpha(p, s, present);
}

}  // namespace

// Relative asset paths must stay inside the case's folder tree, so a case never
// reads arbitrary files and stays portable across checkouts.
std::string assetPathProblem(const std::string& value) {
  if (value.find("://") != std::string::npos)
    return "'" + value + "' is a URI; only local files next to the case are allowed";
  const std::filesystem::path path(value);
  if (path.is_absolute())
    return "'" + value + "' is absolute; give a path relative to the case file";
  for (const auto& part : path.lexically_normal())
    if (part == "..") return "'" + value + "' leaves the case's folder; move the asset under it";
  return "";
}

void validateLighting(Problems& p, const CaseSpec& s, const std::set<std::string>& present) {
  if (glm::length(s.lighting.direction) <= 0.0f) p.add("lighting.direction", "must be non-zero");
  if (present.count("lighting.cascades") && !s.lighting.shadows)
    p.add("lighting.cascades",
          "counts shadow cascades but lighting.shadows is off; set shadows to true or "
          "remove the key");
  // The tracer shades its hits without the shadow atlas, so its pixels would be lit where
  // the raster's are shadowed.
  if (s.lighting.shadows && modeRule(s.taa.mode).adaptive)
    p.add("lighting.shadows",
          "adaptive ray tracing shades its traced pixels without shadows; set taa.mode "
          "to another mode or shadows to false");
}

// LOD matching (seed 000's "always use lod 0", "use lod 0 for alpha test", "aniso"): each
// key only where it changes a lookup.
void validateLod(Problems& p, const CaseSpec& s, const std::set<std::string>& present) {
  if (s.render.lod0 && present.count("material.lod_bias"))
    p.add("material.lod_bias",
          "render.lod0 samples mip 0, which no bias moves; remove one of the two");
  if (s.render.lod0 && s.render.lod0_alpha_test)
    p.add("render.lod0_alpha_test",
          "render.lod0 already tests alpha at mip 0; remove one of the two");
  if (s.render.lod0 && present.count("adaptive.ray_lod") && s.adaptive.ray_lod)
    p.add("adaptive.ray_lod",
          "render.lod0 makes the tracer sample mip 0 too; remove adaptive.ray_lod");
  if (present.count("adaptive.aniso") && (!s.adaptive.ray_lod || s.render.lod0))
    p.add("adaptive.aniso",
          "shapes the ray-differential LOD, which is off (adaptive.ray_lod false or "
          "render.lod0); remove it or turn the LOD approximation on");
}

// debug.image replaces the scene's colour by a still image: nothing may move (the depth and
// velocity the resolve reprojects with are the hidden scene's), and only the raster's
// colour is replaced.
void validateStillImage(Problems& p, const CaseSpec& s, const std::set<std::string>& present) {
  if (s.debug.image.empty()) {
    if (present.count("debug.image_sampling"))
      p.add("debug.image_sampling",
            "samples debug.image, which is not set; set it or remove the key");
    return;
  }
  checkAssetPath(p, "debug.image", s.debug.image);
  const auto& cam = s.camera;
  const bool moves = !cam.path.points.empty() || cam.rotate.yaw_deg_per_s != 0.0f ||
                     cam.rotate.pitch_deg_per_s != 0.0f || cam.bob.amplitude != 0.0f ||
                     cam.strafe.speed != 0.0f || !cam.track.empty() || !cam.cuts.empty();
  if (moves)
    p.add("debug.image",
          "upsamples a still image, but the camera moves; remove camera.path, rotate, bob, strafe, "
          "track and cuts");
  if (!s.movers.empty()) p.add("debug.image", "upsamples a still image; remove the movers");
  if (!modeRule(s.taa.mode).stillImage)
    p.add("debug.image", std::string("replaces the raster's colour only, which taa.mode ") +
                             enumToString(s.taa.mode) + " does not show alone; set taa.mode to " +
                             modeNames(modesWhere(&ModeRule::stillImage)));
}

void validateDebugChannels(Problems& p, const CaseSpec& s, const std::set<std::string>& present) {
  if (!present.count("debug.channels")) return;
  if (s.debug.output == DebugOutput::None)
    p.add("debug.channels",
          "picks channels of a debug view, but debug.output is none; set it or remove the key");
  if (s.debug.channels.empty())
    p.add("debug.channels", "is empty; list at least one of r, g, b, a");
}

void validateCase(CheckedCase& spec, const std::set<std::string>& present) {
  Problems p(spec.file.string());
  const int frames = spec.script.frames;
  if (!spec.scene.gltf.empty()) {
    if (present.count("scene.builtin") && spec.scene.builtin != BuiltinScene::None)
      p.add("scene.builtin", "both a built-in scene and a glTF file are given; set builtin to none");
    spec.scene.builtin = BuiltinScene::None;
    checkAssetPath(p, "scene.gltf", spec.scene.gltf);
  } else if (spec.scene.builtin == BuiltinScene::None) {
    p.add("scene", "no scene: set scene.builtin or scene.gltf");
  }
  if (spec.scene.gltf.empty()) {
    for (const char* k : {"scene.animations", "scene.animation_speed", "scene.animation_offset_s"})
      if (present.count(k))
        p.add(k, "only a glTF scene has animations; remove it or set scene.gltf");
  }
  validateLighting(p, spec, present);
  validateLod(p, spec, present);
  validateStillImage(p, spec, present);
  validateDebugChannels(p, spec, present);
  if (present.count("adaptive.fxaa_debug_border") && !spec.adaptive.fxaa_out_of_history)
    p.add("adaptive.fxaa_debug_border",
          "marks pixels for FXAA, which adaptive.fxaa_out_of_history turns off; "
          "set it to true or remove the key");
  validateRender(p, spec.render);
  validateCamera(p, spec.camera, frames);
  validateMovers(p, spec.movers, present);
  validateJitter(p, spec.jitter, present);
  for (const auto& [key, msg] : taaProblems(spec, present)) p.add(key, msg);
  for (const auto& [key, msg] : emptyPathProblems(spec, present)) p.add(key, msg);
  for (const auto& [key, msg] : outputVolumeProblems(spec)) p.add(key, msg);
  for (const auto& [key, msg] : userShaderProblems(spec, present)) p.add(key, msg);
  for (const auto& [key, msg] : inertProblems(spec, present)) p.add(key, msg);
  if (present.count("material.lod_bias") && spec.material.lod_bias_taa_only &&
      !runsTaa(modeRule(spec.taa.mode)))
    p.add("material.lod_bias", "applies only with TAA (material.lod_bias_taa_only) and taa.mode is off; enable TAA "
                               "or set lod_bias_taa_only to false");
  if (present.count("debug.scale") && spec.debug.output == DebugOutput::None)
    p.add("debug.scale", "has no effect unless debug.output is set; set it or remove the key");
  const ModeRule& rule = modeRule(spec.taa.mode);
  if (spec.debug.output == DebugOutput::Segmentation && !rule.adaptive)
    p.add("debug.output",
          "the segmentation mask comes from adaptive ray tracing; set taa.mode to " +
              modeNames(modesWhere(&ModeRule::adaptive)));
  else if (spec.debug.output != DebugOutput::None && !rule.debugViews)
    p.add("debug.output", "the debug views come from the full resolve; set taa.mode to " +
                              modeNames(modesWhere(&ModeRule::debugViews)));
  validatePost(p, spec, present);
  checkFrames(p, "script.reset_history_at", spec.script.reset_history_at, frames);
  checkFrames(p, "output.frames", spec.output.frames, frames);
  checkFrames(p, "inject.frames", spec.inject.frames, frames);
  if (spec.inject.pixels.size() > 8) p.add("inject.pixels", "at most 8 pixels; split the injection over frames");
  if (!spec.inject.frames.empty() && spec.inject.pixels.empty())
    p.add("inject.pixels", "inject.frames is set but no pixel is; give pixels like [[10, 5]]");
  if (spec.inject.frames.empty() && (present.count("inject.pixels") || present.count("inject.value")))
    p.add("inject.frames", "pixels or value set but no frame; list the frames to inject into");
  for (size_t i = 0; i < spec.inject.pixels.size(); ++i) {
    const auto px = spec.inject.pixels[i];
    if (px.x < 0 || px.y < 0 || px.x >= float(spec.render.width) || px.y >= float(spec.render.height) ||
        px.x != std::floor(px.x) || px.y != std::floor(px.y))
      p.add("inject.pixels[" + std::to_string(i) + "]", "must be whole pixel coordinates inside the render target");
  }
  for (size_t i = 0; i < spec.render.scale_schedule.size(); ++i)
    if (spec.render.scale_schedule[i].frame >= frames)
      p.add("render.scale_schedule[" + std::to_string(i) + "].frame", "past the last frame");
  for (const auto& [key, msg] : invariantProblems(spec, present)) p.add(key, msg);
  for (const auto& [key, msg] : trackProblems(spec, present)) p.add(key, msg);
  for (const auto& [key, msg] : reportProblems(spec, present)) p.add(key, msg);
  p.throwIfAny();

  // Canonical forms the renderer relies on.
  // A mode may have its own default alpha (accumulation: seed 003's 0.2).
  if (const float alpha = modeRule(spec.taa.mode).alpha; alpha > 0.0f && !present.count("taa.alpha"))
    spec.taa.alpha = alpha;
  resolveTaaMoving(spec.taa, present);
  if (spec.output.frames.empty()) spec.output.frames.push_back(frames - 1);
  std::sort(spec.output.frames.begin(), spec.output.frames.end());
  spec.output.frames.erase(std::unique(spec.output.frames.begin(), spec.output.frames.end()),
                           spec.output.frames.end());
  std::sort(spec.script.reset_history_at.begin(), spec.script.reset_history_at.end());
  loadCaseTracks(spec, present);
}

}  // namespace taa::cases
