#include "support/cpu_resolve.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <iterator>
#include <stdexcept>
#include <string_view>

namespace taa::test::cpu {

namespace {

using glm::ivec2;
using glm::vec2;
using glm::vec3;

// GLSL's mix, by its definition x * (1 - a) + y * a (glm's own may use another form).
vec3 mix(vec3 x, vec3 y, float a) {
  return x * (1.0f - a) + y * a;
}
float mix(float x, float y, float a) {
  return x * (1.0f - a) + y * a;
}

vec3 texel(const Image& image, ivec2 p) {
  const int x = std::clamp(p.x, 0, image.width - 1), y = std::clamp(p.y, 0, image.height - 1);
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

vec2 sizeOf(const Image& image) {
  return {float(image.width), float(image.height)};
}
// The reciprocal size the uniforms carry (computed in float on the host).
vec2 invSizeOf(const Image& image) {
  return 1.0f / sizeOf(image);
}

void catmullRomWeights(vec2 f, vec2& w0, vec2& w1, vec2& w2, vec2& w3) {
  w0 = f * (-0.5f + f * (1.0f - 0.5f * f));
  w1 = 1.0f + f * f * (-2.5f + 1.5f * f);
  w2 = f * (0.5f + f * (2.0f - 1.5f * f));
  w3 = f * f * (-0.5f + 0.5f * f);
}

}  // namespace

float luma(vec3 rgb) {
  return glm::dot(rgb, vec3(0.2126f, 0.7152f, 0.0722f));
}

vec3 rgbToYCoCg(vec3 c) {
  return {0.25f * c.r + 0.5f * c.g + 0.25f * c.b, 0.5f * c.r - 0.5f * c.b,
          -0.25f * c.r + 0.5f * c.g - 0.25f * c.b};
}

vec3 yCoCgToRgb(vec3 c) {
  return {c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z};
}

// As the shader: inverse_luma and log run box, rectification and blend in their domain.
vec3 toDomain(vec3 c, spec::ToneWeight weighting) {
  if (weighting == spec::ToneWeight::InverseLuma) {
    c = glm::max(c, vec3(0.0f));
    return c / (1.0f + luma(c));
  }
  if (weighting == spec::ToneWeight::Log) return glm::log(1.0f + glm::max(c, vec3(0.0f)));
  return c;
}
vec3 fromDomain(vec3 d, spec::ToneWeight weighting) {
  if (weighting == spec::ToneWeight::InverseLuma) return d / std::max(1.0f - luma(d), 1.0f / kHalfMax);
  if (weighting == spec::ToneWeight::Log) return glm::exp(d) - 1.0f;
  return d;
}

vec3 toWorking(vec3 rgb, bool yCoCg, spec::ToneWeight weighting) {
  const vec3 d = toDomain(rgb, weighting);
  return yCoCg ? rgbToYCoCg(d) : d;
}
vec3 fromWorking(vec3 w, bool yCoCg, spec::ToneWeight weighting) {
  return fromDomain(yCoCg ? yCoCgToRgb(w) : w, weighting);
}
float workingLuma(vec3 w, bool yCoCg) {
  return yCoCg ? w.x : luma(w);
}

vec3 toneWeightedBlend(vec3 history, vec3 current, float alpha, spec::ToneWeight weighting) {
  if (weighting == spec::ToneWeight::None) return mix(history, current, alpha);
  // As the shader: the weighted blends see the non-negative part of a colour, since a YCoCg
  // box can hand back a history with luma <= -1.
  history = glm::max(history, vec3(0.0f));
  current = glm::max(current, vec3(0.0f));
  switch (weighting) {
    case spec::ToneWeight::Karis: {
      const float wc = alpha / (1.0f + luma(current));
      const float wh = (1.0f - alpha) / (1.0f + luma(history));
      return (current * wc + history * wh) / std::max(wc + wh, 1e-20f);
    }
    case spec::ToneWeight::InverseLuma:
    case spec::ToneWeight::Log:
      return fromDomain(mix(toDomain(history, weighting), toDomain(current, weighting), alpha), weighting);
    case spec::ToneWeight::None:
      break;
  }
  return mix(history, current, alpha);
}

vec3 boundColor(vec3 c) {
  for (int i = 0; i < 3; ++i) c[i] = std::isnan(c[i]) ? 0.0f : std::clamp(c[i], 0.0f, kHalfMax);
  return c;
}

vec3 bilinear(const Image& image, vec2 uv) {
  const vec2 p = uv * sizeOf(image) - 0.5f;
  const vec2 base = glm::floor(p);
  const vec2 f = p - base;
  const ivec2 i(base);
  const vec3 top = mix(texel(image, i), texel(image, i + ivec2(1, 0)), f.x);
  const vec3 bottom = mix(texel(image, i + ivec2(0, 1)), texel(image, i + ivec2(1, 1)), f.x);
  return mix(top, bottom, f.y);
}

vec3 historyBSpline(const Image& image, vec2 uv) {
  const vec2 size = sizeOf(image), inv = invSizeOf(image);
  const vec2 p = uv * size - 0.5f;
  const vec2 f = p - glm::floor(p);
  const vec2 base = glm::floor(p) + 0.5f;
  const vec2 f2 = f * f, f3 = f2 * f;
  const vec2 w0 = (1.0f - 3.0f * f + 3.0f * f2 - f3) / 6.0f;
  const vec2 w1 = (4.0f - 6.0f * f2 + 3.0f * f3) / 6.0f;
  const vec2 w2 = (1.0f + 3.0f * f + 3.0f * f2 - 3.0f * f3) / 6.0f;
  const vec2 w3 = f3 / 6.0f;
  const vec2 g0 = w0 + w1, g1 = w2 + w3;
  const vec2 p0 = (base - 1.0f + w1 / g0) * inv;
  const vec2 p1 = (base + 1.0f + w3 / g1) * inv;
  return g0.x * g0.y * bilinear(image, {p0.x, p0.y}) + g1.x * g0.y * bilinear(image, {p1.x, p0.y}) +
         g0.x * g1.y * bilinear(image, {p0.x, p1.y}) + g1.x * g1.y * bilinear(image, {p1.x, p1.y});
}

namespace {

// The shared layout of the 9- and 5-tap Catmull-Rom: positions of the outer taps and of the
// tap that reads the two middle texels of an axis at once, with their weights.
struct CatmullRomTaps {
  vec2 t0, t12, t3;
  vec2 w0, w12, w3;
};

CatmullRomTaps catmullRomTaps(const Image& image, vec2 uv) {
  const vec2 p = uv * sizeOf(image) - 0.5f;
  const vec2 base = glm::floor(p) + 0.5f;
  vec2 w0, w1, w2, w3;
  catmullRomWeights(p - glm::floor(p), w0, w1, w2, w3);
  const vec2 w12 = w1 + w2, inv = invSizeOf(image);
  return {(base - 1.0f) * inv, (base + w2 / w12) * inv, (base + 2.0f) * inv, w0, w12, w3};
}

}  // namespace

vec3 historyCatmullRom9(const Image& image, vec2 uv) {
  const CatmullRomTaps t = catmullRomTaps(image, uv);
  const float xs[3] = {t.t0.x, t.t12.x, t.t3.x}, ys[3] = {t.t0.y, t.t12.y, t.t3.y};
  const float wx[3] = {t.w0.x, t.w12.x, t.w3.x}, wy[3] = {t.w0.y, t.w12.y, t.w3.y};
  vec3 r(0.0f);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) r += bilinear(image, {xs[i], ys[j]}) * (wx[i] * wy[j]);
  return r;
}

vec3 historyCatmullRom5(const Image& image, vec2 uv) {
  const CatmullRomTaps t = catmullRomTaps(image, uv);
  const float c = t.w12.x * t.w12.y, l = t.w0.x * t.w12.y, r = t.w3.x * t.w12.y;
  const float u = t.w12.x * t.w0.y, d = t.w12.x * t.w3.y;
  const vec3 sum = bilinear(image, {t.t12.x, t.t12.y}) * c +
                   bilinear(image, {t.t0.x, t.t12.y}) * l + bilinear(image, {t.t3.x, t.t12.y}) * r +
                   bilinear(image, {t.t12.x, t.t0.y}) * u + bilinear(image, {t.t12.x, t.t3.y}) * d;
  return sum / (c + l + r + u + d);
}

vec3 historyCatmullRom16(const Image& image, vec2 uv) {
  const vec2 p = uv * sizeOf(image) - 0.5f;
  const ivec2 base(glm::floor(p));
  vec2 w[4];
  catmullRomWeights(p - glm::floor(p), w[0], w[1], w[2], w[3]);
  vec3 r(0.0f);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) r += texel(image, base + ivec2(i - 1, j - 1)) * (w[i].x * w[j].y);
  return r;
}

