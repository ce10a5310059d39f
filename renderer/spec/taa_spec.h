// The temporal resolve and what runs around it: TAA settings, post-processing and
// debug views. Every switch here becomes a specialization constant of a pass.
#pragma once

#include "spec/fields.h"

namespace taa::spec {

enum class TaaMode { Off, PassThrough, Basic, Full, Accumulate, Tscmaa, Adaptive };
TAA_ENUM_NAMES(TaaMode, {TaaMode::Off, "off"}, {TaaMode::PassThrough, "pass_through"}, {TaaMode::Basic, "basic"},
               {TaaMode::Full, "full"}, {TaaMode::Accumulate, "accumulate"}, {TaaMode::Tscmaa, "tscmaa"},
               {TaaMode::Adaptive, "adaptive"})

enum class ToneWeight { None, Karis, InverseLuma, Log };
TAA_ENUM_NAMES(ToneWeight, {ToneWeight::None, "none"}, {ToneWeight::Karis, "karis"},
               {ToneWeight::InverseLuma, "inverse_luma"}, {ToneWeight::Log, "log"})

enum class UseVelocity { Off, Movers, All };
TAA_ENUM_NAMES(UseVelocity, {UseVelocity::Off, "off"}, {UseVelocity::Movers, "movers"}, {UseVelocity::All, "all"})

enum class VelocitySampling { Pixel, Longest3x3, Closest3x3 };
TAA_ENUM_NAMES(VelocitySampling, {VelocitySampling::Pixel, "pixel"}, {VelocitySampling::Longest3x3, "longest3x3"},
               {VelocitySampling::Closest3x3, "closest3x3"})

enum class HistoryFilter { Bilinear, BSpline, CatmullRom9, CatmullRom5, CatmullRom16 };
TAA_ENUM_NAMES(HistoryFilter, {HistoryFilter::Bilinear, "bilinear"}, {HistoryFilter::BSpline, "bspline"},
               {HistoryFilter::CatmullRom9, "catmull_rom_9"}, {HistoryFilter::CatmullRom5, "catmull_rom_5"},
               {HistoryFilter::CatmullRom16, "catmull_rom_16"})

enum class Rectify { None, Clamp, Clip };
TAA_ENUM_NAMES(Rectify, {Rectify::None, "none"}, {Rectify::Clamp, "clamp"}, {Rectify::Clip, "clip"})

enum class ColorSpace { Rgb, YCoCg };
TAA_ENUM_NAMES(ColorSpace, {ColorSpace::Rgb, "rgb"}, {ColorSpace::YCoCg, "ycocg"})

enum class HistoryFormat { Rgba16f, Rgba32f };
TAA_ENUM_NAMES(HistoryFormat, {HistoryFormat::Rgba16f, "rgba16f"}, {HistoryFormat::Rgba32f, "rgba32f"})

struct TaaSpec {
  TaaMode mode = TaaMode::Full;
  float alpha = 0.1f;
  ToneWeight tonemap_weighting = ToneWeight::None;
  UseVelocity use_velocity = UseVelocity::All;
  VelocitySampling velocity_sampling = VelocitySampling::Closest3x3;
  HistoryFilter history_filter = HistoryFilter::CatmullRom5;
  bool reject_offscreen = true;
  bool depth_culling = false;
  float depth_threshold = 0.05f;
  bool consistency = false;
  float consistency_depth = 0.05f;
  float consistency_normal = 0.9f;
  bool anti_ghosting = false;
  float rejection_alpha = 1.0f;
  Rectify rectify = Rectify::Clip;
  bool variance_clip = false;
  float variance_gamma = 1.0f;
  bool shaped_neighborhood = false;
  ColorSpace color_space = ColorSpace::YCoCg;
  bool shrink_chroma = false;
  bool luma_weight = false;
  float alpha_min = 0.04f;
  float alpha_max = 0.2f;
  bool velocity_alpha = false;
  float velocity_alpha_px = 32.0f;
  bool reduce_blend_near_clamp = false;
  bool velocity_in_alpha = false;
  HistoryFormat history_format = HistoryFormat::Rgba16f;
};

template <class V>
void fields(V& v, TaaSpec& s) {
  const char* resolve = "shaders/taa_resolve.comp";
  v.field("mode", s.mode,
          Meta{"off: no temporal pass; pass_through: copy the input; basic: blend with the same pixel "
               "(no reprojection, shows ghosting); full: every enabled technique; accumulate: temporal "
               "accumulation with geometric consistency (SVGF, alpha 0.2); tscmaa: CMAA plus TAA on edge "
               "pixels; adaptive: full TAA plus ray-traced samples where a segmentation marks aliasing",
               resolve});
  v.field("alpha", s.alpha, Range<float>{0.0f, 1.0f},
          Meta{"weight of the current sample (higher = less history)", "shaders/taa/blend_weight.glsl"});
  v.field("tonemap_weighting", s.tonemap_weighting,
          Meta{"blend in a luminance-weighted space against flicker: Karis (1/(1+luma)), inverse "
               "luminance tonemap, or log",
               "shaders/taa/color_space.glsl"});
  v.field("use_velocity", s.use_velocity,
          Meta{"where the motion-vector buffer drives reprojection: off (depth + inverse view-projection "
               "everywhere), movers (velocity on movers, depth elsewhere) or all",
               "shaders/taa/reprojection.glsl"});
  v.field("velocity_sampling", s.velocity_sampling,
          Meta{"which velocity a pixel uses: its own, the longest in 3x3, or the depth-closest in 3x3",
               "shaders/taa/reprojection.glsl"});
  v.field("history_filter", s.history_filter,
          Meta{"history resampling: bilinear, B-spline (4 taps), Catmull-Rom 9-tap, 5-tap approximation "
               "or 16-tap",
               "shaders/taa/history_filter.glsl"});
  v.field("reject_offscreen", s.reject_offscreen,
          Meta{"reject history whose position falls outside the previous frame", "shaders/taa/validation.glsl"});
  v.field("depth_culling", s.depth_culling,
          Meta{"reject history whose previous depth differs from the expected one", "shaders/taa/validation.glsl"});
  v.field("depth_threshold", s.depth_threshold, Range<float>{0.0f, 10.0f},
          Meta{"relative linear-depth difference beyond which depth culling rejects", "shaders/taa/validation.glsl"});
  v.field("consistency", s.consistency,
          Meta{"geometric consistency per bilinear tap (depth, normal, mesh id); 2x2, then 3x3, else the "
               "current sample",
               "shaders/taa/consistency.glsl"});
  v.field("consistency_depth", s.consistency_depth, Range<float>{0.0f, 10.0f},
          Meta{"relative linear-depth tolerance of a consistent tap", "shaders/taa/consistency.glsl"});
  v.field("consistency_normal", s.consistency_normal, Range<float>{-1.0f, 1.0f},
          Meta{"minimum dot product of current and previous normals of a consistent tap",
               "shaders/taa/consistency.glsl"});
  v.field("anti_ghosting", s.anti_ghosting,
          Meta{"dynamic anti-ghosting: reject history where a mover moved at this pixel last frame and "
               "nothing moves in the 5-tap neighbourhood now",
               "shaders/taa/validation.glsl"});
  v.field("rejection_alpha", s.rejection_alpha, Range<float>{0.0f, 1.0f},
          Meta{"alpha where history is rejected (1 = the current sample)", "shaders/taa/blend_weight.glsl"});
  v.field("rectify", s.rectify,
          Meta{"history rectification against the 3x3 neighbourhood: none, clamp to the box, or clip "
               "toward its centre",
               "shaders/taa/rectify.glsl"});
  v.field("variance_clip", s.variance_clip,
          Meta{"use mean +- gamma * sigma of the neighbourhood as the box", "shaders/taa/neighborhood.glsl"});
  v.field("variance_gamma", s.variance_gamma, Range<float>{0.0f, 10.0f},
          Meta{"gamma of variance clipping", "shaders/taa/neighborhood.glsl"});
  v.field("shaped_neighborhood", s.shaped_neighborhood,
          Meta{"average the 3x3 box with the 5-tap cross box", "shaders/taa/neighborhood.glsl"});
  v.field("color_space", s.color_space, Meta{"space of the box and clipping: rgb or ycocg", "shaders/taa/color_space.glsl"});
  v.field("shrink_chroma", s.shrink_chroma,
          Meta{"YCoCg only: chroma extent of the box shrinks to a quarter of the luma extent around the "
               "current pixel's chroma",
               "shaders/taa/neighborhood.glsl"});
  v.field("luma_weight", s.luma_weight,
          Meta{"Lottes luma weighting: alpha from the luma difference of current and history, within "
               "[alpha_min, alpha_max]",
               "shaders/taa/blend_weight.glsl"});
  v.field("alpha_min", s.alpha_min, Range<float>{0.0f, 1.0f}, Meta{"smallest alpha of luma weighting", "shaders/taa/blend_weight.glsl"});
  v.field("alpha_max", s.alpha_max, Range<float>{0.0f, 1.0f}, Meta{"largest alpha of luma weighting", "shaders/taa/blend_weight.glsl"});
  v.field("velocity_alpha", s.velocity_alpha,
          Meta{"fast pixels trust the current frame: alpha rises to 1 at velocity_alpha_px of motion",
               "shaders/taa/blend_weight.glsl"});
  v.field("velocity_alpha_px", s.velocity_alpha_px, Range<float>{1e-3f, 1e6f},
          Meta{"speed (output pixels per frame) at which velocity_alpha reaches alpha 1", "shaders/taa/blend_weight.glsl"});
  v.field("reduce_blend_near_clamp", s.reduce_blend_near_clamp,
          Meta{"Karis anti-flicker: lower alpha (to half on the edge) as the history's luma nears the edge of the box",
               "shaders/taa/blend_weight.glsl"});
  v.field("velocity_in_alpha", s.velocity_in_alpha,
          Meta{"motion blur packs the per-pixel speed into colour alpha, so the resolve reads colour only "
               "for velocity_alpha (needs post.motion_blur, mode full, velocity_alpha and use_velocity off)",
               "shaders/motion_blur.comp"});
  v.field("history_format", s.history_format, Meta{"precision of the history buffer", "renderer/passes/taa_resolve.cpp"});
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
  bool trace_all = false;
};

template <class V>
void fields(V& v, AdaptiveSpec& s) {
  const char* seg = "shaders/adaptive_segmentation.comp";
  const char* trace = "shaders/adaptive_trace.comp";
  v.field("samples", s.samples, Range<int>{1, 16},
          Meta{"rays traced per marked pixel, at fixed sub-pixel positions of the Hammersley set (stratified "
               "in x and y; 1 = the pixel centre)",
               trace});
  v.field("threshold", s.threshold, Range<float>{0.0f, 1e6f},
          Meta{"a pixel is traced when the weighted sum of its derivative terms exceeds this", seg});
  v.field("weight_normal", s.weight_normal, Range<float>{0.0f, 1e6f},
          Meta{"weight of the normal term: (1 - cos) / 2 of the largest normal change to a 4-neighbour", seg});
  v.field("weight_depth", s.weight_depth, Range<float>{0.0f, 1e6f},
          Meta{"weight of the depth term: largest relative linear-depth change to a 4-neighbour (at most 1)", seg});
  v.field("weight_material", s.weight_material, Range<float>{0.0f, 1e6f},
          Meta{"weight of the material term: 1 where a 4-neighbour has another id (object, material or sky)", seg});
  v.field("weight_luminance", s.weight_luminance, Range<float>{0.0f, 1e6f},
          Meta{"weight of the luminance term: largest change of tonemapped luma to a 4-neighbour", seg});
  v.field("history_count", s.history_count, Range<int>{0, 255},
          Meta{"frames a pixel stays traced after its derivatives last marked it (0: no history count)", seg});
  v.field("fxaa_out_of_history", s.fxaa_out_of_history,
          Meta{"pixels without usable history (off screen, rejected, reset) that are not traced get FXAA",
               "shaders/fxaa.comp"});
  v.field("trace_disoccluded", s.trace_disoccluded,
          Meta{"pixels whose history was rejected on screen (disocclusion) are traced instead of FXAA'd", seg});
  v.field("ray_lod", s.ray_lod,
          Meta{"texture LOD from ray differentials (rays one pixel right and one down), matching the raster's "
               "mip selection; false samples mip 0",
               trace});
  v.field("trace_all", s.trace_all, Meta{"debug: trace every pixel", seg});
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
  v.field("edge_threshold", s.edge_threshold, Range<float>{0.0f, 1.0f},
          Meta{"smallest perceptual-luma difference (sqrt of Y/(1+Y)) that makes an edge; the seed "
               "recommends 1/32 .. 1",
               edges});
  v.field("non_dominant_edge_removal", s.non_dominant_edge_removal, Range<float>{0.0f, 8.0f},
          Meta{"an edge loses this many times the amount by which the strongest edge touching it "
               "is stronger, before the threshold test (0 keeps every edge over the threshold)",
               edges});
  v.field(
      "blurriness", s.blurriness, Range<float>{0.0f, 4.0f},
      Meta{"weight of the neighbours in the simple-shape blend of pixels with 2 to 4 edges (not "
           "edge detection)",
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
               "renderer/stereo.cpp"});
}

enum class Sharpen { None, Gradient, Cas };
TAA_ENUM_NAMES(Sharpen, {Sharpen::None, "none"}, {Sharpen::Gradient, "gradient"}, {Sharpen::Cas, "cas"})

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
  v.field("sharpen", s.sharpen,
          Meta{"after the resolve: none, a 5-tap gradient sharpener, or Contrast Adaptive Sharpening",
               "shaders/sharpen.comp"});
  v.field("sharpen_amount", s.sharpen_amount, Range<float>{0.0f, 1.0f},
          Meta{"sharpening strength: gradient adds amount x the 5-tap Laplacian / 4; cas moves the "
               "negative lobe from -1/8 (0) to -1/5 (1)",
               "shaders/sharpen.comp"});
  v.field("fxaa", s.fxaa, Meta{"FXAA on the output (alone, or after the resolve)", "shaders/fxaa.comp"});
  v.field("motion_blur", s.motion_blur,
          Meta{"blur along each pixel's own velocity before the resolve (centred box, depth-aware: "
               "nearer surfaces do not bleed into the blur)",
               "shaders/motion_blur.comp"});
  v.field("motion_blur_samples", s.motion_blur_samples, Range<int>{2, 64},
          Meta{"taps along the velocity vector", "shaders/motion_blur.comp"});
  v.field("motion_blur_scale", s.motion_blur_scale, Range<float>{0.0f, 4.0f},
          Meta{"fraction of the frame's motion covered by the blur (shutter)", "shaders/motion_blur.comp"});
}

enum class DebugOutput { None, Velocity, Rejection, ClampDistance, Segmentation };
TAA_ENUM_NAMES(DebugOutput, {DebugOutput::None, "none"}, {DebugOutput::Velocity, "velocity"},
               {DebugOutput::Rejection, "rejection"}, {DebugOutput::ClampDistance, "clamp_distance"},
               {DebugOutput::Segmentation, "segmentation"})

struct DebugSpec {
  DebugOutput output = DebugOutput::None;
  float scale = 1.0f;
};

template <class V>
void fields(V& v, DebugSpec& s) {
  v.field("output", s.output,
          Meta{"replace the output by a debug view: velocity (rg = v * scale / 2 + 0.5), rejection mask, "
               "clamp distance (times scale), segmentation (adaptive mode: yellow traced by derivatives, "
               "orange traced by history count, blue FXAA, grey the rest)",
               "shaders/taa_resolve.comp"});
  v.field("scale", s.scale, Range<float>{1e-6f, 1e6f}, Meta{"multiplier of the debug values", "shaders/taa_resolve.comp"});
}

}  // namespace taa::spec
