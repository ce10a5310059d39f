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
std::string renderFrame(const run::FrameComparison& f, const std::string& id,
                        const std::filesystem::path& outputDir);

}  // namespace taa::report::detail
