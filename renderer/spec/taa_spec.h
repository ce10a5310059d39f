// The temporal resolve and what runs around it: TAA settings, post-processing and
// debug views. Every switch here becomes a specialization constant of a pass.
#pragma once

#include <string>
#include <vector>

#include "common/taa_settings.h"
#include "spec/fields.h"

namespace taa::spec {

enum class TaaMode { Off, PassThrough, Basic, Full, Accumulate, Tscmaa, Adaptive };
TAA_ENUM_NAMES(TaaMode, {TaaMode::Off, "off"}, {TaaMode::PassThrough, "pass_through"},
               {TaaMode::Basic, "basic"}, {TaaMode::Full, "full"},
               {TaaMode::Accumulate, "accumulate"}, {TaaMode::Tscmaa, "tscmaa"},
               {TaaMode::Adaptive, "adaptive"})

// The resolve's enums and settings are declared in shaders/common/taa_settings.h, shared
// with the shaders; here they become C++ enums (with the same named constants the
// shaders use, e.g. HISTORY_FILTER_CATMULL_ROM_5), TaaSpec and its field list.
#define TAA_CXX_ENUMERATOR(cxx, glsl, value, name) cxx = value,
#define TAA_CXX_NAMED_VALUE(cxx, glsl, value, name) inline constexpr int glsl = value;
#define TAA_CXX_ENUM_NAME(cxx, glsl, value, name) {Self::cxx, name},
#define TAA_DECLARED_ENUM(E, VALUES)                                                  \
  enum class E { VALUES(TAA_CXX_ENUMERATOR) };                                        \
  VALUES(TAA_CXX_NAMED_VALUE)                                                         \
  inline std::span<const ::taa::spec::EnumName<E>> enumNames(E) {                     \
    using Self = E;                                                                   \
    static constexpr ::taa::spec::EnumName<E> kNames[] = {VALUES(TAA_CXX_ENUM_NAME)}; \
    return kNames;                                                                    \
  }

TAA_DECLARED_ENUM(Resolve, TAA_RESOLVE_VALUES)
TAA_DECLARED_ENUM(ToneWeight, TAA_TONE_WEIGHT_VALUES)
TAA_DECLARED_ENUM(UseVelocity, TAA_USE_VELOCITY_VALUES)
TAA_DECLARED_ENUM(VelocitySampling, TAA_VELOCITY_SAMPLING_VALUES)
TAA_DECLARED_ENUM(HistoryFilter, TAA_HISTORY_FILTER_VALUES)
TAA_DECLARED_ENUM(Rectify, TAA_RECTIFY_VALUES)
TAA_DECLARED_ENUM(ColorSpace, TAA_COLOR_SPACE_VALUES)
TAA_DECLARED_ENUM(HistoryFormat, TAA_HISTORY_FORMAT_VALUES)
TAA_DECLARED_ENUM(DebugOutput, TAA_DEBUG_OUTPUT_VALUES)

#define TAA_CXX_MEMBER_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  type key = type(def);
#define TAA_CXX_MEMBER_B(key, def, id, name, modes, reads, rule, text, doc, impl) bool key = def;
#define TAA_CXX_MEMBER_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  float key = def;

// The uniform slot of each float setting, by the name the shaders use (TAA_PARAM_ALPHA).
#define TAA_CXX_SLOT_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_CXX_SLOT_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_CXX_SLOT_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  inline constexpr int name = slot;
TAA_SETTINGS(TAA_CXX_SLOT_E, TAA_CXX_SLOT_B, TAA_CXX_SLOT_F)

// The language of a user's resolve (taa.shader_language): auto takes the file's extension.
enum class ShaderLanguage { Auto, Glsl, Hlsl };
TAA_ENUM_NAMES(ShaderLanguage, {ShaderLanguage::Auto, "auto"}, {ShaderLanguage::Glsl, "glsl"},
               {ShaderLanguage::Hlsl, "hlsl"})

// One specialization constant of a user's resolve (taa.shader), by its name in the shader.
struct ShaderParam {
  std::string name;
  NumberOrBool value;  // double: an int's and a uint's whole 32-bit range is exact
};

template <class V>
void fields(V& v, ShaderParam& p) {
  v.field("name", p.name,
          Meta{"the constant's name in the shader (layout(constant_id = N) const T name), or a "
               "loose uniform's",
               "renderer/user/user_interface.cpp"});
  v.field("value", p.value,
          Meta{"its value (required): true or false (or 1 or 0) for a bool, a whole number for an "
               "int (-2147483648 to 2147483647) or a uint (0 to 4294967295), a number for a "
               "float; a loose uniform's vector or matrix takes a list of its numbers",
               "renderer/user/user_resolve.cpp"});
}

// taa.moving (seed 000: "ideally one would smoothly blend parameters when switching sets"):
// a second value for any float setting of the resolve, blended in by the camera's speed on
// screen. Only floats: they are uniforms, so they can change every frame; enums and switches
// are specialization constants and would need another pipeline.
#define TAA_CXX_NONE_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_CXX_NONE_B(key, def, id, name, modes, reads, rule, text, doc, impl)
struct TaaMovingSpec {
  float from_px = 0.5f;
  float to_px = 4.0f;
  float depth = 10.0f;
  TAA_SETTINGS(TAA_CXX_NONE_E, TAA_CXX_NONE_B, TAA_CXX_MEMBER_F)
  // Not a key: the case sets taa.moving. The case loader copies the still value into every
  // float the object leaves out, so a blend changes only what the case names.
  bool active = false;
};

#define TAA_CXX_MOVING_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  v.field(#key, s.key, Range<float>{lo, hi},                                         \
          Meta{"taa." #key " while the camera moves (default: taa." #key ")", impl,  \
               "TaaUniforms.settings slot " #slot " (" #name "), blended", text});

template <class V>
void fields(V& v, TaaMovingSpec& s) {
  const char* impl = "renderer/passes/taa_moving.cpp";
  v.field("from_px", s.from_px, Range<float>{0.0f, 1e6f},
          Meta{"camera speed on screen (render pixels per frame) up to which the still settings "
               "apply unchanged",
               impl});
  v.field("to_px", s.to_px, Range<float>{0.0f, 1e6f},
          Meta{"camera speed from which the moving settings apply in full; between from_px and "
               "to_px the weight is a smoothstep",
               impl});
  v.field("depth", s.depth, Range<float>{1e-3f, 1e6f},
          Meta{"the speed is that of points this far in front of the camera (world units), the "
               "largest of five across the screen, reprojected from the previous frame",
               impl});
  TAA_SETTINGS(TAA_CXX_NONE_E, TAA_CXX_NONE_B, TAA_CXX_MOVING_F)
}

struct TaaSpec {
  TaaMode mode = TaaMode::Full;
  TAA_SETTINGS(TAA_CXX_MEMBER_E, TAA_CXX_MEMBER_B, TAA_CXX_MEMBER_F)
  TaaMovingSpec moving;
  // A user's own resolve (docs/user-taa.md): replaces the built-in one when set.
  std::string shader;
  ShaderLanguage shader_language = ShaderLanguage::Auto;
  std::string shader_entry = "main";
  std::vector<ShaderParam> shader_params;
  // Preprocessor defines, "NAME" or "NAME=VALUE": an engine's keywords (Unity's multi_compile,
  // Godot's version defines) chosen per variant without a wrapper file per variant.
  std::vector<std::string> shader_defines;
  bool shader_clamps = false;
  // Not keys: set for the lanes the harness builds (score, sweep), never by a case file.
  // The folder taa.shader is relative to and its includes must stay inside, when it is not
  // the case's (a scorecard's lane names a shader on its command line, a sweep's preset one
  // beside its presets file); empty: the case's folder.
  std::string shader_root;
  // The lane's runner skips, with the reason, a case its shader lacks a capability for
  // (user::missingCapabilities) instead of validation refusing the case.
  bool shader_capabilities_unchecked = false;
};

#define TAA_CXX_FIELD_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  v.field(#key, s.key, Meta{doc, impl, "specialization constant " #id " (" #name ")", text});
#define TAA_CXX_FIELD_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  v.field(#key, s.key, Meta{doc, impl, "specialization constant " #id " (" #name ")", text});
#define TAA_CXX_FIELD_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  v.field(#key, s.key, Range<float>{lo, hi},                                        \
          Meta{doc, impl, "TaaUniforms.settings slot " #slot " (" #name ")", text});

template <class V>
void fields(V& v, TaaSpec& s) {
  v.field(
      "mode", s.mode,
      Meta{"off: no temporal pass; pass_through: copy the input; basic: blend with the same pixel "
           "(no reprojection, shows ghosting); full: every enabled technique; accumulate: temporal "
           "accumulation with geometric consistency (SVGF, alpha 0.2); tscmaa: CMAA plus TAA on "
           "edge "
           "pixels; adaptive: full TAA plus ray-traced samples where a segmentation marks aliasing",
           "renderer/spec/taa_modes.h"});
  TAA_SETTINGS(TAA_CXX_FIELD_E, TAA_CXX_FIELD_B, TAA_CXX_FIELD_F)
  v.object("moving", s.moving,
           Meta{"a second set of the resolve's float settings, blended in smoothly as the camera "
                "moves (seed 000); any float taa key, plus from_px, to_px and depth",
                "renderer/passes/taa_moving.cpp"});
  v.field("shader", s.shader,
          Meta{"your own resolve: a GLSL compute shader including taa_user.h, or an HLSL one "
               "including taa_user.hlsli, relative to the case file and inside its folder; "
               "replaces the built-in resolve (taa.mode full only, no other built-in taa setting)",
               "renderer/user/user_resolve.cpp"});
  v.field("shader_language", s.shader_language,
          Meta{"the shader's language: auto (by its extension: .hlsl is HLSL, anything else GLSL), "
               "glsl or hlsl",
               "renderer/user/glsl_compiler.cpp", "", "taa.shader is set"});
  v.field("shader_entry", s.shader_entry,
          Meta{"an HLSL shader's entry point (GLSL's is always main)",
               "renderer/user/glsl_compiler.cpp", "", "taa.shader is an HLSL shader"});
  v.list("shader_params", s.shader_params,
         Meta{"values for the shader's specialization constants and loose uniforms (HLSL's "
              "$Global), [{\"name\": ..., \"value\": ...}]; checked against what the shader "
              "declares",
              "renderer/user/user_interface.cpp", "", "taa.shader is set"});
  v.field("shader_defines", s.shader_defines,
          Meta{"preprocessor defines for the shader, each \"NAME\" (defined as 1) or "
               "\"NAME=VALUE\", as a compiler's -D: an engine's keywords chosen per case, lane "
               "or preset; a NAME that no file of the compile (the shader, its includes, the "
               "harness's header) names is refused, with the nearest name those files hold (a "
               "typo would select nothing)",
               "renderer/api/shader_defines.cpp", "", "taa.shader is set"});
  v.field(
      "shader_clamps", s.shader_clamps,
      Meta{"the shader promises its output stays inside the current frame's 3x3 RGB min/max box, "
           "so the history_bounded invariant may check it",
           "harness/invariants/history_bounded.cpp", "", "taa.shader is set"});
}

// Adaptive ray tracing (Marrs et al.), active when taa.mode is adaptive: after the
// full resolve a segmentation marks aliased pixels, which get `samples` traced rays.
struct AdaptiveSpec {
  int samples = 4;
  float threshold = 0.25f;
  float weight_normal = 1.0f;
  float weight_depth = 1.0f;
  float weight_material = 1.0f;
  float weight_luminance = 1.0f;
  int history_count = 8;
  bool fxaa_out_of_history = true;
  bool trace_disoccluded = false;
  bool ray_lod = true;
  float aniso = 1.0f;
  bool trace_all = false;
  int fxaa_debug_border = 0;
};

template <class V>
void fields(V& v, AdaptiveSpec& s) {
  const char* seg = "shaders/adaptive_segmentation.comp";
  const char* trace = "shaders/adaptive_trace.comp";
  v.field("samples", s.samples, Range<int>{1, 16},
          Meta{"rays traced per marked pixel, at fixed sub-pixel positions of the Hammersley set "
               "(stratified "
               "in x and y; 1 = the pixel centre)",
               trace});
  v.field(
      "threshold", s.threshold, Range<float>{0.0f, 1e6f},
      Meta{"a pixel is traced when the weighted sum of its derivative terms exceeds this", seg});
  v.field(
      "weight_normal", s.weight_normal, Range<float>{0.0f, 1e6f},
      Meta{"weight of the normal term: (1 - cos) / 2 of the largest normal change to a 4-neighbour",
           seg});
  v.field("weight_depth", s.weight_depth, Range<float>{0.0f, 1e6f},
          Meta{"weight of the depth term: largest relative linear-depth change to a 4-neighbour "
               "(at most 1)",
               seg});
  v.field("weight_material", s.weight_material, Range<float>{0.0f, 1e6f},
          Meta{"weight of the material term: 1 where a 4-neighbour has another id (object, "
               "material or sky)",
               seg});
  v.field("weight_luminance", s.weight_luminance, Range<float>{0.0f, 1e6f},
          Meta{"weight of the luminance term: largest change of tonemapped luma to a 4-neighbour",
               seg});
  v.field(
      "history_count", s.history_count, Range<int>{0, 255},
      Meta{"frames a pixel stays traced after its derivatives last marked it (0: no history count)",
           seg});
  v.field("fxaa_out_of_history", s.fxaa_out_of_history,
          Meta{"pixels without usable history (off screen, rejected, reset) that are not traced "
               "get FXAA",
               "shaders/fxaa.comp"});
  v.field(
      "trace_disoccluded", s.trace_disoccluded,
      Meta{
          "pixels whose history was rejected on screen (disocclusion) are traced instead of FXAA'd",
          seg});
  v.field("ray_lod", s.ray_lod,
          Meta{"texture LOD from ray differentials (rays one pixel right and one down), matching "
               "the raster's "
               "mip selection; false samples mip 0",
               trace});
  v.field(
      "aniso", s.aniso, Range<float>{1.0f, 16.0f},
      Meta{"anisotropy of the ray-differential LOD: the longer UV gradient is shortened by up to "
           "this ratio, so the LOD follows the footprint's shorter axis (1: isotropic, the "
           "raster's choice)",
           trace});
  v.field("trace_all", s.trace_all, Meta{"debug: trace every pixel", seg});
  v.field(
      "fxaa_debug_border", s.fxaa_debug_border, Range<int>{0, 4096},
      Meta{"debug (the seed's 'Fxaa dbg.'): a border this many output pixels wide is always marked "
           "for FXAA (0: none)",
           seg});
}

// TSCMAA (taa.mode tscmaa): CMAA on the edge pixels of a luma edge detection, then TAA
// on a share of them; the knobs follow the seed's SetEdgeThresholds.
struct TscmaaSpec {
  float edge_threshold = 1.0f / 22.0f;
  float non_dominant_edge_removal = 0.5f;
  float blurriness = 0.7f;
  float taa_share = 0.5f;
  float history_weight = 0.8f;
  int eyes = 1;
  float eye_separation = 0.064f;
};

template <class V>
void fields(V& v, TscmaaSpec& s) {
  const char* edges = "shaders/tscmaa/edge_rules.glsl";
  v.field(
      "edge_threshold", s.edge_threshold, Range<float>{0.0f, 1.0f},
      Meta{"CMAA's edge threshold: the smallest difference of display-encoded colours (clipped to "
           "[0, 1], square root, Rec. 709 weights on each channel's difference) that makes an "
           "edge; the seed recommends 1/32 .. 1",
           edges});
  v.field("non_dominant_edge_removal", s.non_dominant_edge_removal, Range<float>{0.0f, 8.0f},
          Meta{"CMAA's non-dominant edge removal: an edge must reach mean + this x (max - mean) of "
               "the twelve edges around it (0: the mean; 1: only the strongest stay); the seed "
               "recommends 0 .. 3",
               edges});
  v.field("blurriness", s.blurriness, Range<float>{0.0f, 4.0f},
          Meta{"scales the neighbours' weights in CMAA's simple-shape blend of pixels with 2 to 4 "
               "edges (0.7 gives CMAA's own 0.08/0.11/0.05; not edge detection)",
               "shaders/tscmaa/simple_shape.glsl"});
  v.field(
      "taa_share", s.taa_share, Range<float>{0.0f, 1.0f},
      Meta{"share of edge pixels that also get TAA, chosen by a fixed hash of the pixel", edges});
  v.field("history_weight", s.history_weight, Range<float>{0.0f, 1.0f},
          Meta{"weight of the rectified history in the TAA blend of TAA edge pixels",
               "shaders/tscmaa_taa.comp"});
  v.field("eyes", s.eyes, Range<int>{1, 2},
          Meta{"1, or 2 for stereo: both eyes side by side, output width = 2 x render.width",
               "renderer/passes/tscmaa.cpp"});
  v.field("eye_separation", s.eye_separation, Range<float>{0.0f, 100.0f},
          Meta{"distance between the eyes in world units; each eye sits half of it along the "
               "camera's right axis",
               "renderer/script/stereo.cpp"});
}

enum class Sharpen { None, Gradient, Cas };
TAA_ENUM_NAMES(Sharpen, {Sharpen::None, "none"}, {Sharpen::Gradient, "gradient"},
               {Sharpen::Cas, "cas"})

struct PostSpec {
  Sharpen sharpen = Sharpen::None;
  float sharpen_amount = 0.5f;
  bool fxaa = false;
  bool motion_blur = false;
  int motion_blur_samples = 8;
  float motion_blur_scale = 1.0f;
};

template <class V>
void fields(V& v, PostSpec& s) {
  v.field(
      "sharpen", s.sharpen,
      Meta{"after the resolve: none, a 5-tap gradient sharpener, or Contrast Adaptive Sharpening",
           "shaders/sharpen.comp"});
  v.field("sharpen_amount", s.sharpen_amount, Range<float>{0.0f, 1.0f},
          Meta{"sharpening strength: gradient adds amount x the 5-tap Laplacian / 4; cas moves the "
               "negative lobe from -1/8 (0) to -1/5 (1)",
               "shaders/sharpen.comp"});
  v.field("fxaa", s.fxaa,
          Meta{"FXAA on the output (alone, or after the resolve)", "shaders/fxaa.comp"});
  v.field("motion_blur", s.motion_blur,
          Meta{"blur along each pixel's own velocity before the resolve (centred box, depth-aware: "
               "nearer surfaces do not bleed into the blur)",
               "shaders/motion_blur.comp"});
  v.field("motion_blur_samples", s.motion_blur_samples, Range<int>{2, 64},
          Meta{"taps along the velocity vector", "shaders/motion_blur.comp"});
  v.field("motion_blur_scale", s.motion_blur_scale, Range<float>{0.0f, 4.0f},
          Meta{"fraction of the frame's motion covered by the blur (shutter)",
               "shaders/motion_blur.comp"});
}

enum class ImageSampling { Bilinear, Nearest };
TAA_ENUM_NAMES(ImageSampling, {ImageSampling::Bilinear, "bilinear"},
               {ImageSampling::Nearest, "nearest"})

enum class DebugChannel { R, G, B, A };
TAA_ENUM_NAMES(DebugChannel, {DebugChannel::R, "r"}, {DebugChannel::G, "g"}, {DebugChannel::B, "b"},
               {DebugChannel::A, "a"})

struct DebugSpec {
  DebugOutput output = DebugOutput::None;
  std::vector<DebugChannel> channels{DebugChannel::R, DebugChannel::G, DebugChannel::B,
                                     DebugChannel::A};
  float scale = 1.0f;
  std::string image;  // still-image upsampling: relative to the case file
  ImageSampling image_sampling = ImageSampling::Bilinear;
};

template <class V>
void fields(V& v, DebugSpec& s) {
  v.field("output", s.output,
          Meta{"replace the output by a debug view: velocity (rg = v * scale / 2 + 0.5), rejection "
               "mask, "
               "clamp distance (times scale), segmentation (adaptive mode: yellow traced by "
               "derivatives, "
               "orange traced by history count, blue FXAA, grey the rest)",
               "shaders/taa_resolve.comp"});
  v.field("scale", s.scale, Range<float>{1e-6f, 1e6f},
          Meta{"multiplier of the debug values", "shaders/taa_resolve.comp"});
  v.field(
      "channels", s.channels,
      Meta{"channels of the debug view shown (the seed's R, G, B, A toggles); the others read 0 "
           "(alpha 1)",
           "shaders/debug_channels.comp"});
  v.field(
      "image", s.image,
      Meta{"still-image upsampling (the seed's Debug/image mode): this image (PNG or EXR, output "
           "size, relative to the case file) replaces the scene's colour, sampled at each render "
           "pixel's jittered position; the reference is the image itself",
           "shaders/still_image.comp"});
  v.field("image_sampling", s.image_sampling,
          Meta{"how the still image is sampled at render resolution: bilinear or nearest",
               "shaders/still_image.comp"});
}

}  // namespace taa::spec