vec3 sampleHistory(const Image& image, vec2 uv, spec::HistoryFilter filter) {
  vec3 h;
  switch (filter) {
    case spec::HistoryFilter::BSpline:
      h = historyBSpline(image, uv);
      break;
    case spec::HistoryFilter::CatmullRom9:
      h = historyCatmullRom9(image, uv);
      break;
    case spec::HistoryFilter::CatmullRom5:
      h = historyCatmullRom5(image, uv);
      break;
    case spec::HistoryFilter::CatmullRom16:
      h = historyCatmullRom16(image, uv);
      break;
    case spec::HistoryFilter::Bilinear:
      h = bilinear(image, uv);
      break;
  }
  return glm::max(h, vec3(0.0f));
}

Box neighborhoodBox(const Neighborhood& n, vec3 center, const spec::TaaSpec& taa) {
  vec3 lo(1e30f), hi(-1e30f), sum(0.0f), sum2(0.0f);
  float count = 0.0f;
  for (int i = 0; i < 9; ++i) {
    if (!n.valid[i]) continue;
    lo = glm::min(lo, n.taps[i]);
    hi = glm::max(hi, n.taps[i]);
    sum += n.taps[i];
    sum2 += n.taps[i] * n.taps[i];
    count += 1.0f;
  }
  if (count == 0.0f) return {center, center, center};
  Box b{lo, hi, sum / count};
  if (taa.shaped_neighborhood) {
    vec3 crossLo = center, crossHi = center;
    for (int i = 1; i < 9; i += 2) {
      if (!n.valid[i]) continue;
      crossLo = glm::min(crossLo, n.taps[i]);
      crossHi = glm::max(crossHi, n.taps[i]);
    }
    b.lo = 0.5f * (lo + crossLo);
    b.hi = 0.5f * (hi + crossHi);
  }
  if (taa.variance_clip) {
    const vec3 sigma = glm::sqrt(glm::max(sum2 / count - b.mean * b.mean, vec3(0.0f)));
    b.lo = glm::max(b.lo, b.mean - taa.variance_gamma * sigma);
    b.hi = glm::min(b.hi, b.mean + taa.variance_gamma * sigma);
    b.hi = glm::max(b.hi, b.lo);
  }
  if (taa.color_space == spec::ColorSpace::YCoCg && taa.shrink_chroma) {
    const float chromaExtent = 0.125f * (b.hi.x - b.lo.x);
    b.lo.y = center.y - chromaExtent;
    b.lo.z = center.z - chromaExtent;
    b.hi.y = center.y + chromaExtent;
    b.hi.z = center.z + chromaExtent;
  }
  return b;
}

