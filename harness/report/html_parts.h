// Internal pieces of the HTML report, split by section so each file stays small.
#pragma once

#include <filesystem>
#include <string>

#include "run/results.h"

namespace taa::report::detail {

extern const char* const kReportCss;
extern const char* const kReportJs;

// "PASS", "FAIL", ...: the label that carries the status without colour.
std::string caseLabel(run::CaseStatus s);
std::string frameLabel(run::FrameStatus s);
// CSS class of a status colour: "st-pass", "st-no_golden", ...
std::string caseClass(run::CaseStatus s);
std::string frameClass(run::FrameStatus s);

bool imageExists(const std::filesystem::path& outputDir, const std::string& relative);
// An <img> for a file beside the report, or a placeholder naming what is missing.
std::string imageOrPlaceholder(const std::filesystem::path& outputDir, const std::string& relative,
                               const std::string& what, const std::string& cssClass);

std::string renderCase(const run::CaseResult& c, size_t index, const std::string& runFingerprint,
                       const std::filesystem::path& outputDir);

// Whether the summary offers the case for `bless --from`: failing or stale, with a case file.
bool blessable(const run::CaseResult& c);
// The summary row's golden, actual and diff thumbnails of the case's first differing frame,
// linked to where the case shows it (`id`: the case section's id).
std::string firstDifferenceThumbs(const run::CaseResult& c, const std::string& id,
                                  const std::filesystem::path& outputDir);
std::string blessCheckbox(const run::CaseResult& c);
// The reason and folder fields and the command the page's script builds. The folder is not
// written into the page: the script takes the one the page was opened from (file://), so the
// report stays a function of the results, and a report unpacked from a CI artifact names the
// folder it was unpacked to.
std::string blessPanel();

std::string renderFrame(const run::FrameComparison& f, const std::string& id,
                        const std::filesystem::path& outputDir);

}  // namespace taa::report::detail
