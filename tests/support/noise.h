// Deterministic test inputs from an integer hash: the same values on every machine and run,
// with no generator state to thread through.
#pragma once

#include <cstdint>

namespace taa::test {

// lowbias32 (Chris Wellons): a well-mixed 32-bit hash.
inline uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// A value in [0, 1) for (seed, x, y, c); 24 bits, so it is exact in float.
inline float hashUnit(uint32_t seed, int x, int y = 0, int c = 0) {
  const uint32_t key = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(c) * 83492791u;
  return float(hash32(seed ^ hash32(key)) >> 8) * (1.0f / 16777216.0f);
}

}  // namespace taa::test