vec3 clampToBox(vec3 h, const Box& b) {
  return glm::min(glm::max(h, b.lo), b.hi);
}

vec3 clipToBox(vec3 h, const Box& b) {
  const vec3 center = 0.5f * (b.lo + b.hi);
  // As the shader: every channel widened by one half-float step of the largest bound.
  const vec3 bound = glm::max(glm::abs(b.lo), glm::abs(b.hi));
  const vec3 extent = 0.5f * (b.hi - b.lo) + std::max(bound.x, std::max(bound.y, bound.z)) * (1.0f / 1024.0f);
  const vec3 offset = h - center;
  const vec3 units = glm::abs(offset) / glm::max(extent, vec3(1e-7f));
  const float m = std::max(units.x, std::max(units.y, units.z));
  return m > 1.0f ? center + offset / m : h;
}

vec3 rectifyHistory(vec3 h, const Box& b, spec::Rectify rectify) {
  if (rectify == spec::Rectify::Clamp) return clampToBox(h, b);
  if (rectify == spec::Rectify::Clip) return clipToBox(h, b);
  return h;
}

float lottesAlpha(float lumaCurrent, float lumaHistory, float alphaMin, float alphaMax) {
  const float diff =
      std::abs(lumaCurrent - lumaHistory) / std::max(std::max(lumaCurrent, lumaHistory), 0.2f);
  const float similarity = 1.0f - std::clamp(diff, 0.0f, 1.0f);
  return mix(alphaMax, alphaMin, similarity * similarity);
}

