// The run's HTML report: one self-contained file (inline CSS, JS and SVG, no network access of
// any kind) that sits in the run's output folder next to the PNGs it shows by relative path.
// Per case: status, message, bless command, renderer log, and per checked frame the golden,
// actual and diff images, an A/B split view with a draggable divider and pixel zoom, zoomed crops
// of the worst region, a metrics table, invariant results, per-frame error and frame-time curves
// and per-pass timings. Output is deterministic: the same results give the same bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "run/results.h"

namespace taa::report {

// A section appended after the cases, e.g. the error-versus-run-time sweep. `svg` and `tableHtml`
// are inserted verbatim (make them with svgPlot and htmlTable, which escape their text); `title`
// and `note` are plain text and get escaped.
struct ReportSection {
  std::string title;
  std::string note;
  std::string svg;
  std::string tableHtml;
};

struct ReportExtras {
  std::string title = "TAA golden-image report";
  std::vector<ReportSection> sections;
};

// A <table> whose cells are plain text (escaped here); cells of a row past the header's width
// are dropped, missing ones left empty. Numbers in cells are right-aligned by the report's CSS.
std::string htmlTable(const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows);

// The report as a string; image references are checked against `outputDir` so missing files
// show as a placeholder text instead of a broken image.
std::string renderHtmlReport(const run::RunResults& results, const std::filesystem::path& outputDir,
                             const ReportExtras& extras = {});

// Writes renderHtmlReport to `file` atomically; image paths are relative to file's folder.
// Throws std::runtime_error when the file cannot be written.
void writeHtmlReport(const std::filesystem::path& file, const run::RunResults& results,
                     const ReportExtras& extras = {});

// A page of one section and no cases (a sweep, a scorecard), headed `title`, its device line
// `device`; written as writeHtmlReport writes.
void writeSectionPage(const std::filesystem::path& file, const std::string& title,
                      const std::string& device, const ReportSection& section);

}  // namespace taa::report
