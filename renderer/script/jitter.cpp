#include "script/jitter.h"

#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>

namespace taa::script {

namespace {

using spec::JitterPattern;

constexpr glm::dvec2 kUniform4[] = {{-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}};
constexpr glm::dvec2 kSymmetric2[] = {{-0.25, -0.25}, {0.25, 0.25}};
constexpr glm::dvec2 kLegacy2[] = {{0.0, 0.0}, {0.5, 0.5}};

}  // namespace

double halton(uint32_t index, uint32_t base) {
  if (base < 2) return 0.0;
  // Digits reversed into an integer numerator over base^digits; 64 bits hold
  // every 32-bit index in any base >= 2.
  uint64_t numerator = 0, denominator = 1;
  for (uint64_t i = index; i > 0; i /= base) {
    numerator = numerator * base + i % base;
    denominator *= base;
  }
  return static_cast<double>(numerator) / static_cast<double>(denominator);
}

int jitterPatternLength(const spec::JitterSpec& jitter) {
  switch (jitter.pattern) {
    case JitterPattern::None:
      return 1;
    case JitterPattern::Halton:
      return std::max(1, jitter.length);
    case JitterPattern::Uniform4:
      return 4;
    case JitterPattern::Symmetric2:
    case JitterPattern::Legacy2:
      return 2;
    case JitterPattern::Manual:
      return std::max(1, static_cast<int>(jitter.points.size()));
  }
  return 1;
}

int jitterStep(const spec::JitterSpec& jitter, int frame) {
  const int raw = jitter.lock >= 0 ? jitter.lock : frame / std::max(1, jitter.slowdown);
  const int length = jitterPatternLength(jitter);
  return ((raw % length) + length) % length;
}

glm::dvec2 jitterPatternPoint(const spec::JitterSpec& jitter, int step) {
  const int length = jitterPatternLength(jitter);
  const int s = ((step % length) + length) % length;
  switch (jitter.pattern) {
    case JitterPattern::None:
      return {0.0, 0.0};
    case JitterPattern::Halton: {
      const auto index = static_cast<uint32_t>(s + 1);
      return {halton(index, 2) - 0.5, halton(index, 3) - 0.5};
    }
    case JitterPattern::Uniform4:
      return kUniform4[s];
    case JitterPattern::Symmetric2:
      return kSymmetric2[s];
    case JitterPattern::Legacy2:
      return kLegacy2[s];
    case JitterPattern::Manual:
      if (jitter.points.empty()) return {0.0, 0.0};
      return glm::dvec2(jitter.points[s]);
  }
  return {0.0, 0.0};
}

glm::vec2 jitterOffset(const spec::JitterSpec& jitter, int frame) {
  const glm::dvec2 p = jitterPatternPoint(jitter, jitterStep(jitter, frame));
  const double a = glm::radians(static_cast<double>(jitter.rotate_deg));
  const double c = std::cos(a), s = std::sin(a);
  const glm::dvec2 rotated(p.x * c - p.y * s, p.x * s + p.y * c);
  return glm::vec2(rotated * static_cast<double>(jitter.scale));
}

glm::mat4 applyJitter(const glm::mat4& projection, glm::vec2 offsetPx, glm::ivec2 size) {
  // ndc' = ndc + d  <=>  clip' = clip + d * clip.w: add d times the w row to the x
  // and y rows, for every column.
  const float dx = 2.0f * offsetPx.x / static_cast<float>(size.x);
  const float dy = 2.0f * offsetPx.y / static_cast<float>(size.y);
  glm::mat4 p = projection;
  for (int col = 0; col < 4; ++col) {
    p[col][0] += dx * projection[col][3];
    p[col][1] += dy * projection[col][3];
  }
  return p;
}

}  // namespace taa::script
