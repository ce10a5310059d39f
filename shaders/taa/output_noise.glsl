// Seed 000's experimental output noise: a value in [-amount, amount], the same in every
// channel, from an integer hash of the output pixel and the frame index, so a frame's noise
// depends on nothing else (no state, no invocation order).
#ifndef TAA_OUTPUT_NOISE_GLSL
#define TAA_OUTPUT_NOISE_GLSL

// A 32-bit integer mix (xor-shift and odd multipliers): every input bit reaches every output
// bit, so neighbouring pixels and frames get unrelated values.
uint outputNoiseHash(uvec3 v) {
  uint h = v.x * 0x8da6b343u ^ v.y * 0xd8163841u ^ v.z * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

// Uniform in [-amount, amount): the hash's top 24 bits as a fraction of 2^24.
float outputNoise(ivec2 q, uint frame, float amount) {
  float u = float(outputNoiseHash(uvec3(uvec2(q), frame)) >> 8u) * (1.0 / 16777216.0);
  return (2.0 * u - 1.0) * amount;
}

#endif
