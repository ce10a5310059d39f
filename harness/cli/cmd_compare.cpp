// taa-harness compare: the harness's metrics on any two image files, with bounds that turn into
// an exit code so the command scripts into other CI (as idiff and the FLIP tool do).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "compare/compare_files.h"
#include "compare/heatmap.h"
#include "core/image_io.h"
#include "core/output_file.h"

namespace taa::cli {

namespace {

constexpr double kMaxFlipPixelsPerDegree = 1000.0;

// `names` ("a, b, c") broken after a comma to lines of at most 96 characters, each indented by
// 14 spaces.
std::string indentedList(const std::string& names) {
  std::string out, line;
  std::stringstream in(names);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.starts_with(' ')) item.erase(0, 1);
    if (!line.empty() && 14 + line.size() + item.size() + 2 > 96) {
      out += std::string(14, ' ') + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + item + ",";
  }
  line.pop_back();
  return out + std::string(14, ' ') + line + "\n";
}

std::string compareUsage() {
  return "taa-harness compare REFERENCE TEST [--metrics LIST] [--flip-ppd N] [--hdr] [--threads "
         "N]\n"
         "                    [--pixel-threshold T] [--max METRIC=V,...] [--min METRIC=V,...]\n"
         "                    [--heatmap OUT.png] [--layer NAME] [--json]\n"
         "  metrics of TEST against REFERENCE (OpenEXR or PNG, told apart by content: EXR files "
         "are\n"
         "  linear, PNG files display-referred sRGB; both must be the same kind).\n"
         "  --metrics   comma list of the metrics to report (default: all of them):\n" +
         indentedList(compare::metricNameList()) +
         "  --flip-ppd  pixels per degree for FLIP, 0.01 to 1000 (default 67.02: 0.7 m from a 0.7 "
         "m\n"
         "              wide 4K screen)\n"
         "  --hdr       HDR-FLIP for linear inputs (default: LDR-FLIP of the tonemapped PNG view)\n"
         "  --threads   FLIP worker threads (default: one per core; results do not depend on it)\n"
         "  --pixel-threshold  per-pixel bound that share_over counts, at least 0 (default 1/255)\n"
         "  --max/--min exit 1 when a metric is above a --max or below a --min bound\n"
         "  --heatmap   write the FLIP error map as a magma PNG\n"
         "  --layer     compare the EXR layer NAME (channels NAME.R, NAME.G, NAME.B, NAME.A); "
         "without\n"
         "              it the channels named R, G, B, A (R required; no channel is taken by "
         "position)\n"
         "  --json      print the result as JSON instead of lines\n"
         "exit: 0 within every bound, 1 a bound violated, 2 bad input (file, option, shape)";
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

// "flip_mean=0.05,rmse=0.01" into bounds; names must be known metrics.
void parseBounds(const std::string& option, const std::string& text, bool isMax,
                 std::vector<compare::Bound>& out) {
  const auto items = splitList(text);
  if (!text.empty() && items.empty())
    throw UsageError(option + ": no METRIC=VALUE in '" + text + "'");
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) {
      throw UsageError(option + ": '" + item + "' should be METRIC=VALUE, e.g. flip_mean=0.05");
    }
    compare::Bound b;
    b.metric = item.substr(0, eq);
    if (!compare::isMetricName(b.metric)) {
      throw UsageError(option + ": unknown metric '" + b.metric + "'; use one of " +
                       compare::metricNameList());
    }
    b.isMax = isMax;
    ParsedArgs one;
    one.values[option + " " + b.metric] = item.substr(eq + 1);
    b.value = numberOption(one, option + " " + b.metric, -1e300, 1e300);
    out.push_back(b);
  }
}

nlohmann::json number(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}

}  // namespace

int cmdCompare(const Args& args) {
  const auto a = parseArgs(args, {"--json", "--hdr"},
                           {"--metrics", "--flip-ppd", "--threads", "--pixel-threshold", "--max",
                            "--min", "--heatmap", "--layer"},
                           compareUsage());
  if (a.positional.size() != 2) {
    throw UsageError("expected REFERENCE and TEST, got " + std::to_string(a.positional.size()) +
                     " file(s)\nusage: " + compareUsage());
  }
  compare::CompareRequest req;
  req.referencePath = a.positional[0];
  req.testPath = a.positional[1];
  if (a.values.count("--metrics")) {
    req.metrics = splitList(a.value("--metrics"));
    if (req.metrics.empty()) throw UsageError("--metrics: empty list");
    for (const auto& m : req.metrics) {
      if (!compare::isMetricName(m)) {
        throw UsageError("--metrics: unknown metric '" + m + "'; use one of " +
                         compare::metricNameList());
      }
    }
  }
  // FLIP's filters are 0.135 * ppd pixels wide: past 1000 ppd (a 135-pixel radius) the cost
  // grows without telling anything a viewer could see.
  if (a.values.count("--flip-ppd"))
    req.flip.pixelsPerDegree = numberOption(a, "--flip-ppd", 0.01, kMaxFlipPixelsPerDegree);
  if (a.values.count("--threads"))
    req.flip.threads = int(numberOption(a, "--threads", 1, 1024, true));
  if (a.values.count("--pixel-threshold"))
    req.pixelThreshold = numberOption(a, "--pixel-threshold", 0.0, 1e30);
  req.hdr = a.has("--hdr");
  req.layer = a.value("--layer");
  req.wantHeatmap = a.values.count("--heatmap") > 0;
  // Before the images are read and compared: never a device, FIFO, link or either input.
  if (req.wantHeatmap)
    checkOutputPath(a.value("--heatmap"), {req.referencePath, req.testPath}, "compare --heatmap");
  parseBounds("--max", a.value("--max"), true, req.bounds);
  parseBounds("--min", a.value("--min"), false, req.bounds);

  compare::CompareOutcome out;
  try {
    out = compare::compareFiles(req);
  } catch (const compare::CompareInputError& e) {
    throw UsageError(e.what());
  }
  if (req.wantHeatmap) {
    // A heatmap that cannot be written is an output failure (exit 3), like every output.
    writePngLinear8(a.value("--heatmap"), compare::heatmap(out.flipMap));
  }

  if (a.has("--json")) {
    nlohmann::json j = {{"reference", req.referencePath},
                        {"test", req.testPath},
                        {"width", out.width},
                        {"height", out.height},
                        {"flip", out.flipKind}};
    for (const auto& [name, value] : out.values) j["metrics"][name] = number(value);
    if (out.exposures > 0) {
      j["hdr_exposures"] = {
          {"start", out.startExposure}, {"stop", out.stopExposure}, {"count", out.exposures}};
    }
    j["violations"] = out.violations;
    j["pass"] = out.violations.empty();
    std::cout << j.dump(2) << "\n";
  } else {
    for (const auto& [name, value] : out.values) std::cout << name << " " << value << "\n";
    for (const auto& v : out.violations) std::cout << "FAIL " << v << "\n";
  }
  return out.violations.empty() ? kPass : kRegression;
}

}  // namespace taa::cli
