// The neighbourhood box as history_bounded checks it, mirroring shaders/taa_resolve.comp and
// shaders/taa/neighborhood.glsl, plus the one way the stored output may legitimately sit
// outside it: negative RGB lifted to zero.
#pragma once

#include "core/image.h"

namespace taa::invariants::box {

struct Box {
  double lo[3];
  double hi[3];
};

// RGB -> working space (YCoCg as in color_space.glsl, or RGB unchanged).
void toWorking(const double rgb[3], bool ycocg, double w[3]);

// The min/max box of the 3x3 taps of `current` around (x, y), built as the resolve builds it:
// taps with a NaN channel are skipped, the others clamped to [0, 65504]; no valid tap gives
// the point 0. With shrinkChroma, the union with the shrunk chroma box (chroma +- an eighth
// of the luma extent around the centre), which may exceed the min/max chroma range.
// Shaped and variance boxes lie inside the min/max box, so they need no modelling.
Box neighbourhoodBox(const Image& current, int x, int y, bool ycocg, bool shrinkChroma);

// How far (max norm, working space) the colour lies outside the box; 0 inside.
double excess(const double rgb[3], const Box& b, bool ycocg);

// Where a YCoCg box holds colours with negative RGB, the stored output may be such a colour
// with negative channels raised:
//   ZeroChannels:     boundColor clamps the blend's negatives to 0 (tonemap weighting none),
//                     so only channels that are exactly 0 may have been raised;
//   NegativeChannels: Karis blends max(history, 0), so any channel the box lets go negative
//                     may sit above the blend (by at most how negative the box lets it go).
enum class Lift { ZeroChannels, NegativeChannels };

// The smallest excess over colours the output could have been before the lift.
double liftedExcess(const double rgb[3], const Box& b, Lift lift);

}  // namespace taa::invariants::box
