// What the settings audit leaves out, and why (docs/settings-audit.md). Two lists, both meant
// to stay short: keys it does not try, and keys whose change its scene cannot show on a path.
// Every entry that could change pixels names the test that shows it acting.
#include <string>

#include "support/settings_audit.h"

namespace taa::test::audit {

const std::vector<Exclusion>& exclusions() {
  static const std::vector<Exclusion> list = {
      // Cannot change pixels by design: read by the harness after rendering, or choose what is
      // written, never what is drawn (their implementing files are under harness/ or readback).
      {"description", "free text for people"},
      {"checks.*",
       "judges the rendered frames (harness/golden, harness/compare, harness/invariants)"},
      {"report.*", "what the HTML report shows (harness/run); renders nothing of the case"},
      {"output.*",
       "which frames and buffers are written (renderer/frame/readback.cpp); the audit reads every "
       "frame's colour anyway"},
      {"reference.samples",
       "the supersampled ground truth's sample count: the reference image, not "
       "the output (EffectUpsample.ConvergesTowardTheFullResolutionReference uses it)"},
      // A value the generic audit cannot invent: a file or a list of objects. Each is shown acting
      // by the named test.
      {"scene.gltf", "a glTF file (GltfKhronos.BoxAnimatedPlaysBothAnimations)"},
      {"scene.animations",
       "names a glTF file's animations "
       "(GltfPick.CaseChoosesAnimationsByNameOrIndexAndRefusesUnknownOnes)"},
      {"movers[].gltf", "a glTF file (case gltf_animated_mover's goldens)"},
      {"movers[].animations",
       "names a glTF mover's animations "
       "(GltfPick.CaseChoosesAnimationsByNameOrIndexAndRefusesUnknownOnes)"},
      {"camera.track", "a track file (TrackCase.ShippedCsvCaptureCaseReplaysWithItsCut)"},
      {"camera.track_camera",
       "a glTF camera node of a track file (TrackGltf.CameraNodeWorldPoseAtKnownTimes)"},
      {"movers[].track",
       "a track file (TrackBake.RenderedFramesAreBitIdentical, case track_csv_capture)"},
      {"debug.image", "an image file (StillImage.TemporalUpsamplingConvergesTowardsTheImage)"},
      {"taa.shader",
       "a user's GLSL file (ctest example.user_taa.*: goldens of the shipped user resolves)"},
      {"taa.shader_entry",
       "a function of a user's HLSL file, with taa.shader only "
       "(GlslCompilerTest.HlslEntryPointParametersHistoriesAndErrors)"},
      {"taa.shader_params*",
       "constants of a user's shader (UserCaseTest.ValidShaderAndParamsLoad, example.user_taa.*)"},
      {"taa.shader_defines",
       "keywords of a user's shader, names inside its file "
       "(UserCaseTest.ShaderDefinesPickTheVariantAndBadNamesAreRefused)"},
      {"render.scale_schedule*",
       "a list of keyframes "
       "(EffectDynamicResolution.PanningErrorStaysCloseToTheFixedResolutionRun)"},
      {"camera.cuts*", "a list of shots (EffectHistoryReset.CameraCutOutputsTheCurrentFrame)"},
      {"movers",
       "the list itself; its members' keys (movers[].*) are audited on the scene's one mover"},
  };
  return list;
}

const Exclusion* excluded(const std::string& key) {
  for (const auto& e : exclusions()) {
    const std::string k = e.key;
    if (key == k) return &e;
    // A trailing '*' covers every key it prefixes: "checks.*", "camera.cuts*" (and cuts[].*).
    if (k.back() == '*' && key.rfind(k.substr(0, k.size() - 1), 0) == 0) return &e;
  }
  return nullptr;
}

const std::vector<Allowance>& allowances() {
  static const std::vector<Allowance> list = {
      // By design: pass_through copies the rendered frame through the resolve pass (it measures
      // the pass and its plumbing), so its pixels are off's.
      {"taa.mode", "off", "pass_through shows the rendered frame unchanged, as off does",
       "EffectPassThrough.OutputIsTheInputBitForBit"},
      {"taa.mode", "pass_through", "off shows the rendered frame unchanged, as pass_through does",
       "EffectPassThrough.OutputIsTheInputBitForBit"},
      // The scene cannot show it: every pixel with another id beside it is already marked by the
      // luminance, depth or normal term, so the material term adds none.
      {"adaptive.weight_material", "adaptive",
       "the other derivative terms already mark every pixel the material term marks here",
       "AdaptiveSegmentation.EachWeightMarksPixelsByItself"},
  };
  return list;
}

const Allowance* allowed(const std::string& key, const std::string& path) {
  for (const auto& a : allowances())
    if (key == a.key && (std::string(a.path) == "*" || path == a.path)) return &a;
  return nullptr;
}

}  // namespace taa::test::audit
