#version 450
// Averages the supersampled reference: each sub-pixel render of the frame is added
// to a float32 accumulator; the last one also divides by the sample count.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D colorTex;
layout(binding = 1, rgba32f) uniform image2D accum;
layout(push_constant) uniform Push {
  ivec2 size;
  uint mode;       // bit 0: add to the accumulator (not the first sample); bit 1: divide (last)
  float invCount;
  int offsetX;     // the eye's half of a side-by-side (stereo) accumulator
};

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  vec4 c = vec4(texelFetch(colorTex, p, 0).rgb, 1.0);
  ivec2 a = p + ivec2(offsetX, 0);
  vec4 sum = (mode & 1u) != 0u ? imageLoad(accum, a) + c : c;
  imageStore(accum, a, (mode & 2u) != 0u ? sum * invCount : sum);
}
