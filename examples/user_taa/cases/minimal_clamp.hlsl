// The HLSL twin of minimal_clamp.comp: blend the previous output at the same pixel (no
// reprojection) with the current colour, after clamping it to the current 3x3
// neighbourhood's min/max box. Written only against the installed taa_user.hlsli
// (docs/user-taa.md); ctest checks it renders what the GLSL one does.
#include "taa_user.hlsli"

// Weight of the current frame; 1 turns the resolve off.
[[vk::constant_id(0)]] const float alpha = 0.1;

TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  int2 rp = taa_render_pixel(p);
  float3 current = taa_color_at(rp);
  if (!taa_has_history()) {
    taa_output[p] = float4(current, 1.0);
    return;
  }
  float3 lo = current, hi = current;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      float3 c = taa_color_at(rp + int2(dx, dy));
      lo = min(lo, c);
      hi = max(hi, c);
    }
  float3 history = taa_prev_output.Load(int3(p, 0)).rgb;
  history = clamp(history, lo, hi);
  taa_output[p] = float4(lerp(history, current, alpha), 1.0);
}
