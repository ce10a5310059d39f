// Float cube root, log2, exp2 and pow for the fast FLIP, written with plain arithmetic and bit
// operations so that the compiler vectorizes the loops that call them (libm's cbrtf and powf are
// function calls it cannot). Each is accurate to a few float ulps on the range FLIP feeds it, and
// gives the same bits scalar or vectorized, so results do not depend on how a loop was compiled.
#pragma once

#include <bit>
#include <cstdint>

namespace taa::compare::flipmath {

// Cube root of x > 0 (x normal). A bit-level first guess (the exponent divided by three, through
// float so it vectorizes), then two Halley steps y *= (y^3 + 2x) / (2y^3 + x), each of which
// cubes the relative error: ~3% -> ~1e-5 -> float rounding.
inline float cbrtPositive(float x) {
  const float bits = float(std::bit_cast<int32_t>(x));
  float y = std::bit_cast<float>(int32_t(bits * (1.0f / 3.0f)) + 709921077);
  for (int i = 0; i < 2; ++i) {
    const float y3 = y * y * y;
    y = y * (y3 + 2.0f * x) / (2.0f * y3 + x);
  }
  return y;
}

// log2 of x > 0 (x normal): x = m * 2^e with m in [sqrt(1/2), sqrt(2)), then
// ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172, by its odd series to s^9 (the next term
// is below 4e-10).
inline float log2Positive(float x) {
  const int32_t bits = std::bit_cast<int32_t>(x);
  // Shift the split point from m = 1 to m = sqrt(1/2) (0x3f3504f3) so m stays near 1.
  const int32_t shifted = bits - 0x3f3504f3;
  const int32_t e = shifted >> 23;
  const float m = std::bit_cast<float>(bits - (e << 23));
  const float s = (m - 1.0f) / (m + 1.0f);
  const float s2 = s * s;
  const float series =
      s *
      (2.0f + s2 * (2.0f / 3.0f + s2 * (2.0f / 5.0f + s2 * (2.0f / 7.0f + s2 * (2.0f / 9.0f)))));
  return float(e) + series * 1.44269504088896341f;  // ln -> log2
}

// 2^y for y in [-126, 127]: y = n + f with n = round(y), |f| <= 1/2, 2^f = e^(f ln 2) by its
// Taylor series to degree 8 (|f ln 2| <= 0.347; the next term is below 1e-9), scaled by 2^n
// through the exponent bits.
inline float exp2Bounded(float y) {
  const float n = float(int32_t(y + (y >= 0.0f ? 0.5f : -0.5f)));
  const float t = (y - n) * 0.693147180559945309f;
  float p = 1.0f / 40320.0f;
  p = p * t + 1.0f / 5040.0f;
  p = p * t + 1.0f / 720.0f;
  p = p * t + 1.0f / 120.0f;
  p = p * t + 1.0f / 24.0f;
  p = p * t + 1.0f / 6.0f;
  p = p * t + 0.5f;
  p = p * t + 1.0f;
  p = p * t + 1.0f;
  return p * std::bit_cast<float>((int32_t(n) + 127) << 23);
}

// x^e for x > 0 (normal) with |e * log2(x)| <= 126, exp2Bounded's range. FLIP's powers stay far
// inside it: the sRGB decode (e = 2.4, x >= 0.05), HyAB^0.7 and dC^(1 - dF) with x >= FLT_MIN.
// The relative error is about (5 + |e log2 x|) * 1e-7: y = e log2 x is rounded to float once.
inline float powPositive(float x, float e) {
  return exp2Bounded(e * log2Positive(x));
}

}  // namespace taa::compare::flipmath
