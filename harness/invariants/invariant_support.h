// Shared by the invariant files: their table row type, tonemapped luma, and the spec
// predicates several invariants use.
#pragma once

#include <cmath>
#include <initializer_list>
#include <memory>
#include <string>

#include "core/image.h"
#include "invariants/invariant.h"
#include "invariants/registry.h"
#include "spec/case_spec.h"

namespace taa::invariants {

// Rec. 709 luma of the per-channel Reinhard curve c / (1 + c), the mapping toDisplaySrgb
// applies before the sRGB transfer (c <= 0 -> 0, +Inf -> 1). It lies in [0, 1), so a few
// very bright pixels cannot dominate a mean. NaN stays NaN so that a defect fails the check
// that meets it instead of vanishing into an average.
inline float reinhardChannel(float c) {
  if (std::isnan(c)) return c;
  if (c <= 0.0f) return 0.0f;
  if (std::isinf(c)) return 1.0f;
  return c / (1.0f + c);
}

inline float tonemappedLuma(const Image& img, int x, int y) {
  return 0.2126f * reinhardChannel(img.at(x, y, 0)) + 0.7152f * reinhardChannel(img.at(x, y, 1)) +
         0.0722f * reinhardChannel(img.at(x, y, 2));
}

// Compact decimal for details ("0.00312").
std::string num(double value);

// "" when nothing in the scene or camera moves, else the setting that moves it
// (e.g. "camera.strafe.speed is 2"). glTF movers count when their animation plays.
std::string whatMoves(const spec::CaseSpec& spec);

// "" when the output keeps a temporal history (taa.mode basic or full), else why not.
std::string noHistoryReason(const std::string& name, const spec::CaseSpec& spec);

// "" when the output is an image of the scene at render size == output size, else the
// setting that breaks per-pixel correspondence with ids / velocity / current.
std::string renderSizeReason(const std::string& name, const spec::CaseSpec& spec);

// "" unless debug.output replaces the output by a debug view.
std::string debugViewReason(const std::string& name, const spec::CaseSpec& spec);

// "" when every frame gets the same sub-pixel jitter, else the setting that varies it.
std::string jitterVaries(const spec::CaseSpec& spec);
// The opposite: the setting that keeps the jitter constant, or "" when it varies.
std::string jitterConstant(const spec::CaseSpec& spec);

// Checks that an image the invariant needs is there and has the output's size; returns why
// not ("" when fine). `what` names it for the message.
std::string requireImage(const FrameView& f, const Image* img, const char* what, int minChannels);

struct RequiredCapture {
  Capture capture;
  int minChannels;
};
// The output with at least `outputChannels` channels, then each capture (named as in
// api/captures.h): the first of requireImage's errors, in order; empty when all are usable.
std::string requireCaptures(const FrameView& f, int outputChannels,
                            std::initializer_list<RequiredCapture> captures);

}  // namespace taa::invariants
