
#include "core/output_file.h"
#include "report/html_report.h"
#include "report/svg_plot.h"
#include "report/text_util.h"
#include "sweep/sweep.h"

namespace taa::sweep {

namespace fs = std::filesystem;

namespace {

// The Pareto front of the presets that ran, as indices into r.presets.
std::vector<size_t> front(const SweepResult& r) {
  std::vector<double> x, y;
  std::vector<size_t> ran;
  for (size_t i = 0; i < r.presets.size(); ++i)
    if (r.presets[i].skipped.empty()) {
      ran.push_back(i);
      x.push_back(r.presets[i].frameMs);
      y.push_back(r.presets[i].flipMean);
    }
  std::vector<size_t> out;
  for (size_t k : report::paretoFront(x, y)) out.push_back(ran[k]);
  return out;
}

// A lane's notes: why it did not run, or the case's invariants it cannot meet.
std::string presetNotes(const PresetResult& p) {
  if (!p.skipped.empty()) return "skipped: " + p.skipped;
  std::string out;
  for (const auto& n : p.notApplicable) out += (out.empty() ? "n/a: " : "; ") + n;
  return out;
}

std::string figure(const PresetResult& p, double v, int digits) {
  return p.skipped.empty() ? report::formatFixed(v, digits) : "-";
}

bool onFront(const std::vector<size_t>& f, size_t i) {
  return std::find(f.begin(), f.end(), i) != f.end();
}

void writeText(const fs::path& file, const std::string& text) {
  writeFileAtomically(file, text);
}

std::string plot(const SweepResult& r, bool standalone) {
  const auto f = front(r);
  report::PlotSeries all{"presets", {}, {}, "", false, true, false, {}};
  report::PlotSeries best{"Pareto front", {}, {}, "#d62728", true, true, true, {}};
  best.showLabels = true;  // a static SVG (docs, CI artefacts) has no tooltips; the front is sparse
  for (size_t i = 0; i < r.presets.size(); ++i) {
    const auto& p = r.presets[i];
    if (!p.skipped.empty()) continue;
    all.x.push_back(p.frameMs);
    all.y.push_back(p.flipMean);
    all.pointLabels.push_back(p.name);
  }
  for (size_t i : f) {
    best.x.push_back(r.presets[i].frameMs);
    best.y.push_back(r.presets[i].flipMean);
    best.pointLabels.push_back(r.presets[i].name);
  }
  report::PlotOptions o;
  o.title = r.caseName + ": error against run time";
  o.xLabel = "whole frame, median GPU ms (log)";
  o.logX = true;  // presets span from a bare raster to ray tracing
  // Errors span from a ray tracer's to no reprojection at all (0.01 to 0.2 on the open area):
  // on a linear axis the useful presets would sit on one line at the bottom.
  o.logY = true;
  o.yFromZero = false;
  o.yLabel = "FLIP mean vs reference (log)";
  o.height = 280;
  o.standalone = standalone;
  return report::svgPlot({all, best}, o);
}

}  // namespace

std::string markdownTable(const SweepResult& r) {
  const auto f = front(r);
  std::string s =
      "| preset | FLIP mean | RMSE | flicker (reference) | TAA ms | frame ms | Pareto | notes |\n"
      "|---|---:|---:|---:|---:|---:|:---:|---|\n";
  for (size_t i = 0; i < r.presets.size(); ++i) {
    const auto& p = r.presets[i];
    s += "| " + p.name + " | " + figure(p, p.flipMean, 4) + " | " + figure(p, p.rmse, 4) + " | " +
         figure(p, p.flicker, 4) + (p.skipped.empty() ? " (" + report::formatFixed(p.referenceFlicker, 4) + ")" : "") +
         " | " + figure(p, p.taaMs, 2) + " | " + figure(p, p.frameMs, 2) + " | " +
         (onFront(f, i) ? "yes" : "") + " | " + presetNotes(p) + " |\n";
  }
  return s;
}

void writeSweep(const fs::path& dir, const SweepResult& r) {
  createOutputDirectory(dir);
  std::string csv =
      "preset,flip_mean,rmse,flicker,reference_flicker,taa_ms,frame_ms,pareto,patch\n";
  const auto f = front(r);
  for (size_t i = 0; i < r.presets.size(); ++i) {
    const auto& p = r.presets[i];
    if (!p.skipped.empty()) continue;  // in sweep.md and report.html, with the reason
    std::string patch = p.patch;
    for (auto& c : patch)
      if (c == '"') c = '\'';
    csv += p.name + "," + report::formatNumber(p.flipMean, 6) + "," +
           report::formatNumber(p.rmse, 6) + "," + report::formatNumber(p.flicker, 6) + "," +
           report::formatNumber(p.referenceFlicker, 6) + "," + report::formatFixed(p.taaMs, 4) +
           "," + report::formatFixed(p.frameMs, 4) + "," + (onFront(f, i) ? "1" : "0") + ",\"" +
           patch + "\"\n";
  }
  writeText(dir / "sweep.csv", csv);
  // Each measured frame's error beside what it cost (GPU ms, run/timing.h).
  std::string frames = "preset,frame,rmse,flip_mean,taa_ms,frame_ms\n";
  for (const auto& p : r.presets)
    for (size_t k = 0; k < p.rmsePerFrame.size(); ++k) {
      const auto ms = [k](const std::vector<double>& v) {
        return k < v.size() ? report::formatFixed(v[k], 4) : std::string();
      };
      frames += p.name + "," + std::to_string(r.fromFrame + int(k)) + "," +
                report::formatNumber(p.rmsePerFrame[k], 6) + "," +
                report::formatNumber(p.flipPerFrame[k], 6) + "," + ms(p.taaMsPerFrame) + "," +
                ms(p.frameMsPerFrame) + "\n";
    }
  writeText(dir / "frames.csv", frames);
  writeText(dir / "sweep.md", markdownTable(r));
  writeText(dir / "sweep.svg", plot(r, true));

  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < r.presets.size(); ++i) {
    const auto& p = r.presets[i];
    rows.push_back({p.name, figure(p, p.flipMean, 4), figure(p, p.rmse, 4), figure(p, p.flicker, 4),
                    figure(p, p.taaMs, 2), figure(p, p.frameMs, 2), onFront(f, i) ? "yes" : "",
                    p.patch, presetNotes(p)});
  }
  report::ReportSection section;
  section.title = "Sweep: " + r.caseName;
  section.note = "Each preset replays the same script; errors are means over frames " +
                 std::to_string(r.fromFrame) + ".." + std::to_string(r.frames - 1) +
                 " against the supersampled reference (" + std::to_string(r.referenceSamples) +
                 " samples), times are GPU timestamps on " + r.device + ".";
  section.svg = plot(r, false);
  section.tableHtml = report::htmlTable(
      {"preset", "FLIP mean", "RMSE", "flicker", "TAA ms", "frame ms", "Pareto", "settings", "notes"},
      rows);
  report::writeSectionPage(dir / "report.html", "TAA sweep: " + r.caseName, r.device, section);
}

}  // namespace taa::sweep
