#include "run/console.h"

#include <cstdio>
#include <string>

#include "compare/metric_table.h"

namespace taa::run {

namespace {
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), f, v);
  return buf;
}
}  // namespace

std::string sequenceWorst(const CaseResult::SequenceCheck& q) {
  if (q.mode != "signature") return "";
  // A frame of -1 means nothing differed: "cell 0/255 at frame -1" would read like a finding.
  if (q.worstCellFrame < 0 && q.worstMeanFrame < 0) return " (no difference)";
  const std::string cell = q.worstCellFrame < 0 ? "no cell differs"
                                                : "cell " + std::to_string(q.worstCell) + "/255 at frame " +
                                                      std::to_string(q.worstCellFrame);
  const std::string mean = q.worstMeanFrame < 0 ? "no channel mean differs"
                                                : "channel mean " + fmt("%.3g", q.worstMean) + " at frame " +
                                                      std::to_string(q.worstMeanFrame);
  return " (worst: " + cell + ", " + mean + ")";
}

bool caseFailed(const CaseResult& c) {
  return c.status != CaseStatus::Pass && c.status != CaseStatus::NoGolden;
}

void printCase(std::ostream& out, const CaseResult& c) {
  // A missing golden is a skip unless it fails the case by itself (CI=true, unusable goldens).
  const bool goldensSkipped = c.goldenStatus == CaseStatus::NoGolden;
  bool invariantFailed = false;
  for (const auto& inv : c.invariants) invariantFailed |= !inv.passed;
  for (const auto& f : c.frames) {
    const bool ok = f.status == FrameStatus::Exact || f.status == FrameStatus::WithinTolerance;
    const bool skipped = f.status == FrameStatus::MissingGolden && goldensSkipped;
    out << (ok ? "PASS " : skipped ? "SKIP " : "FAIL ") << c.name << " frame " << f.frame
        << " golden ";
    if (f.status == FrameStatus::Exact) {
      out << "exact";
    } else if (f.status == FrameStatus::MissingGolden) {
      out << "missing";
    } else {
      out << (f.toleranceMode ? "tolerance" : "exact");
      for (const auto* m : compare::goldenMetrics())
        if (m->summary) out << " " << m->name << " " << fmt("%.3g", f.metrics.*m->golden);
    }
    for (const auto& why : f.failures) out << "; " << why;
    if (!ok && !f.images.diff.empty()) out << " (diff " << f.images.diff << ")";
    out << "\n";
  }
  if (const auto& q = c.sequenceCheck; !q.mode.empty() && c.firstDifference.frame < 0)
    out << "PASS " << c.name << " sequence: " << q.frames << " frames "
        << (q.mode == "exact" ? "identical to this environment's positive"
                              : "within signature tolerance of the nearest positive's")
        << sequenceWorst(q) << "\n";
  if (const auto& d = c.firstDifference; d.frame >= 0) {
    out << "FAIL " << c.name << " frame " << d.frame << " sequence: " << d.detail;
    if (!d.actual.empty()) out << " (actual " << d.actual;
    for (const auto& n : d.goldenNeighbours) out << ", golden frame " << n.frame << " " << n.image;
    if (!d.actual.empty()) out << ")";
    out << "\n";
  }
  for (const auto& inv : c.invariants)
    out << (inv.passed ? "PASS " : "FAIL ") << c.name << " invariant " << inv.name << ": " << inv.detail << "\n";
  // What the run did not do as the input asked (an extension a glTF uses and the loader
  // ignores, a constant the shader never reads) reaches the console, not only the run log.
  for (const auto& line : c.log)
    if (line.rfind("scene note: ", 0) == 0 || line.rfind("user shader note: ", 0) == 0)
      out << "NOTE " << c.name << ": " << line << "\n";
  switch (c.status) {
    case CaseStatus::Pass:
      if (!c.message.empty()) out << "NOTE " << c.name << ": " << c.message << "; refresh with " << c.blessCommand << "\n";
      break;
    case CaseStatus::Stale:
      out << "STALE " << c.name << ": " << c.message << "; if intended: " << c.blessCommand << "\n";
      break;
    case CaseStatus::NoGolden:
      out << "SKIP " << c.name << ": " << c.message << ": " << c.blessCommand
          << " (a skip here; under CI=true a case without goldens fails)\n";
      break;
    case CaseStatus::Error:
      out << "ERROR " << c.name << ": " << c.message << "\n";
      break;
    case CaseStatus::Fail:
      if (goldensSkipped)
        out << "SKIP " << c.name << ": " << c.message << " once its invariants pass\n";
      else if (!c.message.empty())
        out << "FAIL " << c.name << ": " << c.message << "\n";
      // bless refuses a case whose invariants fail: it is no way out of this failure.
      if (invariantFailed)
        out << "HINT " << c.name
            << ": an invariant fails, so bless would refuse the frames; fix the resolve or the "
               "case's checks (bless --force only if the invariant itself is wrong)\n";
      else if (!c.frames.empty() && !c.blessCommand.empty())
        out << "HINT " << c.name << ": if the change is intended, look at the report, then " << c.blessCommand
            << "\n";
      break;
  }
}

void printSummary(std::ostream& out, const RunResults& r, double seconds) {
  int pass = 0, skipped = 0, checks = 0, exact = 0, tolerance = 0;
  std::string failed;
  for (const auto& c : r.cases) {
    checks += int(c.frames.size() + c.invariants.size());
    exact += c.goldenMode == "exact";
    tolerance += c.goldenMode == "tolerance";
    if (c.status == CaseStatus::Pass) {
      ++pass;
    } else if (c.status == CaseStatus::NoGolden) {
      ++skipped;
    } else {
      failed += (failed.empty() ? "" : ", ") + c.name + " (" + toString(c.status) + ")";
    }
  }
  out << "summary: " << r.cases.size() << " cases, " << pass << " pass, " << skipped
      << " skipped (no goldens), " << (r.cases.size() - size_t(pass + skipped)) << " fail; "
      << checks << " checks; goldens: " << exact << " exact, " << tolerance << " by tolerance"
      << (tolerance ? " (no positive for " + r.fingerprint + ")" : "") << "; "
      << fmt("%.1f", seconds) << " s";
  if (!failed.empty()) out << "; failing: " << failed;
  out << "\n";
}

}  // namespace taa::run
