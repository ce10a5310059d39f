// The report's frame: head, run header with the summary, table of contents, cases, extra sections.
#include "report/html_report.h"

#include <algorithm>
#include <array>

#include "report/html_parts.h"
#include "report/text_util.h"

namespace taa::report {

namespace fs = std::filesystem;

namespace detail {

std::string caseLabel(run::CaseStatus s) {
  switch (s) {
    case run::CaseStatus::Pass:
      return "PASS";
    case run::CaseStatus::Fail:
      return "FAIL";
    case run::CaseStatus::Stale:
      return "STALE";
    case run::CaseStatus::NoGolden:
      return "NO GOLDEN";
    case run::CaseStatus::Error:
      return "ERROR";
  }
  return "?";
}

std::string frameLabel(run::FrameStatus s) {
  switch (s) {
    case run::FrameStatus::Exact:
      return "EXACT";
    case run::FrameStatus::WithinTolerance:
      return "WITHIN TOL";
    case run::FrameStatus::Failed:
      return "FAILED";
    case run::FrameStatus::MissingGolden:
      return "NO GOLDEN";
  }
  return "?";
}

std::string caseClass(run::CaseStatus s) {
  return std::string("st-") + run::toString(s);
}
std::string frameClass(run::FrameStatus s) {
  return std::string("st-") + run::toString(s);
}

bool imageExists(const fs::path& outputDir, const std::string& relative) {
  std::error_code ec;
  return !relative.empty() && fs::is_regular_file(outputDir / relative, ec) &&
         fs::file_size(outputDir / relative, ec) > 0;
}

std::string imageOrPlaceholder(const fs::path& outputDir, const std::string& relative,
                               const std::string& what, const std::string& cssClass) {
  const std::string cls = cssClass.empty() ? "" : " class=\"" + cssClass + "\"";
  if (!imageExists(outputDir, relative)) {
    return "<div class=\"missing\">" + escapeMarkup(what) + ": " +
           (relative.empty() ? std::string("no image") : "missing " + escapeMarkup(relative)) +
           "</div>";
  }
  return "<img" + cls + " src=\"" + encodePath(relative) + "\" alt=\"" + escapeMarkup(what) +
         "\" loading=\"eager\">";
}

}  // namespace detail

namespace {

using detail::caseClass;
using detail::caseLabel;

constexpr std::array<run::CaseStatus, 5> kStatuses = {
    run::CaseStatus::Pass, run::CaseStatus::Fail, run::CaseStatus::Stale, run::CaseStatus::NoGolden,
    run::CaseStatus::Error};

std::string header(const run::RunResults& r, const ReportExtras& extras) {
  std::string s = "<header class=\"run\">\n<h1>" + escapeMarkup(extras.title) + "</h1>\n";
  s += "<dl class=\"kv\"><dt>device</dt><dd>" + escapeMarkup(r.device) + "</dd>";
  if (!r.fingerprint.empty())
    s += "<dt>fingerprint</dt><dd>" + escapeMarkup(r.fingerprint) + "</dd>";
  s += "</dl>\n";
  // A report of extra sections only (a sweep) has no cases to summarise.
  if (r.cases.empty()) return s + "</header>\n";
  s += "<div class=\"summary\">";
  s += "<span>" + std::to_string(r.cases.size()) + " cases:</span>";
  for (const auto st : kStatuses) {
    const auto n = std::count_if(r.cases.begin(), r.cases.end(),
                                 [&](const run::CaseResult& c) { return c.status == st; });
    s += "<span data-status=\"" + std::string(run::toString(st)) + "\"><span class=\"badge " +
         caseClass(st) + "\">" + caseLabel(st) + "</span> " + std::to_string(n) + "</span>";
  }
  size_t invPass = 0, invFail = 0, frames = 0, framesFailed = 0;
  for (const auto& c : r.cases) {
    for (const auto& inv : c.invariants) (inv.passed ? invPass : invFail)++;
    frames += c.frames.size();
    for (const auto& f : c.frames) framesFailed += f.status == run::FrameStatus::Failed;
  }
  s += "<span>invariants: " + std::to_string(invPass) + " passed, " + std::to_string(invFail) +
       " failed</span><span>frames: " + std::to_string(frames) + " checked, " +
       std::to_string(framesFailed) + " failed</span></div>\n</header>\n";
  return s;
}

std::string tableOfContents(const run::RunResults& r, const fs::path& dir) {
  const bool bless = std::any_of(r.cases.begin(), r.cases.end(), detail::blessable);
  std::string s = "<nav class=\"toc\"><table><tr>";
  if (bless)
    s += "<th><input type=\"checkbox\" id=\"bless-all\" aria-label=\"tick every failing or "
         "stale case\" title=\"tick every failing or stale case\"></th>";
  s += "<th>status</th><th>case</th><th class=\"num\">failed frames</th>"
       "<th class=\"num\">failed invariants</th><th>message</th>";
  if (bless) s += "<th>first differing frame</th>";
  s += "</tr>\n";
  for (size_t i = 0; i < r.cases.size(); ++i) {
    const auto& c = r.cases[i];
    const std::string id = "case-" + std::to_string(i);
    const auto badFrames = std::count_if(c.frames.begin(), c.frames.end(), [](const auto& f) {
      return f.status == run::FrameStatus::Failed;
    });
    const auto badInvariants = std::count_if(c.invariants.begin(), c.invariants.end(),
                                             [](const auto& inv) { return !inv.passed; });
    // The first line of the message is enough to see what happened; the case has the rest.
    const std::string firstLine = c.message.substr(0, c.message.find('\n'));
    const bool pick = detail::blessable(c);
    s += "<tr>";
    if (bless) s += "<td>" + (pick ? detail::blessCheckbox(c) : std::string()) + "</td>";
    s += "<td><span class=\"badge " + caseClass(c.status) + "\">" + caseLabel(c.status) +
         "</span></td><td><a href=\"#" + id + "\">" + escapeMarkup(c.name) +
         "</a></td><td class=\"num\">" + std::to_string(badFrames) + "/" +
         std::to_string(c.frames.size()) + "</td><td class=\"num\">" +
         std::to_string(badInvariants) + "/" + std::to_string(c.invariants.size()) +
         "</td><td><div class=\"toc-msg\">" + escapeMarkup(firstLine) + "</div></td>";
    if (bless) s += "<td>" + (pick ? detail::firstDifferenceThumbs(c, id, dir) : "") + "</td>";
    s += "</tr>\n";
  }
  s += "</table>\n";
  if (bless) s += detail::blessPanel();
  return s + "</nav>\n";
}

}  // namespace

std::string htmlTable(const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows) {
  // Cells that parse as a number (or inf/nan) are right-aligned like the report's own tables.
  auto numeric = [](const std::string& t) {
    if (t == "inf" || t == "-inf" || t == "nan") return true;
    return !t.empty() && t.find_first_not_of("0123456789.eE+-") == std::string::npos &&
           t.find_first_of("0123456789") != std::string::npos;
  };
  std::string s = "<table class=\"extra-table\"><tr>";
  for (const auto& h : header) s += "<th>" + escapeMarkup(h) + "</th>";
  s += "</tr>\n";
  for (const auto& row : rows) {
    s += "<tr>";
    for (size_t i = 0; i < header.size(); ++i) {
      const std::string cell = i < row.size() ? row[i] : "";
      s +=
          std::string(numeric(cell) ? "<td class=\"num\">" : "<td>") + escapeMarkup(cell) + "</td>";
    }
    s += "</tr>\n";
  }
  return s + "</table>\n";
}

std::string renderHtmlReport(const run::RunResults& r, const fs::path& outputDir,
                             const ReportExtras& extras) {
  std::string s =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>" +
      escapeMarkup(extras.title) + "</title>\n<style>" + detail::kReportCss + "</style>\n</head>\n";
  s += "<body data-case-count=\"" + std::to_string(r.cases.size()) + "\">\n";
  s += header(r, extras);
  if (!r.cases.empty()) s += tableOfContents(r, outputDir);
  for (size_t i = 0; i < r.cases.size(); ++i)
    s += detail::renderCase(r.cases[i], i, r.fingerprint, outputDir);
  for (const auto& extra : extras.sections) {
    s += "<section class=\"extra\">\n<h2>" + escapeMarkup(extra.title) + "</h2>\n";
    if (!extra.note.empty()) s += "<p>" + escapeMarkup(extra.note) + "</p>\n";
    s += extra.svg + extra.tableHtml + "</section>\n";
  }
  s += "<script>" + std::string(detail::kReportJs) + "</script>\n</body>\n</html>\n";
  return s;
}

void writeHtmlReport(const fs::path& file, const run::RunResults& results,
                     const ReportExtras& extras) {
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  writeFileAtomically(file, renderHtmlReport(results, dir, extras));
}

void writeSectionPage(const fs::path& file, const std::string& title, const std::string& device,
                      const ReportSection& section) {
  ReportExtras extras;
  extras.title = title;
  extras.sections.push_back(section);
  run::RunResults noCases;
  noCases.device = device;
  writeHtmlReport(file, noCases, extras);
}

}  // namespace taa::report
