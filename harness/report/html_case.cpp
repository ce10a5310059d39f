// One case of the report: status and message, metrics, invariants, curves, frames, timings, log.
#include <algorithm>
#include <string>

#include "compare/metric_table.h"
#include "report/html_parts.h"
#include "report/svg_plot.h"
#include "report/text_util.h"
#include "run/console.h"

namespace taa::report::detail {

namespace fs = std::filesystem;

namespace {

std::string num(double v, int significant = 4) {
  return escapeMarkup(formatNumber(v, significant));
}

// "max abs, RMSE and PSNR dB": the titles of the golden columns computed by `source`.
std::string columnTitles(compare::MetricSource source) {
  std::vector<std::string> titles;
  for (const auto* col : compare::goldenMetrics())
    if (col->source == source) titles.emplace_back(col->title);
  std::string out;
  for (size_t i = 0; i < titles.size(); ++i)
    out += (i == 0 ? "" : i + 1 == titles.size() ? " and " : ", ") + titles[i];
  return out;
}

std::string metricsTable(const run::CaseResult& c, const std::string& id) {
  if (c.frames.empty()) return "<p class=\"muted\">no frames were compared</p>\n";
  const auto columns = compare::goldenMetrics();
  std::string s = "<table class=\"metrics\"><tr><th>frame</th><th>status</th><th>mode</th>";
  for (const auto* col : columns) s += std::string("<th class=\"num\">") + col->title + "</th>";
  s += "</tr>\n";
  for (const auto& f : c.frames) {
    const bool bad = f.status == run::FrameStatus::Failed;
    s += std::string("<tr") + (bad ? " class=\"bad\"" : "") + "><td class=\"num\"><a href=\"#" +
         id + "-f" + std::to_string(f.frame) + "\">" + std::to_string(f.frame) + "</a></td>";
    s += "<td><span class=\"badge " + frameClass(f.status) + "\">" + frameLabel(f.status) +
         "</span></td>";
    if (f.status == run::FrameStatus::MissingGolden) {
      // Nothing was compared: zeros here would read as a perfect match.
      s += "<td colspan=\"" + std::to_string(columns.size() + 1) +
           "\" class=\"muted\">not compared: no golden</td></tr>\n";
      continue;
    }
    s += std::string("<td>") + (f.toleranceMode ? "tolerance" : "exact") + "</td>";
    for (const auto* col : columns) {
      const bool hit =
          std::any_of(f.failures.begin(), f.failures.end(),
                      [&](const std::string& line) { return compare::isViolationOf(*col, line); });
      s += std::string("<td class=\"num") + (hit ? " bad" : "") + "\">" +
           num(f.metrics.*col->golden) + "</td>";
    }
    s += "</tr>\n";
  }
  s += "</table>\n";
  // What each number is computed on, so nobody has to guess from the column title.
  return s + "<p class=\"muted metric-notes\">" +
         escapeMarkup(columnTitles(compare::MetricSource::Linear)) +
         ": on the linear half-float frames (RGB). PSNR = 10 log10(peak\xC2\xB2 / MSE) with a "
         "fixed peak of 1.0 (nominal white), not the image maximum, so HDR values above 1 can "
         "make it negative. " +
         escapeMarkup(columnTitles(compare::MetricSource::Flip)) +
         ": LDR-FLIP on exactly the 8-bit sRGB PNGs shown here (Reinhard c / (1 + c), sRGB curve, "
         "rounded to 8 bits), at 67 pixels per degree.</p>\n";
}

// Where the sequence starts to go wrong: the first frame whose hash differs from the golden's,
// beside the stored golden frames nearest to it.
std::string firstDifference(const run::CaseResult& c, const std::string& id, const fs::path& dir) {
  const auto& d = c.firstDifference;
  if (d.frame < 0) return "";
  std::string s = "<h3>First differing frame</h3>\n<div class=\"first-diff\" id=\"" + id +
                  "-first\" data-frame=\"" + std::to_string(d.frame) +
                  "\"><ul class=\"failures\"><li>" + escapeMarkup(d.detail) +
                  "</li></ul>\n<div class=\"row\">";
  auto figure = [&](const std::string& rel, const std::string& caption) {
    s += "<figure><figcaption>" + escapeMarkup(caption) + "</figcaption>" +
         imageOrPlaceholder(dir, rel, caption, "") + "</figure>";
  };
  for (const auto& n : d.goldenNeighbours)
    if (n.frame < d.frame) figure(n.image, "golden frame " + std::to_string(n.frame) + " (stored)");
  if (!d.actual.empty()) figure(d.actual, "actual frame " + std::to_string(d.frame));
  for (const auto& n : d.goldenNeighbours)
    if (n.frame >= d.frame)
      figure(n.image, "golden frame " + std::to_string(n.frame) + " (stored)");
  s += "</div>\n";
  if (!d.actualSha256.empty())
    s += "<dl class=\"kv\"><dt>actual sha256</dt><dd>" + escapeMarkup(d.actualSha256) +
         "</dd><dt>golden sha256</dt><dd>" + escapeMarkup(d.goldenSha256) + "</dd></dl>\n";
  return s + "</div>\n";
}

std::string invariantsTable(const run::CaseResult& c) {
  if (c.invariants.empty()) return "";
  std::string s =
      "<h3>Invariants</h3>\n<table class=\"invariants\"><tr><th>result</th>"
      "<th>invariant</th><th>detail</th><th>values</th></tr>\n";
  for (const auto& inv : c.invariants) {
    s += std::string("<tr") + (inv.passed ? "" : " class=\"bad\"") + "><td><span class=\"badge " +
         (inv.passed ? "st-pass\">PASS" : "st-fail\">FAIL") + "</span></td><td class=\"mono\">" +
         escapeMarkup(inv.name) + "</td><td>" + escapeMarkup(inv.detail) +
         "</td><td class=\"mono\">";
    // By name, as results.json keeps them: a report written from results read back (merge)
    // lists them as the run's own report does.
    auto values = inv.values;
    std::sort(values.begin(), values.end());
    for (size_t i = 0; i < values.size(); ++i)
      s += (i ? "<br>" : "") + escapeMarkup(values[i].first) + " = " + num(values[i].second, 6);
    s += "</td></tr>\n";
  }
  return s + "</table>\n";
}

std::string curves(const run::CaseResult& c) {
  const bool anyGolden = std::any_of(c.frames.begin(), c.frames.end(), [](const auto& f) {
    return f.status != run::FrameStatus::MissingGolden;
  });
  if (c.referenceRmse.empty() && c.frameMs.empty() && !anyGolden) return "";
  PlotOptions o;
  o.width = 620;
  o.height = 200;
  o.integerX = true;
  o.xLabel = "frame";
  for (const auto& f : c.frames) o.xMarks.push_back(f.frame);
  // The whole sequence, so that one checked frame shows where it lies in it.
  const size_t sequence =
      std::max({c.frameMs.size(), c.referenceRmse.size(), c.frameSha256.size()});
  if (sequence > 1) {
    o.xMin = 0.0;
    o.xMax = double(sequence - 1);
  }
  std::string s = "<h3>Over the sequence</h3>\n<div class=\"plots\">\n";
  {
    std::vector<PlotSeries> series;
    PlotSeries ref{.name = "RMSE vs reference"};
    for (size_t i = 0; i < c.referenceRmse.size(); ++i) {
      ref.x.push_back(double(i));
      ref.y.push_back(c.referenceRmse[i]);
    }
    if (!ref.x.empty()) series.push_back(ref);
    PlotSeries golden{.name = "RMSE vs golden", .line = false, .markers = true};
    PlotSeries failed{
        .name = "failed", .colour = "#c62828", .line = false, .markers = true, .highlight = true};
    for (const auto& f : c.frames) {
      if (f.status == run::FrameStatus::MissingGolden) continue;
      PlotSeries& target = f.status == run::FrameStatus::Failed ? failed : golden;
      target.x.push_back(f.frame);
      target.y.push_back(f.metrics.rmse);
      target.pointLabels.push_back("frame " + std::to_string(f.frame) + ": RMSE " +
                                   formatNumber(f.metrics.rmse, 4));
    }
    if (!golden.x.empty()) series.push_back(golden);
    if (!failed.x.empty()) series.push_back(failed);
    o.title = "error per frame (dashed: checked frames)";
    o.yLabel = "RMSE";
    s += svgPlot(series, o);
  }
  if (!c.frameMs.empty()) {
    PlotSeries ms{.name = "frame time", .colour = "#555"};
    for (size_t i = 0; i < c.frameMs.size(); ++i) {
      ms.x.push_back(double(i));
      ms.y.push_back(c.frameMs[i]);
    }
    o.title = "frame time";
    o.yLabel = "ms";
    o.width = 420;
    o.height = 160;
    s += svgPlot({ms}, o);
  }
  return s + "</div>\n";
}

std::string timingsTable(const run::CaseResult& c) {
  if (c.timings.empty() && c.seconds == 0.0) return "";  // the case never got to render
  std::string s = "<h3>Pass timings</h3>\n";
  if (c.timings.empty()) {
    s += "<p class=\"muted\">no timings recorded</p>\n";
  } else {
    s += "<table class=\"timings\"><tr><th>pass</th><th class=\"num\">median ms</th>"
         "<th class=\"num\">p95 ms</th></tr>\n";
    for (const auto& t : c.timings)
      s += "<tr><td class=\"mono\">" + escapeMarkup(t.pass) + "</td><td class=\"num\">" +
           escapeMarkup(formatFixed(t.medianMs, 3)) + "</td><td class=\"num\">" +
           escapeMarkup(formatFixed(t.p95Ms, 3)) + "</td></tr>\n";
    s += "</table>\n";
  }
  return s + "<p class=\"muted mono\">case wall time " + escapeMarkup(formatFixed(c.seconds, 2)) +
         " s</p>\n";
}

}  // namespace

std::string renderCase(const run::CaseResult& c, size_t index, const std::string& runFingerprint,
                       const fs::path& dir) {
  const std::string id = "case-" + std::to_string(index);
  std::string s = "<section class=\"case " + caseClass(c.status) + "\" id=\"" + id +
                  "\" data-case=\"" + escapeMarkup(c.name) + "\">\n";
  s += "<h2><span class=\"badge " + caseClass(c.status) + "\">" + caseLabel(c.status) +
       "</span><span>" + escapeMarkup(c.name) + "</span><span class=\"file\">" +
       escapeMarkup(c.file) + "</span></h2>\n";
  if (!c.description.empty()) s += "<p class=\"desc\">" + escapeMarkup(c.description) + "</p>\n";
  if (!c.resolve.empty()) s += "<p class=\"desc\">" + escapeMarkup(c.resolve) + "</p>\n";
  if (!c.message.empty()) s += "<div class=\"msg\">" + escapeMarkup(c.message) + "</div>\n";
  if (!c.blessCommand.empty())
    s += "<div class=\"bless\"><span class=\"muted\">bless:</span><code>" +
         escapeMarkup(c.blessCommand) +
         "</code><button type=\"button\" class=\"copy\">copy"
         "</button></div>\n";
  const bool ownFingerprint = !c.fingerprint.empty() && c.fingerprint != runFingerprint;
  if (ownFingerprint || !c.goldenFingerprint.empty()) {
    s += "<dl class=\"kv\">";
    if (ownFingerprint) s += "<dt>fingerprint</dt><dd>" + escapeMarkup(c.fingerprint) + "</dd>";
    if (!c.goldenFingerprint.empty()) {
      const std::string& mine = c.fingerprint.empty() ? runFingerprint : c.fingerprint;
      // Which verdict: bit for bit against this environment's positive, or within tolerances
      // for want of one (never a tolerance pass that reads like an exact one).
      s += c.goldenMode == "tolerance"
               ? "<dt>golden</dt><dd class=\"tolerance\">tolerance: no positive for " +
                     escapeMarkup(mine) + "; compared with the positive of " +
                     escapeMarkup(c.goldenFingerprint) + "</dd>"
               : "<dt>golden</dt><dd>exact: this environment's positive (" +
                     escapeMarkup(c.goldenFingerprint) + ")</dd>";
    }
    s += "</dl>\n";
  }
  s += "<h3>Frames compared with goldens</h3>\n" + metricsTable(c, id);
  if (const auto& q = c.sequenceCheck; !q.mode.empty())
    s += "<p class=\"muted sequence\">every frame compared (" + std::to_string(q.frames) + "): " +
         (q.mode == "exact" ? "pixel hashes, bit-exact (this environment's positive)"
                            // "within tolerance" would read as a verdict on a failing sequence
                            : "quality signatures against tolerances (no positive for this environment)" +
                                  escapeMarkup(run::sequenceWorst(q))) +
         "</p>\n";
  s += firstDifference(c, id, dir);
  s += invariantsTable(c);
  s += curves(c);
  for (const auto& f : c.frames) s += renderFrame(f, id + "-f" + std::to_string(f.frame), dir);
  s += timingsTable(c);
  if (c.log.empty()) {
    s += "<p class=\"muted\">no renderer log</p>\n";
  } else {
    s += "<details><summary>renderer log (" + std::to_string(c.log.size()) +
         " lines: passes and buffers)</summary><pre class=\"log\">";
    for (const auto& line : c.log) s += escapeMarkup(line) + "\n";
    s += "</pre></details>\n";
  }
  s += "</section>\n";
  return s;
}

}  // namespace taa::report::detail
