#include "report/junit.h"

#include <algorithm>

#include "report/text_util.h"

namespace taa::report {

namespace {

// Everything a person needs to see why the case failed, one finding per line.
std::vector<std::string> failureLines(const run::CaseResult& c) {
  std::vector<std::string> lines;
  if (c.firstDifference.frame >= 0)
    lines.push_back("frame " + std::to_string(c.firstDifference.frame) + ": " +
                    c.firstDifference.detail);
  for (const auto& f : c.frames)
    for (const auto& why : f.failures)
      lines.push_back("frame " + std::to_string(f.frame) + ": " + why);
  for (const auto& inv : c.invariants)
    if (!inv.passed) lines.push_back("invariant " + inv.name + ": " + inv.detail);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

}  // namespace

std::string renderJUnit(const run::RunResults& r) {
  size_t failures = 0, errors = 0, skipped = 0;
  double seconds = 0.0;
  for (const auto& c : r.cases) {
    failures += c.status == run::CaseStatus::Fail || c.status == run::CaseStatus::Stale;
    errors += c.status == run::CaseStatus::Error;
    skipped += c.status == run::CaseStatus::NoGolden;
    seconds += c.seconds;
  }
  const std::string counts = " tests=\"" + std::to_string(r.cases.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
                             "\" skipped=\"" + std::to_string(skipped) + "\" time=\"" +
                             formatFixed(seconds, 3) + "\"";
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<testsuites name=\"taa\"" + counts + ">\n";
  s += "<testsuite name=\"taa\"" + counts + ">\n";
  s += "<properties><property name=\"device\" value=\"" + escapeMarkup(r.device) +
       "\"/><property name=\"fingerprint\" value=\"" + escapeMarkup(r.fingerprint) +
       "\"/></properties>\n";
  for (const auto& c : r.cases) {
    s += "<testcase classname=\"taa\" name=\"" + escapeMarkup(c.name) + "\" file=\"" +
         escapeMarkup(c.file) + "\" time=\"" + formatFixed(c.seconds, 3) + "\">\n";
    const std::string firstLine = c.message.substr(0, c.message.find('\n'));
    switch (c.status) {
      case run::CaseStatus::Pass:
        break;
      case run::CaseStatus::Fail:
      case run::CaseStatus::Stale: {
        const auto lines = failureLines(c);
        // A case-level reason (unusable goldens, no goldens under CI) heads the list.
        const std::string body =
            (c.message.empty() ? std::string() : c.message + "\n") + join(lines);
        const bool stale = c.status == run::CaseStatus::Stale;
        const std::string summary = !firstLine.empty() ? firstLine
                                    : lines.empty()
                                        ? std::string(stale ? "golden is stale" : "failed")
                                        : std::to_string(lines.size()) + " failed checks";
        s += "<failure type=\"" + std::string(stale ? "stale" : "golden") + "\" message=\"" +
             escapeMarkup(summary) + "\">" + escapeMarkup(body) + "</failure>\n";
        break;
      }
      case run::CaseStatus::Error:
        s += "<error type=\"error\" message=\"" + escapeMarkup(firstLine) + "\">" +
             escapeMarkup(c.message) + "</error>\n";
        break;
      case run::CaseStatus::NoGolden:
        s += "<skipped message=\"" +
             escapeMarkup(firstLine.empty() ? std::string("no golden") : firstLine) + "\"/>\n";
        break;
    }
    std::string out = c.message.empty() ? "" : c.message + "\n";
    // Which verdict the goldens gave: bit for bit, or within tolerances for want of a positive.
    if (!c.goldenMode.empty())
      out += "golden: " +
             (c.goldenMode == "exact" ? std::string("exact (this environment's positive)")
                                      : "tolerance: no positive for " + c.fingerprint) +
             "\n";
    if (!c.blessCommand.empty()) out += "bless: " + c.blessCommand + "\n";
    if (!out.empty()) s += "<system-out>" + escapeMarkup(out) + "</system-out>\n";
    s += "</testcase>\n";
  }
  s += "</testsuite>\n</testsuites>\n";
  return s;
}

void writeJUnit(const std::filesystem::path& file, const run::RunResults& results) {
  writeFileAtomically(file, renderJUnit(results));
}

}  // namespace taa::report
