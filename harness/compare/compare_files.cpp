#include "compare/compare_files.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "compare/metric_table.h"
#include "compare/metrics.h"
#include "core/image_io.h"

namespace taa::compare {

namespace {

ReadImage readOrExplain(const std::string& path, const std::string& layer, const char* role) {
  ReadImage read;
  try {
    read = readImageByName(path, layer, kMaxCompareSamples);
  } catch (const ImageIoError& e) {
    throw CompareInputError(std::string(role) + " " + e.what() +
                            " (compare's limit; docs/trust.md)");
  }
  // FLIP works on three channels whatever the file holds, so pixels bound the memory too.
  if (read.image.pixelCount() > kMaxComparePixels)
    throw CompareInputError(std::string(role) + " " + path + ": " +
                            std::to_string(read.image.width) + "x" +
                            std::to_string(read.image.height) + " is over compare's limit of " +
                            std::to_string(kMaxComparePixels) +
                            " pixels (8K UHD fits); compare crops of it (docs/trust.md)");
  return read;
}

std::string shape(const Image& img) {
  return std::to_string(img.width) + "x" + std::to_string(img.height) + "x" +
         std::to_string(img.channels);
}

Image firstThreeChannels(const Image& img) {
  Image out(img.width, img.height, 3);
  for (size_t p = 0; p < img.pixelCount(); ++p)
    for (size_t c = 0; c < 3; ++c) out.data[p * 3 + c] = img.data[p * size_t(img.channels) + c];
  return out;
}

bool wanted(const CompareRequest& r, const std::string& name) {
  if (r.metrics.empty()) return true;
  if (std::find(r.metrics.begin(), r.metrics.end(), name) != r.metrics.end()) return true;
  return std::any_of(r.bounds.begin(), r.bounds.end(),
                     [&](const Bound& b) { return b.metric == name; });
}

std::string violation(const Bound& b, double value) {
  char buf[160];
  std::snprintf(buf, sizeof(buf), "%s %.6g %s %.6g", b.metric.c_str(), value, b.isMax ? ">" : "<",
                b.value);
  return buf;
}

}  // namespace

bool isMetricName(const std::string& name) {
  return findMetric(name) != nullptr;
}

std::string metricNameList() {
  std::vector<const MetricInfo*> rows;
  for (const auto& row : metricTable()) rows.push_back(&row);
  return metricList(rows);
}

CompareOutcome compareFiles(const CompareRequest& r) {
  ReadImage refRead = readOrExplain(r.referencePath, r.layer, "reference");
  ReadImage testRead = readOrExplain(r.testPath, r.layer, "test");
  const bool linear = refRead.linear;
  if (linear != testRead.linear) {
    throw CompareInputError(
        r.referencePath + " is " + (linear ? "linear (OpenEXR)" : "display-referred (PNG)") +
        " but " + r.testPath + " is " + (linear ? "display-referred (PNG)" : "linear (OpenEXR)") +
        " (by their content); compare an EXR with an EXR, or the PNGs of both");
  }
  if (r.hdr && !linear) {
    throw CompareInputError("--hdr needs linear inputs (OpenEXR), but " + r.referencePath +
                            " is a PNG");
  }
  Image ref = std::move(refRead.image);
  Image test = std::move(testRead.image);
  if (ref.width != test.width || ref.height != test.height) {
    throw CompareInputError(r.referencePath + " is " + shape(ref) + " but " + r.testPath + " is " +
                            shape(test) + "; both images must have the same size");
  }
  if (ref.channels != test.channels) {
    if (ref.channels < 3 || test.channels < 3) {
      throw CompareInputError(r.referencePath + " has " + std::to_string(ref.channels) +
                              " channel(s) but " + r.testPath + " has " +
                              std::to_string(test.channels) + "; convert both to RGB");
    }
    ref = firstThreeChannels(ref);
    test = firstThreeChannels(test);
  }

  CompareOutcome out;
  out.width = ref.width;
  out.height = ref.height;
  bool anyLinear = false, anyFlip = r.wantHeatmap;
  for (const auto& row : metricTable()) {
    if (!wanted(r, row.name)) continue;
    if (row.source == MetricSource::Linear)
      anyLinear = true;
    else
      anyFlip = true;
  }
  Metrics m;
  if (anyLinear) {
    MetricOptions mo;
    mo.threshold = r.pixelThreshold;
    m = computeMetrics(ref, test, mo);
  }
  FlipResult f;
  if (anyFlip) {
    if (r.hdr) {
      HdrFlipResult h = flipHdr(ref, test, r.flip);
      out.startExposure = h.startExposure;
      out.stopExposure = h.stopExposure;
      out.exposures = h.exposures;
      f = std::move(h);
      out.flipKind = "hdr";
    } else if (linear) {
      f = flipLdrFromHdr(ref, test, r.flip);
      out.flipKind = "ldr-tonemapped";
    } else {
      f = flipLdr(ref, test, r.flip);
      out.flipKind = "ldr";
    }
  }
  // Only what was computed: a metric of a computation that did not run is never wanted.
  std::vector<std::pair<std::string, double>> all;
  for (const auto& row : metricTable())
    if (row.source == MetricSource::Linear ? anyLinear : anyFlip)
      all.emplace_back(row.name, row.value(m, f));
  out.flipMap = std::move(f.errorMap);
  for (const auto& [name, value] : all) {
    if (wanted(r, name)) out.values.emplace_back(name, value);
  }
  for (const Bound& b : r.bounds) {
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const auto& v) { return v.first == b.metric; });
    const double v = it->second;
    // Written so that a NaN value violates every bound.
    const bool ok = b.isMax ? v <= b.value : v >= b.value;
    if (!ok) out.violations.push_back(violation(b, v));
  }
  return out;
}

}  // namespace taa::compare
