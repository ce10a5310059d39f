// Resolution, render path and what a run writes out.
#pragma once

#include <vector>

#include "spec/fields.h"

namespace taa::spec {

enum class RenderPath { Forward, Deferred };
TAA_ENUM_NAMES(RenderPath, {RenderPath::Forward, "forward"}, {RenderPath::Deferred, "deferred"})

struct ScaleKey {
  int frame = 0;
  float scale = 1.0f;
};

template <class V>
void fields(V& v, ScaleKey& s) {
  const char* impl = "renderer/script/frame_state.cpp";
  v.field("frame", s.frame, Range<int>{0, 99999}, Meta{"first frame rendered at this scale", impl});
  v.field("scale", s.scale, Range<float>{0.05f, 1.0f}, Meta{"render size / full render size", impl});
}

struct RenderSpec {
  int width = 320;  // output size; the scene renders at width / upsample
  int height = 180;
  float upsample = 1.0f;
  RenderPath path = RenderPath::Forward;
  int msaa = 1;  // samples per pixel of the raster pass: 1, 2, 4 or 8, as the device allows
  std::vector<ScaleKey> scale_schedule;
  bool lod0 = false;
  bool lod0_alpha_test = false;
};

template <class V>
void fields(V& v, RenderSpec& s) {
  v.field("width", s.width, Range<int>{1, 8192}, Meta{"output width in pixels", "renderer/frame/renderer.cpp"});
  v.field("height", s.height, Range<int>{1, 8192}, Meta{"output height in pixels", "renderer/frame/renderer.cpp"});
  v.field("upsample", s.upsample, Range<float>{1.0f, 8.0f},
          Meta{"temporal upsampling: the scene renders at output size / upsample",
               "shaders/taa/current_sample.glsl"});
  v.field("path", s.path, Meta{"forward shading in the raster pass, or a deferred lighting pass",
                               "shaders/deferred_lighting.comp"});
  v.field("msaa", s.msaa, Range<int>{1, 8},
          Meta{"MSAA samples per pixel in the raster pass (1, 2, 4 or 8; the device must offer "
               "the count): colour is resolved by averaging, depth and ids take sample 0, "
               "velocity and normals average",
               "renderer/passes/gbuffer.cpp"});
  v.list("scale_schedule", s.scale_schedule,
         Meta{"dynamic resolution: piecewise-constant render scale from each key's frame on",
              "renderer/script/frame_state.cpp"});
  v.field(
      "lod0", s.lod0,
      Meta{
          "LOD matching: every texture lookup samples mip 0 (raster, reference and tracer), as the "
          "seed's 'always use lod 0' matches a tracer without LOD approximation",
          "shaders/gbuffer.frag"});
  v.field(
      "lod0_alpha_test", s.lod0_alpha_test,
      Meta{
          "LOD matching: alpha-tested materials test the alpha of mip 0 (colour keeps its mip), in "
          "the raster, the shadow casters and the tracer",
          "shaders/gbuffer.frag"});
}

enum class AuxBuffer { Depth, Velocity, Normal, MaterialId };
TAA_ENUM_NAMES(AuxBuffer, {AuxBuffer::Depth, "depth"}, {AuxBuffer::Velocity, "velocity"},
               {AuxBuffer::Normal, "normal"}, {AuxBuffer::MaterialId, "material_id"})

struct OutputSpec {
  std::vector<int> frames;  // empty: the last frame
  std::vector<AuxBuffer> aux;
};

template <class V>
void fields(V& v, OutputSpec& s) {
  v.field("frames", s.frames, Range<int>{0, 99999},
          Meta{"frames written and checked against goldens; empty = the last frame", "renderer/frame/readback.cpp"});
  v.field("aux", s.aux, Meta{"auxiliary G-buffer images written beside each frame", "renderer/frame/readback.cpp"});
}

struct ReferenceSpec {
  int samples = 64;
};

template <class V>
void fields(V& v, ReferenceSpec& s) {
  v.field("samples", s.samples, Range<int>{1, 4096},
          Meta{"stratified sub-pixel samples averaged per pixel for the supersampled ground truth",
               "renderer/passes/reference.cpp"});
}

}  // namespace taa::spec
