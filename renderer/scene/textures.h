// CPU texture work: sRGB-correct mip chains and procedural textures. Everything
// here is a pure function of its arguments (integer hashing, no rand, no clock),
// so two runs produce byte-identical texels.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace taa::scene {

using Rgba8 = std::array<uint8_t, 4>;

// sRGB transfer functions on [0, 1] (IEC 61966-2-1).
double srgbToLinear(double encoded);
double linearToSrgb(double linear);
// The linear value of an 8-bit sRGB code, from a table (exact for all 256 codes).
double srgb8ToLinear(uint8_t code);
uint8_t linearToSrgb8(double linear);

// Integer hashes (lowbias32 by Chris Wellons): well mixed and identical on every platform.
uint32_t hash32(uint32_t x);
uint32_t hash3(uint32_t x, uint32_t y, uint32_t seed);
// Uniform in [0, 1) from the top 24 bits of a hash.
float hashUnit(uint32_t h);

// Replaces levels[1..] with a chain computed from levels[0] down to 1x1. Colour is
// averaged in linear light and re-encoded; alpha (and every channel of a `linear`
// texture, such as a normal map) is averaged as stored. A level of
// odd size is reduced by an area-weighted box over each destination texel's
// footprint (1.5 source texels wide when 3 -> 1 etc.), which is exactly the 2x2 box
// for even sizes and never drops a source row or column.
void generateMips(Texture& texture);

// A texture with one level taken from `rgba` (width * height * 4 bytes) plus its mips.
Texture makeTexture(int width, int height, std::vector<uint8_t> rgba,
                    TextureSampler sampler = {}, bool linear = false);

// Whether any texel of level 0 has alpha below 255.
bool hasTranslucentTexels(const Texture& texture);

// Procedural textures. `size` is the width and height in texels.
// Hard-edged two-colour checker with `cells` squares per side.
Texture checkerTexture(int size, int cells, Rgba8 a, Rgba8 b);
// A sprig of leaves on a stem: alpha 255 inside a leaf or the stem, 0 elsewhere. The
// transparent texels carry the mean leaf colour so that mips do not darken the edges.
Texture leafTexture(int size, uint32_t seed);
// Rough stone: per-texel white noise over two octaves of value noise with sparse
// bright sparkles, a deliberately high local colour variance for TAA clamping tests.
Texture roughNoiseTexture(int size, uint32_t seed);
// Low-contrast ground (grass, dirt): value noise between two colours.
Texture groundTexture(int size, uint32_t seed, Rgba8 dark, Rgba8 bright);
// Painted wooden slat: faint grain along v.
Texture woodTexture(int size, uint32_t seed);

}  // namespace taa::scene
