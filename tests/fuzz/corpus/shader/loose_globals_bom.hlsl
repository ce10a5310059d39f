#include "taa_user.hlsli"
[[vk::constant_id(100)]] const float k = 1.0;
[[vk::constant_id(2)]] const float motion_scale = 1.0;
float4 _FinalBlendParameters;
float _Sharpness;
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  taa_output[p] = float4(taa_color_at(p) * _Sharpness * k, 1.0) * _FinalBlendParameters;
}
