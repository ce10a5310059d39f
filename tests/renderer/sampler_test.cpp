// glTF samplers on the raster and in the tracer (cases/scenes/samplers.gltf, unlit, so a
// pixel is the texel it samples): wrapS and wrapT each on its own axis, mirrored repeat,
// NEAREST and LINEAR magnification, and a minFilter without mipmaps. Before issue 25 a
// texture clamped only when both axes clamped, mirrored repeat repeated, and every texture
// was sampled trilinearly: each expectation below then fails.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "support/content.h"
#include "support/gpu.h"

namespace taa {
namespace {

// The three tiled quads: centres x -1.2, 0, 1.2 at y 1.2, 1 x 1, UVs -1 to 2 on both axes
// (v grows downwards) over a 4x4 texture; then the minified quads at (-0.5, 0.35) and
// (0.5, 0.35), 0.4 x 0.4.
enum Quad { kClampSRepeatT, kMirror, kLinear };
constexpr float kTiledX[3] = {-1.2f, 0.0f, 1.2f};

const char* kMembers = R"("scene": {"gltf": "scenes/samplers.gltf"},
    "render": {"width": 640, "height": 360},
    "camera": {"position": [0, 0.85, 3.0], "target": [0, 0.85, 0]})";

const spec::CaseSpec& samplerCase() {
  static const spec::CaseSpec spec = test::stillCase(kMembers, "samplers");
  return spec;
}

test::Pixel uvPixel(Quad q, float u, float v) {
  return test::pixelOf(samplerCase(),
                       {kTiledX[q] - 0.5f + (u + 1.0f) / 3.0f, 1.7f - (v + 1.0f) / 3.0f, 0.0f});
}

struct Colour {
  float c[3];
};
Colour at(const Image& im, Quad q, float u, float v) {
  const test::Pixel p = uvPixel(q, u, v);
  return {{im.at(p.x, p.y, 0), im.at(p.x, p.y, 1), im.at(p.x, p.y, 2)}};
}

float difference(const Colour& a, const Colour& b) {
  float d = 0.0f;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.c[c] - b.c[c]));
  return d;
}

// Half-float storage of one texel's colour: exact to 2^-11 relative.
constexpr float kSame = 2e-3f;

void expectWrapsAndFilters(const Image& im, const std::string& what) {
  // Texel centres are at u, v = 0.125 + k / 4; row 1 (v 0.375) throughout.
  const Colour col0 = at(im, kClampSRepeatT, 0.125f, 0.375f), col1 = at(im, kClampSRepeatT, 0.375f, 0.375f),
               col3 = at(im, kClampSRepeatT, 0.875f, 0.375f);
  EXPECT_GT(difference(col1, col3), 0.05f) << what << ": the texels differ";
  EXPECT_LT(difference(at(im, kClampSRepeatT, 1.375f, 0.375f), col3), kSame)
      << what << ": past u = 1 wrapS CLAMP_TO_EDGE keeps the last column (repeat: column 1)";
  EXPECT_LT(difference(at(im, kClampSRepeatT, -0.625f, 0.375f), col0), kSame)
      << what << ": below u = 0 it keeps the first column";
  EXPECT_LT(difference(at(im, kClampSRepeatT, 0.375f, 1.375f), col1), kSame)
      << what << ": wrapT REPEAT repeats along v on the same texture";
  EXPECT_LT(difference(at(im, kClampSRepeatT, 0.375f, -0.625f), col1), kSame) << what;

  const Colour m1 = at(im, kMirror, 0.375f, 0.375f), m2 = at(im, kMirror, 0.625f, 0.375f);
  EXPECT_LT(difference(at(im, kMirror, 1.375f, 0.375f), m2), kSame)
      << what << ": MIRRORED_REPEAT reflects u = 1.375 onto 0.625 (repeat: 0.375)";
  EXPECT_GT(difference(m1, m2), 0.05f) << what;
  EXPECT_LT(difference(at(im, kMirror, -0.375f, 0.375f), m1), kSame)
      << what << ": and u = -0.375 onto 0.375";
  EXPECT_LT(difference(at(im, kMirror, 0.375f, -0.375f), m1), kSame) << what << ": along v too";
  EXPECT_LT(difference(at(im, kMirror, 0.375f, 1.375f), at(im, kMirror, 0.375f, 0.625f)), kSame)
      << what;
  EXPECT_LT(difference(at(im, kMirror, 0.44f, 0.375f), m1), kSame)
      << what << ": magFilter NEAREST keeps a texel's colour up to its edge";

  // LINEAR halfway between columns 1 and 2: strictly between their colours.
  const Colour l1 = at(im, kLinear, 0.375f, 0.375f), l2 = at(im, kLinear, 0.625f, 0.375f),
               mid = at(im, kLinear, 0.5f, 0.375f);
  for (const int c : {0, 2}) {  // red and blue differ between the two columns
    const float lo = std::min(l1.c[c], l2.c[c]), hi = std::max(l1.c[c], l2.c[c]);
    EXPECT_GT(mid.c[c], lo + 0.2f * (hi - lo)) << what << ": magFilter LINEAR blends, channel " << c;
    EXPECT_LT(mid.c[c], hi - 0.2f * (hi - lo)) << what << ": channel " << c;
  }
}

