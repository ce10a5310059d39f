// Sub-pixel projection jitter (jitter.*). Offsets are in render-target pixels,
// x right and y down, and say where the image moves: a surface point that
// projects to pixel p without jitter projects to p + offset with it.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "spec/script_spec.h"

namespace taa::script {

// Radical inverse of `index` in `base`, in [0,1). The jitter uses indices
// 1..length and skips 0, whose radical inverse is 0 in every base and would put
// the first sample on the pixel corner for both axes. Exact: the numerator and
// denominator are integers, so there is a single rounding.
double halton(uint32_t index, uint32_t base);

// Number of distinct steps of the pattern (none: 1; manual: the point count, at
// least 1).
int jitterPatternLength(const spec::JitterSpec& jitter);

// Step used at `frame`: lock if >= 0, else frame / slowdown; modulo the length.
int jitterStep(const spec::JitterSpec& jitter, int frame);

// The pattern's offset at `step` (taken modulo the length), before rotate and scale:
//   none (0,0); halton (H2(step+1) - 0.5, H3(step+1) - 0.5);
//   uniform4 (-.25,-.25) (.25,-.25) (-.25,.25) (.25,.25);
//   symmetric2 (-.25,-.25) (.25,.25); legacy2 (0,0) (.5,.5); manual: points[step].
glm::dvec2 jitterPatternPoint(const spec::JitterSpec& jitter, int step);

// Offset at `frame`: the pattern point of jitterStep(), rotated by rotate_deg about
// the pixel centre (positive turns +x towards +y, i.e. clockwise on screen since y
// points down), then multiplied by scale.
glm::vec2 jitterOffset(const spec::JitterSpec& jitter, int frame);

// Moves the whole image by `offsetPx` pixels of a size.x x size.y target: adds
// 2*offset/size to NDC x and y, which is exact for any projection because it
// scales with clip w. For reversedZPerspective() (clip w = -z_view) that is
// proj[2][0] -= 2*jx/w and proj[2][1] -= 2*jy/h.
glm::mat4 applyJitter(const glm::mat4& projection, glm::vec2 offsetPx, glm::ivec2 size);

}  // namespace taa::script
