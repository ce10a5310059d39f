// One checked frame: the three images side by side, the golden/actual split view, the split of
// two parameter sets (report.ab) and the magnified crops (worst region or report.zoom's).
#include <string>

#include "report/html_parts.h"
#include "report/text_util.h"

namespace taa::report::detail {

namespace fs = std::filesystem;

namespace {

std::string figure(const fs::path& dir, const std::string& rel, const std::string& caption,
                   const std::string& alt) {
  return "<figure><figcaption>" + escapeMarkup(caption) + "</figcaption>" +
         imageOrPlaceholder(dir, rel, alt, "") + "</figure>";
}

// A draggable split of two images of one frame: `left` over `right`, clipped at the divider.
std::string splitImages(const std::string& left, const std::string& right,
                        const std::string& leftTag, const std::string& rightTag) {
  std::string s = "<div class=\"ab\" data-zoom=\"auto\">\n<div class=\"ab-tools\">";
  s += "<span>A/B: " + escapeMarkup(leftTag) + " | " + escapeMarkup(rightTag) +
       "; drag, or focus and use \xE2\x86\x90 \xE2\x86\x92</span>";
  for (const char* z : {"1", "2", "4", "8"})
    s += std::string("<button type=\"button\" class=\"zoom\" data-zoom=\"") + z +
         "\" aria-pressed=\"false\">" + z + "x</button>";
  s += "</div>\n<div class=\"ab-scroll\"><div class=\"split\" tabindex=\"0\" role=\"slider\" "
       "aria-label=\"A/B divider\" aria-valuemin=\"0\" aria-valuemax=\"100\" "
       "aria-valuenow=\"50\" data-pos=\"0.5000\">";
  s += "<img class=\"ab-actual\" src=\"" + encodePath(right) + "\" alt=\"" +
       escapeMarkup(rightTag) + "\">";
  s += "<img class=\"ab-golden\" src=\"" + encodePath(left) + "\" alt=\"" + escapeMarkup(leftTag) +
       "\">";
  s += "<div class=\"divider\"></div><span class=\"tag l\">" + escapeMarkup(leftTag) +
       "</span><span class=\"tag r\">" + escapeMarkup(rightTag) + "</span></div></div>\n</div>\n";
  return s;
}

std::string splitView(const run::FrameImages& im, const fs::path& dir) {
  if (!imageExists(dir, im.golden) || !imageExists(dir, im.actual))
    return "<div class=\"missing\">A/B view needs both the golden and the actual image</div>\n";
  return splitImages(im.golden, im.actual, "golden", "actual");
}

// report.ab: this run's output (A) against the same frame rendered with a second parameter
// set (B), the seed's split screen.
std::string abView(const run::FrameImages& im, const fs::path& dir) {
  if (im.ab.empty()) return "";
  if (!imageExists(dir, im.ab) || !imageExists(dir, im.actual))
    return "<div class=\"missing\">A/B of the second parameter set needs both outputs</div>\n";
  return "<h4>parameter sets <span class=\"mono\">A: this case | B: " + escapeMarkup(im.abLabel) +
         "</span></h4>\n" + splitImages(im.actual, im.ab, "A: case", "B: " + im.abLabel);
}

std::string crops(const run::FrameImages& im, const fs::path& dir) {
  if (im.zoomGolden.empty() && im.zoomActual.empty() && im.zoomDiff.empty()) return "";
  const std::string rect = "x " + std::to_string(im.zoomX) + ", y " + std::to_string(im.zoomY) +
                           ", " + std::to_string(im.zoomW) + "\xC3\x97" + std::to_string(im.zoomH) +
                           " px";
  std::string s = std::string("<div class=\"crops\"><h4>") +
                  (im.zoomChosen ? "chosen region (report.zoom)" : "worst region") +
                  " <span class=\"mono\">" + escapeMarkup(rect) +
                  "</span> (magnified)</h4><div class=\"row\">";
  // Without a golden (a new case with report.zoom) there is only the actual crop, and B's.
  if (!im.zoomGolden.empty() || !im.golden.empty())
    s += figure(dir, im.zoomGolden, "golden " + rect, "golden crop");
  s += figure(dir, im.zoomActual, "actual " + rect, "actual crop");
  if (!im.zoomAb.empty()) s += figure(dir, im.zoomAb, "B: " + im.abLabel + " " + rect, "B crop");
  if (!im.zoomDiff.empty() || !im.diff.empty())
    s += figure(dir, im.zoomDiff, "diff " + rect, "diff crop");
  s += "</div></div>\n";
  return s;
}

}  // namespace

std::string renderFrame(const run::FrameComparison& f, const std::string& id, const fs::path& dir) {
  std::string s =
      "<div class=\"frame\" id=\"" + id + "\" data-frame=\"" + std::to_string(f.frame) + "\">\n";
  s += "<h4>frame " + std::to_string(f.frame) + " <span class=\"badge " + frameClass(f.status) +
       "\">" + frameLabel(f.status) + "</span> <span class=\"muted\">" +
       (f.toleranceMode ? "tolerance mode" : "exact mode") + "</span></h4>\n";
  if (!f.failures.empty()) {
    s += "<ul class=\"failures\">";
    for (const auto& line : f.failures) s += "<li>" + escapeMarkup(line) + "</li>";
    s += "</ul>\n";
  }
  s += "<div class=\"row triptych\">";
  s += figure(dir, f.images.golden, "golden", "golden frame " + std::to_string(f.frame));
  s += figure(dir, f.images.actual, "actual", "actual frame " + std::to_string(f.frame));
  s += figure(dir, f.images.diff, "diff heatmap", "diff frame " + std::to_string(f.frame));
  s += "</div>\n";
  s += splitView(f.images, dir);
  s += abView(f.images, dir);
  s += crops(f.images, dir);
  if (!f.actualSha256.empty() || !f.goldenSha256.empty()) {
    s += "<dl class=\"kv\"><dt>actual sha256</dt><dd>" + escapeMarkup(f.actualSha256) +
         "</dd><dt>golden sha256</dt><dd>" + escapeMarkup(f.goldenSha256) + "</dd></dl>\n";
  }
  s += "</div>\n";
  return s;
}

}  // namespace taa::report::detail
