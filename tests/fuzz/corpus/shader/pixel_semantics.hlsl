#include "taa_user.hlsli"
TAA_NUMTHREADS
float4 main(uint3 id : SV_DispatchThreadID, float4 pos : SV_Position, float4 q : SV_Bogus, uint n) : SV_Target {
  int2 p;
  if (!taa_pixel(id, p)) return 0;
  if (n > 2) discard;
  taa_output[p] = float4(taa_color_at(p), 1.0) + pos + q;
  return 1;
}
