// Helpers of the effect tests (tests/effects/): cases built from a base plus a JSON merge
// patch, and error measures against the supersampled reference over whole frames or regions.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "api/frame_record.h"
#include "api/renderer.h"
#include "core/image.h"
#include "spec/case_spec.h"
#include "support/gpu.h"

namespace taa::test {

// `base` with `patch` merged into it (RFC 7386: objects merge key by key, anything else,
// arrays included, replaces), parsed and validated like a case file.
spec::CaseSpec effectCase(const std::string& base, const std::string& patch = "{}");

// A rendered case; frames[i] is frame i (images only where requested).
struct EffectRun {
  spec::CaseSpec spec;
  std::vector<FrameRecord> frames;
  const FrameRecord& operator[](int frame) const { return frames.at(size_t(frame)); }
};

// effectCase(base, patch) rendered with images for `withImages`, once per test process:
// tests that compare the same configuration share one render.
const EffectRun& renderOnce(const std::string& base, const std::string& patch,
                            const std::vector<int>& withImages, const RenderOptions& options = {});

// Prints a measured number, so a test run documents what its assertions compared.
void report(const std::string& what, double value);

// A buffer read back beside the output ("reference" names FrameRecord::reference).

// Which pixels a measure covers. Empty: every pixel.
using Mask = std::vector<bool>;
Mask fullMask(int width, int height);
// Pixels with x0 <= x < x1 and y0 <= y < y1.
Mask rectMask(int width, int height, int x0, int y0, int x1, int y1);
Mask maskWhere(int width, int height, const std::function<bool(int x, int y)>& pred);
Mask maskAnd(const Mask& a, const Mask& b);
Mask maskNot(const Mask& a);
// Grows (radius > 0) a mask by a square of `radius` pixels.
Mask dilate(const Mask& m, int width, int height, int radius);
int count(const Mask& m);
// Pixels showing a mover in a frame captured with ids ("material_id").
Mask moverMask(const FrameRecord& r);
// What a mover left behind by frame `to`: pixels it covered in any of frames [from, to) that
// are more than a pixel away from it in frame `to` (ids needed for all of them).
Mask vacatedMask(const EffectRun& run, int from, int to);
// Pixels within `radius` of a mover's silhouette in frame r (inside or outside).
Mask silhouetteMask(const FrameRecord& r, int radius);

// Root mean square of the RGB difference over the mask.
double rmse(const Image& a, const Image& b, const Mask& mask = {});
// Mean absolute RGB difference over the mask.
double meanAbs(const Image& a, const Image& b, const Mask& mask = {});
// Largest absolute RGB difference over the mask.
double maxAbs(const Image& a, const Image& b, const Mask& mask = {});
// Pixels of the mask whose largest RGB difference exceeds `tolerance`.
int differing(const Image& a, const Image& b, double tolerance = 0.0, const Mask& mask = {});

// Mean over the mask of the local contrast |p - mean of its 4 neighbours| (luma): a
// blurrier image of the same content has less of it.
double localContrast(const Image& img, const Mask& mask = {});
// Mean absolute RGB change between consecutive outputs over frames (first, last], over
// the mask: how much a pixel flickers.
double meanFlicker(const EffectRun& run, int first, int last, const Mask& mask = {});
// The same RGB values, bit for bit (alpha is not compared).
bool rgbIdentical(const Image& a, const Image& b);
// Every channel finite and at most `limit`.
bool allFiniteAtMost(const Image& img, float limit);

// `low` resampled bilinearly (pixel centres aligned, edges clamped) to width x height: what
// a plain upscale of a low-resolution frame gives, for temporal upsampling to beat.
Image bilinearUpscale(const Image& low, int width, int height);

}  // namespace taa::test