float reduceBlendNearClamp(float alpha, float lumaHistory, float lo, float hi) {
  const float halfExtent = 0.5f * (hi - lo);
  const float t =
      halfExtent > 1e-7f
          ? std::clamp(std::min(lumaHistory - lo, hi - lumaHistory) / halfExtent, 0.0f, 1.0f)
          : 0.0f;
  return alpha * (0.5f + 0.5f * t);
}

float velocityAlpha(float alpha, float speedPx, float fullSpeedPx) {
  return mix(alpha, 1.0f, std::clamp(speedPx / fullSpeedPx, 0.0f, 1.0f));
}

namespace {

void requireMirrored(const CpuResolveInputs& in, const spec::TaaSpec& taa) {
  auto refuse = [](const char* what) {
    throw std::invalid_argument(std::string("cpuResolve does not mirror ") + what);
  };
  if (taa.mode != spec::TaaMode::Full) refuse("modes other than full");
  if (taa.use_velocity != spec::UseVelocity::All) refuse("use_velocity other than all");
  if (taa.velocity_sampling != spec::VelocitySampling::Pixel) refuse("3x3 velocity sampling");
  // Any other declared setting (common/taa_settings.h) the mirror does not implement must keep
  // its default, so a new technique is refused here rather than silently left out.
  static constexpr std::string_view kMirrored[] = {
      "alpha",          "tonemap_weighting", "use_velocity",  "velocity_sampling",
      "history_filter", "reject_offscreen",  "rejection_alpha", "rectify",
      "variance_clip",  "variance_gamma",    "shaped_neighborhood", "color_space",
      "shrink_chroma",  "luma_weight",       "alpha_min",     "alpha_max",
      "velocity_alpha", "velocity_alpha_px", "reduce_blend_near_clamp", "history_format"};
  const spec::TaaSpec defaults;
  auto check = [&](const char* key, bool isDefault) {
    const auto* end = std::end(kMirrored);
    if (!isDefault && std::find(std::begin(kMirrored), end, key) == end) refuse(key);
  };
#define CPU_MIRROR_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  check(#key, taa.key == defaults.key);
#define CPU_MIRROR_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  check(#key, taa.key == defaults.key);
#define CPU_MIRROR_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  check(#key, taa.key == defaults.key);
  TAA_SETTINGS(CPU_MIRROR_E, CPU_MIRROR_B, CPU_MIRROR_F)
#undef CPU_MIRROR_E
#undef CPU_MIRROR_B
#undef CPU_MIRROR_F
  if (in.current.width != in.history.width || in.current.height != in.history.height)
    refuse("upsampling (history and current sizes differ)");
  if (in.current.channels < 3 || in.history.channels < 3)
    refuse("images with fewer than 3 channels");
}

}  // namespace

