#include <nlohmann/json.hpp>

#include "core/output_file.h"
#include "report/html_report.h"
#include "report/svg_plot.h"
#include "report/text_util.h"
#include "score/score.h"

namespace taa::score {

namespace fs = std::filesystem;

namespace {

const char* kPalette[] = {"", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string ghostText(const LaneScore& l) {
  return l.ghostingMeasured ? report::formatFixed(l.ghosting, 4) : "-";
}

// "5 / 24", or "never: error rose" (the figures are in score.json and the HTML table).
std::string convergedText(const LaneScore& l, int frames) {
  if (l.converged.frame >= 0) return std::to_string(l.converged.frame) + " / " + std::to_string(frames);
  return "never: " + l.converged.why.substr(0, l.converged.why.find(" ("));
}

// One row's cells: figures, or the reason the lane did not run the case.
std::vector<std::string> laneCells(const CaseScore& c, const LaneScore& l) {
  if (!l.skipped.empty()) return {"skipped: " + l.skipped, "", "", "", "", "", ""};
  return {report::formatFixed(l.flip, 4),
          report::formatFixed(l.rmse, 4),
          report::formatFixed(l.flicker, 4) + " (" + report::formatFixed(c.referenceFlicker, 4) + ")",
          convergedText(l, c.frames),
          ghostText(l),
          std::to_string(l.nonFinite),
          report::formatFixed(l.taaMs, 2)};
}

// FLIP of every case, one series per lane, against the case: where each resolve wins and
// loses at a glance (the sweep's plot, with cases on the x axis).
std::string scorePlot(const Scorecard& s, bool standalone) {
  std::vector<report::PlotSeries> series;
  for (size_t lane = 0; lane < s.lanes.size(); ++lane) {
    report::PlotSeries p{lane ? s.lanes[lane].name : "default (built-in)",
                         {},
                         {},
                         kPalette[lane % (sizeof(kPalette) / sizeof(kPalette[0]))],
                         false,
                         true,
                         lane > 0,
                         {}};
    for (size_t i = 0; i < s.cases.size(); ++i) {
      const LaneScore& l = s.cases[i].lanes[lane];
      if (!l.skipped.empty()) continue;
      p.x.push_back(double(i));
      p.y.push_back(l.flip);
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

const char* kFiniteNote =
    "FLIP, RMSE and flicker are over finite samples: a pixel with a NaN or infinite output "
    "sample is measured as the reference's (no error), RMSE's mean taken over the other "
    "pixels; non-finite counts those samples, every channel, every frame. Converged at: the "
    "first frame from which FLIP stays within 10% of the run's fall above the level of the "
    "last quarter (never when it fell by less than 10% of frame 0's, rose, or still settles "
    "in the last quarter; at the reference's floor, FLIP 0.001, from the first frame there).";

std::string laneLegend(const Scorecard& s) {
  std::string out;
  for (const auto& l : s.lanes) out += "- " + l.name + ": " + l.describe + "\n";
  return out;
}

}  // namespace

std::string scoreMarkdown(const Scorecard& s) {
  std::string out =
      "| # | case | lane | FLIP | RMSE | flicker (reference) | converged at | ghosting | "
      "non-finite | ms/frame |\n"
      "|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (size_t i = 0; i < s.cases.size(); ++i) {
    const auto& c = s.cases[i];
    for (const auto& l : c.lanes) {
      out += "| " + std::to_string(i) + " | " + c.name + (c.stress ? " (stress)" : "") + " | " + l.lane;
      for (const auto& cell : laneCells(c, l)) out += " | " + cell;
      out += " |\n";
    }
  }
  return out;
}

void writeScorecard(const fs::path& dir, const Scorecard& s) {
  createOutputDirectory(dir);
  nlohmann::json j;
  j["device"] = s.device;
  j["skipped"] = s.skipped;
  j["note"] = std::string(kFiniteNote) +
              " Every figure but ms_per_frame is deterministic on one driver; ms_per_frame is a "
              "GPU timestamp.";
  for (const auto& l : s.lanes) j["lanes"].push_back({{"name", l.name}, {"taa", l.taa}, {"describe", l.describe}});
  for (const auto& c : s.cases) {
    nlohmann::json jc{{"name", c.name},
                      {"frames", c.frames},
                      {"movers", c.movers},
                      {"stress", c.stress},
                      {"reference_flicker", c.referenceFlicker}};
    for (const auto& l : c.lanes) {
      nlohmann::json jl;
      if (!l.skipped.empty()) {
        jl["skipped"] = l.skipped;
      } else {
        jl = {{"flip_mean", l.flip},
              {"rmse", l.rmse},
              {"flicker", l.flicker},
              {"convergence_frame", l.converged.frame >= 0 ? nlohmann::json(l.converged.frame) : nlohmann::json(nullptr)},
              {"not_converged", l.converged.why},
              {"non_finite", l.nonFinite},
              {"ms_per_frame", l.taaMs},
              {"flip_per_frame", l.flipPerFrame}};
        jl["ghosting"] = l.ghostingMeasured ? nlohmann::json(l.ghosting) : nlohmann::json(nullptr);
      }
      jc["lanes"][l.lane] = jl;
    }
    j["cases"].push_back(jc);
  }
  writeFileAtomically(dir / "score.json", j.dump(2) + "\n");
  const std::string md = "# Scorecard\n\nDevice: " + s.device + ". Lanes:\n\n" + laneLegend(s) +
                         "\n" + kFiniteNote +
                         " Every figure but ms/frame is deterministic; ms/frame is a GPU "
                         "timestamp median.\n\n" +
                         scoreMarkdown(s);
  writeFileAtomically(dir / "score.md", md);
  writeFileAtomically(dir / "score.svg", scorePlot(s, true));

  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < s.cases.size(); ++i)
    for (const auto& l : s.cases[i].lanes) {
      std::vector<std::string> row{std::to_string(i), s.cases[i].name, l.lane};
      for (auto& cell : laneCells(s.cases[i], l)) row.push_back(cell);
      rows.push_back(std::move(row));
    }
  std::string lanes;
  for (const auto& l : s.lanes) lanes += (lanes.empty() ? "" : "; ") + l.name + ": " + l.describe;
  report::ReportSection section;
  section.title = "Scorecard";
  section.note = "Each case replayed once per lane (" + lanes +
                 "), all measured against one supersampled reference on " + s.device +
                 ". Ghosting: no_ghosting's worst mean error on mover cases. " + kFiniteNote +
                 " Every figure but ms/frame is deterministic.";
  section.svg = scorePlot(s, false);
  section.tableHtml = report::htmlTable({"#", "case", "lane", "FLIP", "RMSE", "flicker",
                                         "converged at", "ghosting", "non-finite", "ms/frame"},
                                        rows);
  report::writeSectionPage(dir / "score.html", "TAA scorecard", s.device, section);
}

}  // namespace taa::score
