// The work behind `taa-harness compare`: two image files in, the requested metrics and the bounds
// they violate out. Kept apart from the CLI so it is one function to test.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "compare/flip.h"
#include "core/errors.h"
#include "core/image.h"

namespace taa::compare {

// What `compare` reads (docs/trust.md): at most 2^25 pixels (8K UHD, 7680x4320, fits) and
// 2^27 samples an image, so the two images, FLIP's three-channel copies and its maps stay
// within the peak docs/trust.md gives.
inline constexpr uint64_t kMaxComparePixels = uint64_t(1) << 25;
inline constexpr uint64_t kMaxCompareSamples = uint64_t(1) << 27;

// A file that cannot be read or a pair that cannot be compared; what() names the file and the fix.
class CompareInputError : public InputError {
 public:
  using InputError::InputError;
};

struct Bound {
  std::string metric;
  bool isMax = true;  // fail when the value is above (isMax) or below (!isMax) `value`
  double value = 0.0;
};

struct CompareRequest {
  std::string referencePath;
  std::string testPath;
  std::vector<std::string> metrics;  // empty: every row of metricTable()
  FlipOptions flip;
  bool hdr = false;  // HDR-FLIP; needs linear inputs
  double pixelThreshold = 1.0 / 255.0;
  std::vector<Bound> bounds;  // bounded metrics are computed even when not listed in `metrics`
  bool wantHeatmap = false;   // compute FLIP for its map even when no FLIP metric is asked for
  std::string layer;          // EXR channels LAYER.R, .G, .B, .A; empty: R, G, B, A
};

struct CompareOutcome {
  int width = 0;
  int height = 0;
  std::vector<std::pair<std::string, double>> values;  // in metricTable() order
  std::vector<std::string> violations;                 // "flip_mean 0.0762 > 0.05"
  std::string flipKind;  // "ldr", "ldr-tonemapped", "hdr", or "" when FLIP was not computed
  Image flipMap;         // when FLIP was computed
  double startExposure = 0.0, stopExposure = 0.0;  // HDR-FLIP only
  int exposures = 0;
};

// A row of metricTable() (metric_table.h) by name, and every row's name in output order.
bool isMetricName(const std::string& name);
std::string metricNameList();  // "max_abs, mean_abs, ..."

// Reads both files (each file's kind by its content: OpenEXR is linear, PNG display-referred;
// EXR channels by name, readImageByName) and measures. Linear inputs get LDR-FLIP of their
// tonemapped display view (toDisplaySrgb, what the harness's PNGs show) or, with `hdr`,
// HDR-FLIP; display inputs get LDR-FLIP directly. Images whose channel counts differ are
// compared on their first three channels when both have at least three. Throws
// CompareInputError for unreadable files, a linear file against a display one, different
// sizes, or `hdr` with display inputs.
CompareOutcome compareFiles(const CompareRequest& request);

}  // namespace taa::compare
