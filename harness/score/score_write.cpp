#include <nlohmann/json.hpp>

#include "core/output_file.h"
#include "report/html_report.h"
#include "report/svg_plot.h"
#include "report/text_util.h"
#include "score/score.h"

namespace taa::score {

namespace fs = std::filesystem;

namespace {

std::string ghostText(const LaneScore& l) {
  return l.ghostingMeasured ? report::formatFixed(l.ghosting, 4) : "-";
}

// FLIP of every case, one series per lane, against the case: where the user's resolve
// wins and loses at a glance (the sweep's plot, with cases on the x axis).
std::string scorePlot(const Scorecard& s, bool standalone) {
  std::vector<report::PlotSeries> series;
  for (size_t lane = 0; lane < 2; ++lane) {
    report::PlotSeries p{lane ? "user" : "default (built-in)",
                         {},
                         {},
                         lane ? "#d62728" : "",
                         false,
                         true,
                         lane == 1,
                         {}};
    for (size_t i = 0; i < s.cases.size(); ++i) {
      p.x.push_back(double(i));
      p.y.push_back(s.cases[i].lanes[lane].flip);
      p.pointLabels.push_back(s.cases[i].name);
    }
    series.push_back(p);
  }
  report::PlotOptions o;
  o.title = "FLIP mean against the reference, per case (index as in the table)";
  o.xLabel = "case";
  o.integerX = true;
  o.yLabel = "FLIP mean";
  o.height = 260;
  o.standalone = standalone;
  return report::svgPlot(series, o);
}

}  // namespace

std::string scoreMarkdown(const Scorecard& s) {
  std::string out =
      "| # | case | resolve | FLIP | RMSE | flicker (reference) | converged at | ghosting | "
      "non-finite | ms/frame |\n"
      "|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (size_t i = 0; i < s.cases.size(); ++i) {
    const auto& c = s.cases[i];
    for (const auto& l : c.lanes)
      out += "| " + std::to_string(i) + " | " + c.name + (c.stress ? " (stress)" : "") + " | " +
             l.lane + " | " + report::formatFixed(l.flip, 4) + " | " +
             report::formatFixed(l.rmse, 4) + " | " + report::formatFixed(l.flicker, 4) + " (" +
             report::formatFixed(c.referenceFlicker, 4) + ") | " + std::to_string(l.convergence) +
             " / " + std::to_string(c.frames) + " | " + ghostText(l) + " | " +
             std::to_string(l.nonFinite) + " | " + report::formatFixed(l.frameMs, 2) + " |\n";
  }
  return out;
}

void writeScorecard(const fs::path& dir, const Scorecard& s) {
  createOutputDirectory(dir);
  nlohmann::json j;
  j["shader"] = s.shader;
  j["device"] = s.device;
  j["skipped"] = s.skipped;
  j["note"] =
      "every figure but ms_per_frame is deterministic on one driver; ms_per_frame is a GPU "
      "timestamp";
  for (const auto& c : s.cases) {
    nlohmann::json jc{{"name", c.name},
                      {"frames", c.frames},
                      {"movers", c.movers},
                      {"stress", c.stress},
                      {"reference_flicker", c.referenceFlicker}};
    for (const auto& l : c.lanes) {
      nlohmann::json jl{{"flip_mean", l.flip},
                        {"rmse", l.rmse},
                        {"flicker", l.flicker},
                        {"convergence_frame", l.convergence},
                        {"non_finite", l.nonFinite},
                        {"ms_per_frame", l.frameMs},
                        {"flip_per_frame", l.flipPerFrame}};
      jl["ghosting"] = l.ghostingMeasured ? nlohmann::json(l.ghosting) : nlohmann::json(nullptr);
      jc["lanes"][l.lane] = jl;
    }
    j["cases"].push_back(jc);
  }
  writeFileAtomically(dir / "score.json", j.dump(2) + "\n");
  const std::string md =
      "# Scorecard: " + s.shader + "\n\nDevice: " + s.device +
      ". Every figure but ms/frame is deterministic; ms/frame is a GPU timestamp median.\n\n" +
      scoreMarkdown(s);
  writeFileAtomically(dir / "score.md", md);
  writeFileAtomically(dir / "score.svg", scorePlot(s, true));

  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < s.cases.size(); ++i)
    for (const auto& l : s.cases[i].lanes)
      rows.push_back({std::to_string(i), s.cases[i].name, l.lane, report::formatFixed(l.flip, 4),
                      report::formatFixed(l.rmse, 4), report::formatFixed(l.flicker, 4),
                      std::to_string(l.convergence), ghostText(l), std::to_string(l.nonFinite),
                      report::formatFixed(l.frameMs, 2)});
  report::ReportSection section;
  section.title = "Scorecard: " + s.shader;
  section.note =
      "Each case replayed with the built-in resolve at its defaults and with the user's shader, "
      "both "
      "measured against one supersampled reference on " +
      s.device +
      ". Ghosting: no_ghosting's worst mean error on mover cases. Every figure but ms/frame is "
      "deterministic.";
  section.svg = scorePlot(s, false);
  section.tableHtml = report::htmlTable({"#", "case", "resolve", "FLIP", "RMSE", "flicker",
                                         "converged at", "ghosting", "non-finite", "ms/frame"},
                                        rows);
  report::writeSectionPage(dir / "score.html", "TAA scorecard: " + s.shader, s.device, section);
}

}  // namespace taa::score
