// The HLSL twin of variance_clip.comp: velocity reprojection and variance clipping (Salvi
// 2016), the history fetched where the pixel was last frame, clipped towards the
// neighbourhood mean into mean +- gamma * sigma, intersected with the min/max box. Written
// only against the installed taa_user.hlsli (docs/user-taa.md); ctest checks it renders
// what the GLSL one does.
#define TAA_USE_VELOCITY
#include "taa_user.hlsli"

[[vk::constant_id(0)]] const float alpha = 0.1;  // weight of the current frame
[[vk::constant_id(1)]] const float gamma = 1.0;  // box half-size in standard deviations

// Moves `history` along the line to `center` until it lies inside [lo, hi].
float3 clipToBox(float3 history, float3 center, float3 lo, float3 hi) {
  float3 d = history - center;
  float3 extent = max(hi - center, center - lo);
  float3 t = abs(d) / max(extent, float3(1e-6, 1e-6, 1e-6));
  float m = max(t.x, max(t.y, t.z));
  return m > 1.0 ? center + d / m : history;
}

// A NaN or infinite input sample would poison the history for good; count it as black.
float3 finiteColor(int2 p) {
  float3 c = taa_color_at(p);
  return any(isnan(c)) || any(isinf(c)) ? float3(0.0, 0.0, 0.0) : c;
}

TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  int2 rp = taa_render_pixel(p);
  float3 current = finiteColor(rp);
  if (!taa_has_history()) {
    taa_output[p] = float4(current, 1.0);
    return;
  }
  float3 lo = current, hi = current, m1 = float3(0.0, 0.0, 0.0), m2 = float3(0.0, 0.0, 0.0);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      float3 c = finiteColor(rp + int2(dx, dy));
      lo = min(lo, c);
      hi = max(hi, c);
      m1 += c;
      m2 += c * c;
    }
  float3 mean = m1 / 9.0;
  float3 sigma = sqrt(max(m2 / 9.0 - mean * mean, float3(0.0, 0.0, 0.0)));
  float3 boxLo = max(mean - gamma * sigma, lo), boxHi = min(mean + gamma * sigma, hi);

  // Velocity is in render pixels; the history lives at output size.
  float2 velocity = taa_velocity.Load(int3(rp, 0)).xy * taa_frame.outputSize.xy * taa_frame.renderSize.zw;
  float2 uv = (float2(p) + 0.5 - velocity) * taa_frame.outputSize.zw;
  bool offscreen = any(uv < float2(0.0, 0.0)) || any(uv > float2(1.0, 1.0));
  float3 history = taa_prev_output.SampleLevel(taa_linear_clamp, uv, 0).rgb;
  history = clipToBox(history, clamp(mean, lo, hi), boxLo, boxHi);
  // Clipping can leave rounding outside the min/max box; the declared bound is that box.
  history = clamp(history, lo, hi);
  float3 result = offscreen ? current : lerp(history, current, alpha);
  taa_output[p] = float4(result, 1.0);
}