Image cpuResolve(const CpuResolveInputs& in, const spec::TaaSpec& taa) {
  requireMirrored(in, taa);
  // As the shader: without rectification there is no box, so no YCoCg round trip.
  const bool yCoCg =
      taa.color_space == spec::ColorSpace::YCoCg && taa.rectify != spec::Rectify::None;
  const Image& color = in.current;
  const vec2 size = sizeOf(color), inv = invSizeOf(color);
  const ivec2 hi(color.width - 1, color.height - 1);
  Image out(color.width, color.height, 4, 1.0f);
  for (int y = 0; y < color.height; ++y)
    for (int x = 0; x < color.width; ++x) {
      const ivec2 q(x, y);
      const vec2 uv = (vec2(q) + 0.5f) * inv;
      Neighborhood n;
      vec3 finiteSum(0.0f), centre(0.0f);
      float finiteCount = 0.0f;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
          const int k = (j + 1) * 3 + (i + 1);
          vec3 c = texel(color, glm::clamp(q + ivec2(i, j), ivec2(0), hi));
          n.valid[k] = !(std::isnan(c.x) || std::isnan(c.y) || std::isnan(c.z));
          for (int ch = 0; ch < 3; ++ch)
            c[ch] = std::isnan(c[ch]) ? 0.0f : std::clamp(c[ch], 0.0f, kHalfMax);
          n.taps[k] = toWorking(c, yCoCg, taa.tonemap_weighting);
          if (k == 4) centre = c;
          if (n.valid[k]) {
            finiteSum += c;
            finiteCount += 1.0f;
          }
        }
      const vec3 current = n.valid[4] ? centre
                                      : (finiteCount > 0.0f ? finiteSum / finiteCount : vec3(0.0f));

      // reprojectVelocity: the velocity is in render pixels; render size == output size here.
      vec2 prevUv = uv - in.velocityPx * inv;
      const vec2 motionPx = in.velocityPx * size * inv;
      const bool rejected = taa.reject_offscreen && (prevUv.x < 0.0f || prevUv.y < 0.0f ||
                                                     prevUv.x > 1.0f || prevUv.y > 1.0f);
      prevUv = glm::clamp(prevUv, vec2(0.0f), vec2(1.0f));

      const vec3 history = sampleHistory(in.history, prevUv, taa.history_filter);
      const vec3 wHistory = toWorking(history, yCoCg, taa.tonemap_weighting);
      const Box box = neighborhoodBox(n, toWorking(current, yCoCg, taa.tonemap_weighting), taa);
      const vec3 wRectified = rectifyHistory(wHistory, box, taa.rectify);

      float alpha = taa.alpha;
      if (taa.luma_weight)
        alpha = lottesAlpha(luma(current), luma(fromWorking(wRectified, yCoCg, taa.tonemap_weighting)), taa.alpha_min,
                            taa.alpha_max);
      if (taa.reduce_blend_near_clamp)
        alpha = reduceBlendNearClamp(alpha, workingLuma(wHistory, yCoCg),
                                     workingLuma(box.lo, yCoCg), workingLuma(box.hi, yCoCg));
      if (taa.velocity_alpha)
        alpha = velocityAlpha(alpha, glm::length(motionPx), taa.velocity_alpha_px);
      if (rejected) alpha = taa.rejection_alpha;

      const vec3 result = boundColor(
          toneWeightedBlend(fromWorking(wRectified, yCoCg, taa.tonemap_weighting), current, alpha, taa.tonemap_weighting));
      for (int ch = 0; ch < 3; ++ch) out.at(x, y, ch) = result[ch];
    }
  return out;
}

}  // namespace taa::test::cpu
