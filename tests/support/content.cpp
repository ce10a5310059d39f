#include "support/content.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "script/frame_state.h"
#include "script/projection.h"
#include "support/gpu.h"

namespace taa::test {

spec::CaseSpec stillCase(const std::string& members, const std::string& name) {
  return caseFromJson("{" + members + R"(,
      "jitter": {"pattern": "none"}, "taa": {"mode": "off"}, "script": {"frames": 1},
      "output": {"frames": [0]}})",
                      name);
}

Image renderStill(const spec::CaseSpec& spec) { return renderCase(spec)[0].color; }

Pixel pixelOf(const spec::CaseSpec& spec, const glm::vec3& p) {
  const auto s = script::frameState(spec, 0);
  const glm::dvec3 q = script::worldToPixel(s.camera.viewProjection, glm::dvec3(p), s.renderSize);
  return {int(std::floor(q.x)), int(std::floor(q.y))};
}

float meanAround(const Image& image, Pixel at, int c) {
  float sum = 0.0f;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) sum += image.at(at.x + dx, at.y + dy, c);
  return sum / 9.0f;
}

TracedAndRaster traceEveryPixel(const std::string& members) {
  const auto spec = caseFromJson("{" + members + R"(,
      "jitter": {"pattern": "none"}, "taa": {"mode": "adaptive"},
      "adaptive": {"trace_all": true, "samples": 1}, "script": {"frames": 1}})");
  RenderOptions o;
  o.captures |= {Capture::Current};
  const auto records = renderCaseWith(spec, o, {0});
  return {records.back().color, capturedImage(records.back(), Capture::Current)};
}

void expectTracedMatchesRaster(const TracedAndRaster& r, int x, int y, const std::string& what) {
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx)
      for (int c = 0; c < 3; ++c) {
        const float raster = r.raster.at(x + dx, y + dy, c);
        EXPECT_NEAR(r.traced.at(x + dx, y + dy, c), raster, 2e-3f * std::max(1.0f, raster))
            << what << " at (" << x + dx << ", " << y + dy << ") channel " << c;
      }
}

}  // namespace taa::test
