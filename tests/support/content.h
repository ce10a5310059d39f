// Helpers for the tests of what glTF content looks like on screen (sidedness, samplers,
// material maps, instancing): one still frame, where a world point lands in it, and the
// adaptive tracer's image of every pixel beside the raster's.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "core/image.h"
#include "spec/case_spec.h"

namespace taa::test {

// A case of `members` (JSON object members, without braces) rendered as one frame with no
// jitter and no TAA, so each pixel is the raster's value at its centre.
spec::CaseSpec stillCase(const std::string& members, const std::string& name);
Image renderStill(const spec::CaseSpec& spec);

// The pixel (column, row) holding world point `p` in frame 0 of `spec`.
struct Pixel {
  int x = 0, y = 0;
};
Pixel pixelOf(const spec::CaseSpec& spec, const glm::vec3& p);

// The mean of channel c over the 3x3 pixels around `at`.
float meanAround(const Image& image, Pixel at, int c);

// Every pixel traced once through its centre (taa.mode adaptive, trace_all) and the
// raster's image of the same frame (the resolve's input).
struct TracedAndRaster {
  Image traced, raster;
};
TracedAndRaster traceEveryPixel(const std::string& members);

// Traced and raster agree to half-float rounding over the 5x5 pixels around (x, y).
void expectTracedMatchesRaster(const TracedAndRaster& r, int x, int y, const std::string& what);

}  // namespace taa::test