// The share of a minified quad's pixels that show a single texel, black or white, and the
// spread of their luminance.
struct Minified {
  double pure = 0.0, stddev = 0.0;
};
Minified minified(const Image& im, float x) {
  const test::Pixel a = test::pixelOf(samplerCase(), {x - 0.15f, 0.5f, 0.0f}),
                    b = test::pixelOf(samplerCase(), {x + 0.15f, 0.2f, 0.0f});
  double n = 0, pure = 0, sum = 0, sum2 = 0;
  for (int y = a.y; y <= b.y; ++y)
    for (int px = a.x; px <= b.x; ++px) {
      const double l = im.at(px, y, 1);
      pure += (l < 1e-3 || l > 1.0 - 2e-3) ? 1 : 0;
      sum += l;
      sum2 += l * l;
      ++n;
    }
  return {pure / n, std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)))};
}

TEST(Samplers, TheLoaderKeepsEachAxisAndFilter) {
  scene::Scene s;
  scene::loadGltf(std::filesystem::path(TAA_SOURCE_DIR) / "cases/scenes/samplers.gltf", s);
  ASSERT_EQ(s.textures.size(), 5u);
  using scene::Filter, scene::MipFilter, scene::Wrap;
  const scene::TextureSampler& clamp = s.textures[0].sampler;
  EXPECT_EQ(clamp.wrapS, Wrap::ClampToEdge);
  EXPECT_EQ(clamp.wrapT, Wrap::Repeat);
  EXPECT_EQ(clamp.mag, Filter::Nearest);
  EXPECT_EQ(clamp.mip, MipFilter::None);
  EXPECT_EQ(s.textures[1].sampler.wrapS, Wrap::MirroredRepeat);
  EXPECT_EQ(s.textures[1].sampler.wrapT, Wrap::MirroredRepeat);
  EXPECT_EQ(s.textures[2].sampler.mag, Filter::Linear);
  EXPECT_EQ(s.textures[2].sampler.mip, MipFilter::Linear);
  EXPECT_EQ(s.textures[3].sampler.min, Filter::Nearest);
  EXPECT_EQ(s.textures[3].sampler.mag, Filter::Linear);
  EXPECT_EQ(s.textures[3].sampler.mip, MipFilter::None);
  EXPECT_NE(s.textures[0].sampler.key(), s.textures[1].sampler.key());
}

TEST(Samplers, RasterHonoursWrapPerAxisMirrorAndFilters) {
  const Image im = test::renderStill(samplerCase());
  expectWrapsAndFilters(im, "raster");
  const Minified nearest = minified(im, -0.5f), mipmapped = minified(im, 0.5f);
  EXPECT_GT(nearest.pure, 0.95) << "minFilter NEAREST without mipmaps: each pixel one texel";
  EXPECT_GT(nearest.stddev, 0.3) << "and the checker aliases";
  EXPECT_LT(mipmapped.pure, 0.05);
  EXPECT_LT(mipmapped.stddev, 0.15) << "LINEAR_MIPMAP_LINEAR: mostly the mips' even grey";
}

TEST(Samplers, TheTracerSamplesAsTheRaster) {
  const test::TracedAndRaster r = test::traceEveryPixel(kMembers);
  expectWrapsAndFilters(r.traced, "traced");
  for (const auto& [q, u, v] : {std::tuple{kClampSRepeatT, 1.375f, 0.375f},
                                std::tuple{kMirror, 1.375f, 0.375f},
                                std::tuple{kLinear, 0.5f, 0.375f}}) {
    const test::Pixel p = uvPixel(q, u, v);
    test::expectTracedMatchesRaster(r, p.x, p.y, "quad " + std::to_string(int(q)));
  }
}

}  // namespace
}  // namespace taa
