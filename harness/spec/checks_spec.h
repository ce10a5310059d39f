// What `taa-harness run` checks for a case: golden comparison with tolerances for
// other environments, and named invariants with their parameters. The harness's own part of
// the case format: the renderer never sees it (spec::CheckedCase in spec/checked_case.h adds
// it to the renderer's CaseSpec).
#pragma once

#include <string>
#include <vector>

#include "spec/fields.h"

namespace taa::spec {

// Defaults measured on lavapipe between CPU feature levels (x86-64-v4 against
// GALLIUM_OVERRIDE_CPU_CAPS=sse4.1): TAA's feedback turns low-bit differences into a
// few large single-pixel ones in high-frequency regions (max_abs 0.26, RMSE 0.0074,
// FLIP mean 0.0013, p99 0.013 on checkerboard_static), so single-pixel bounds are
// loose and the perceptual and aggregate ones carry the check.
struct ToleranceSpec {
  float max_abs = 1.0f;
  float rmse = 0.02f;
  float psnr_min = 30.0f;
  float pixel_threshold = 0.05f;
  float pixels_over = 0.02f;
  float flip_mean = 0.01f;
  float flip_p99 = 0.1f;
};

template <class V>
void fields(V& v, ToleranceSpec& s) {
  const char* impl = "harness/compare/tolerance.cpp";
  v.field("max_abs", s.max_abs, Range<float>{0.0f, 1e6f},
          Meta{"largest per-channel absolute error (linear)", impl});
  v.field("rmse", s.rmse, Range<float>{0.0f, 1e6f},
          Meta{"root-mean-square error over RGB (linear)", impl});
  v.field("psnr_min", s.psnr_min, Range<float>{-1000.0f, 1000.0f},
          Meta{"lowest PSNR in dB (peak 1.0; below 0 for HDR frames far above 1)", impl});
  v.field("pixel_threshold", s.pixel_threshold, Range<float>{0.0f, 1e6f},
          Meta{"per-pixel error above which a pixel counts as differing", impl});
  v.field("pixels_over", s.pixels_over, Range<float>{0.0f, 1.0f},
          Meta{"largest share of pixels over pixel_threshold", impl});
  v.field("flip_mean", s.flip_mean, Range<float>{0.0f, 1.0f},
          Meta{"largest mean LDR-FLIP error", impl});
  v.field("flip_p99", s.flip_p99, Range<float>{0.0f, 1.0f},
          Meta{"largest 99th percentile of LDR-FLIP", impl});
}

struct NoGhostingSpec {
  int frames = 8;
  float max_error = 0.06f;
};

template <class V>
void fields(V& v, NoGhostingSpec& s) {
  const char* impl = "harness/invariants/no_ghosting.cpp";
  v.field("frames", s.frames, Range<int>{1, 10000},
          Meta{"K: pixels a mover left K or more frames ago must match the reference", impl});
  v.field("max_error", s.max_error, Range<float>{0.0f, 1.0f},
          Meta{"largest mean tonemapped-luma error over those pixels", impl});
}

struct ConvergesSpec {
  float ratio = 0.6f;
};

template <class V>
void fields(V& v, ConvergesSpec& s) {
  v.field("ratio", s.ratio, Range<float>{0.0f, 1.0f},
          Meta{"the last frame's RMSE against the reference must be at most ratio times the first "
               "frame's",
               "harness/invariants/converges.cpp"});
}

struct StabilitySpec {
  float factor = 1.5f;
  float epsilon = 0.002f;
};

template <class V>
void fields(V& v, StabilitySpec& s) {
  const char* impl = "harness/invariants/temporal_stability.cpp";
  v.field(
      "factor", s.factor, Range<float>{0.0f, 1e3f},
      Meta{
          "frame-to-frame flicker of static pixels may be at most factor times the reference's own",
          impl});
  v.field("epsilon", s.epsilon, Range<float>{0.0f, 1.0f},
          Meta{"absolute slack added to the bound", impl});
}

struct EnergySpec {
  float epsilon = 0.02f;
};

template <class V>
void fields(V& v, EnergySpec& s) {
  v.field("epsilon", s.epsilon, Range<float>{0.0f, 10.0f},
          Meta{"largest relative difference of mean luminance from the reference",
               "harness/invariants/energy.cpp"});
}

struct BitStableSpec {
  int after_frame = 0;
};

template <class V>
void fields(V& v, BitStableSpec& s) {
  v.field("after_frame", s.after_frame, Range<int>{0, 100000},
          Meta{"from this frame on the output must not change at all",
               "harness/invariants/bit_stable.cpp"});
}

struct ChecksSpec {
  bool golden = true;
  ToleranceSpec tolerance;
  // Names from the invariant table (invariants/invariant_list.h); validation checks them.
  std::vector<std::string> invariants;
  int from_frame = 0;  // invariants look at frames from here on
  NoGhostingSpec no_ghosting;
  ConvergesSpec converges;
  StabilitySpec temporal_stability;
  EnergySpec energy;
  BitStableSpec bit_stable;
  std::vector<std::string> labels;
};

template <class V>
void fields(V& v, ChecksSpec& s) {
  v.field("golden", s.golden,
          Meta{"compare output.frames against goldens/NAME/", "harness/golden/golden_store.cpp"});
  v.object(
      "tolerance", s.tolerance,
      Meta{"thresholds used when the environment differs from the goldens' (otherwise bit-exact)",
           ""});
  v.field("invariants", s.invariants,
          Meta{"named checks run on the frame sequence", "harness/invariants/"});
  v.field(
      "from_frame", s.from_frame, Range<int>{0, 99999},
      Meta{"first frame the sequence invariants look at (skip warm-up); finite checks every frame",
           "harness/run/invariant_run.cpp"});
  v.object("no_ghosting", s.no_ghosting, Meta{"parameters of no_ghosting", ""});
  v.object("converges", s.converges, Meta{"parameters of converges", ""});
  v.object("temporal_stability", s.temporal_stability,
           Meta{"parameters of temporal_stability", ""});
  v.object("energy", s.energy, Meta{"parameters of energy", ""});
  v.object("bit_stable", s.bit_stable, Meta{"parameters of bit_stable", ""});
  v.field("labels", s.labels, Meta{"extra CTest labels (stress, slow)", "tests/CMakeLists.txt"});
}

}  // namespace taa::spec
