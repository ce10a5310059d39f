// CPU reference of TSCMAA's edge detection (shaders/tscmaa_edges.comp with
// shaders/tscmaa/edge_rules.glsl), written to give the GPU's mask bit for bit: the
// same float expressions in the same order, no contraction.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"
#include "spec/taa_spec.h"

namespace taa::test {

// One display-encoded channel (Reinhard c / (1 + c), square root), as edgeColor.
float tscmaaEdgeChannel(float c);
// CMAA's 4-bit edge value between two encoded colours, as edgeValue.
int tscmaaEdgeValue(const float a[3], const float b[3], float threshold);
// CMAA's non-dominant removal on an owner's twelve values (the judged edge first).
bool tscmaaEdgeKept(const int values[12], float removal);
uint32_t tscmaaTaaHash(uint32_t x, uint32_t y);

// TSCMAA_EDGE_* and TSCMAA_TAA bits of every pixel (row-major) of one eye's colour;
// `offsetX` is the eye's offset in the side-by-side images (it feeds the TAA hash).
std::vector<uint32_t> tscmaaEdgeMask(const Image& color, const spec::TscmaaSpec& t,
                                     int offsetX = 0);

}  // namespace taa::test
