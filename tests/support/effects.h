// Helpers of the effect tests (tests/effects/): cases built from a base plus a JSON merge
// patch, and error measures against the supersampled reference over whole frames or regions.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/image.h"
#include "frame_record.h"
#include "spec/case_spec.h"

namespace taa::test {

// `base` with `patch` merged into it (RFC 7386: objects merge key by key, anything else,
// arrays included, replaces), parsed and validated like a case file.
spec::CaseSpec effectCase(const std::string& base, const std::string& patch = "{}");

// A buffer read back beside the output ("reference" names FrameRecord::reference).
const Image& auxImage(const FrameRecord& r, const std::string& name);

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

// Root mean square of the RGB difference over the mask.
double rmse(const Image& a, const Image& b, const Mask& mask = {});
// Mean absolute RGB difference over the mask.
double meanAbs(const Image& a, const Image& b, const Mask& mask = {});
// Largest absolute RGB difference over the mask.
double maxAbs(const Image& a, const Image& b, const Mask& mask = {});
// Pixels of the mask whose largest RGB difference exceeds `tolerance`.
int differing(const Image& a, const Image& b, double tolerance = 0.0, const Mask& mask = {});
// Every RGBA value identical, bit for bit (NaNs compare by bits too).
bool bitIdentical(const Image& a, const Image& b);

// Mean over the mask of the local contrast |p - mean of its 4 neighbours| (luma): a
// blurrier image of the same content has less of it.
double localContrast(const Image& img, const Mask& mask = {});
// Every channel finite and at most `limit`.
bool allFiniteAtMost(const Image& img, float limit);

// `low` resampled bilinearly (pixel centres aligned, edges clamped) to width x height: what
// a plain upscale of a low-resolution frame gives, for temporal upsampling to beat.
Image bilinearUpscale(const Image& low, int width, int height);

}  // namespace taa::test
