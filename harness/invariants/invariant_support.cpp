#include "invariants/invariant_support.h"

#include <cstdio>

#include "api/scene_loading.h"
#include "spec/taa_modes.h"

namespace taa::invariants {

using namespace taa::spec;

FrameView FrameView::of(const FrameRecord& r) {
  FrameView v;
  v.frame = r.frame;
  v.historyReset = r.historyReset;
  // A frame whose images were not read still carries its output when every frame is hashed.
  v.output = r.hasImages || !r.color.data.empty() ? &r.color : nullptr;
  v.sha256 = r.colorSha256;
  for (const CaptureInfo& c : kCaptures) v.set(c.capture, r.capture(c.capture));
  return v;
}

std::string num(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", value);
  return buf;
}

std::string whatMoves(const CaseSpec& spec) {
  const CameraSpec& cam = spec.camera;
  if (!cam.path.points.empty())
    return "camera.path has " + std::to_string(cam.path.points.size()) + " points";
  if (cam.rotate.yaw_deg_per_s != 0.0f)
    return "camera.rotate.yaw_deg_per_s is " + num(cam.rotate.yaw_deg_per_s);
  if (cam.rotate.pitch_deg_per_s != 0.0f)
    return "camera.rotate.pitch_deg_per_s is " + num(cam.rotate.pitch_deg_per_s);
  if (cam.bob.amplitude > 0.0f && cam.bob.frequency_hz > 0.0f)
    return "camera.bob.amplitude is " + num(cam.bob.amplitude);
  if (cam.strafe.speed > 0.0f) return "camera.strafe.speed is " + num(cam.strafe.speed);
  if (!cam.cuts.empty()) return "camera.cuts has " + std::to_string(cam.cuts.size()) + " cut(s)";
  if (!spec.scene.gltf.empty() && spec.scene.animation_speed > 0.0f &&
      gltfAnimates(spec.file.parent_path() / spec.scene.gltf))
    return "the glTF scene's own animations play (scene.animation_speed is " +
           num(spec.scene.animation_speed) + "; 0 holds them)";
  for (size_t i = 0; i < spec.movers.size(); ++i) {
    const MoverSpec& m = spec.movers[i];
    const std::string key = "movers[" + std::to_string(i) + "]";
    if (m.speed > 0.0f) return key + ".speed is " + num(m.speed);
    if (m.rotation_speed_deg != 0.0f)
      return key + ".rotation_speed_deg is " + num(m.rotation_speed_deg);
    // The model's own node animation moves it even at speed 0.
    if (m.shape == MoverShape::Gltf && m.animation_speed > 0.0f)
      return key + ".animation_speed is " + num(m.animation_speed);
  }
  return "";
}

std::string noHistoryReason(const std::string& name, const CaseSpec& spec) {
  const auto m = spec.taa.mode;
  if (modeRule(m).history) return "";
  return name + " needs a temporal history, but taa.mode is " + enumToString(m) +
         "; remove it from checks.invariants or set taa.mode to one that keeps a history";
}

std::string renderSizeReason(const std::string& name, const CaseSpec& spec) {
  const char* fix = "; remove it from checks.invariants or render at output size";
  if (spec.render.upsample != 1.0f)
    return name +
           " compares pixels of render-size buffers with the output, but render.upsample is " +
           num(spec.render.upsample) + fix;
  if (modeRule(spec.taa.mode).tscmaa && spec.tscmaa.eyes == 2)
    return name +
           " compares pixels of render-size buffers with the output, but tscmaa.eyes 2 puts two "
           "eyes side by side; remove it from checks.invariants or render one eye";
  if (!spec.render.scale_schedule.empty())
    return name +
           " compares pixels of render-size buffers with the output, but render.scale_schedule "
           "changes the render size" +
           fix;
  return "";
}

std::string debugViewReason(const std::string& name, const CaseSpec& spec) {
  if (spec.debug.output == DebugOutput::None) return "";
  return name + " measures the image, but debug.output is " + enumToString(spec.debug.output) +
         ", which replaces it by a debug view; remove it from checks.invariants or set "
         "debug.output "
         "to none";
}

std::string jitterConstant(const CaseSpec& spec) {
  const JitterSpec& j = spec.jitter;
  if (j.pattern == JitterPattern::None) return "jitter.pattern is none";
  if (j.lock >= 0) return "jitter.lock is " + std::to_string(j.lock);
  if (j.scale == 0.0f) return "jitter.scale is 0";
  if (j.pattern == JitterPattern::Halton && j.length == 1) return "jitter.length is 1";
  if (j.pattern == JitterPattern::Manual && j.points.size() <= 1)
    return "jitter.points has one point";
  return "";
}

std::string jitterVaries(const CaseSpec& spec) {
  if (!jitterConstant(spec).empty()) return "";
  return std::string("jitter.pattern ") + enumToString(spec.jitter.pattern) +
         " moves the samples every frame";
}

std::string requireImage(const FrameView& f, const Image* img, const char* what, int minChannels) {
  const std::string at = "frame " + std::to_string(f.frame) + ": ";
  if (f.output == nullptr) return at + "no output image was read back";
  if (img == nullptr) return at + "no " + what + " image was read back";
  if (img->width != f.output->width || img->height != f.output->height)
    return at + what + " is " + std::to_string(img->width) + "x" + std::to_string(img->height) +
           " but the output is " + std::to_string(f.output->width) + "x" +
           std::to_string(f.output->height);
  if (img->channels < minChannels)
    return at + what + " has " + std::to_string(img->channels) + " channel(s), " +
           std::to_string(minChannels) + " needed";
  return "";
}

std::string requireCaptures(const FrameView& f, int outputChannels,
                            std::initializer_list<RequiredCapture> captures) {
  if (auto why = requireImage(f, f.output, "output", outputChannels); !why.empty()) return why;
  for (const auto& r : captures)
    if (auto why = requireImage(f, f.capture(r.capture), captureName(r.capture), r.minChannels);
        !why.empty())
      return why;
  return "";
}

}  // namespace taa::invariants
