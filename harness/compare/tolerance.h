// Comparing a frame with its golden when the environment differs: every metric the
// case's tolerances bound, and the violated bounds as readable lines.
#pragma once

#include <string>
#include <vector>

#include "core/image.h"
#include "run/results.h"
#include "spec/checks_spec.h"

namespace taa::compare {

struct Measured {
  run::ImageMetrics metrics;
  Image errorMap;  // FLIP error per pixel, for the heatmap and the worst region
};

// What the report's PNG of a linear HDR frame holds (toDisplaySrgb, rounded to 8 bits as
// writePng does), as 3-channel floats k / 255.
Image displayedPng(const Image& hdr);

// Linear metrics on RGB (PSNR with a fixed peak of 1.0) with `pixelThreshold` as the
// per-pixel "over" bound; LDR-FLIP on exactly the 8-bit PNGs the report shows (displayedPng).
Measured measureAgainstGolden(const Image& golden, const Image& actual, float pixelThreshold);

// "rmse 0.021 > 0.01"-style lines, one per bound the metrics exceed.
std::vector<std::string> toleranceViolations(const run::ImageMetrics& m, const spec::ToleranceSpec& t);

// The value of a named metric of a golden comparison (the rows of compare/metric_table.h with
// a golden field); throws std::invalid_argument listing the names for anything else.
double metricByName(const run::ImageMetrics& m, const std::string& name);

}  // namespace taa::compare
