#include "taa_user.hlsli"
[numthreads(0, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  taa_output[p] = float4(taa_color_at(p), 1.0);
}
