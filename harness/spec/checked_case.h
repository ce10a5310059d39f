// A case as the harness reads it: the renderer's CaseSpec plus what `taa-harness run` checks.
// Derived rather than wrapped so that harness code reads spec.camera and spec.checks alike,
// while the renderer, handed the CaseSpec part by reference, never sees the checks.
#pragma once

#include "spec/case_spec.h"
#include "spec/checks_spec.h"
#include "spec/report_spec.h"

namespace taa::spec {

struct CheckedCase : CaseSpec {
  ChecksSpec checks;
  ReportSpec report;
};

// The case file's keys: the renderer's sections, then "checks" and "report" (the order
// validate --print and techniques --json list them in).
template <class V>
void fields(V& v, CheckedCase& s) {
  fields(v, static_cast<CaseSpec&>(s));
  v.object("checks", s.checks, Meta{"golden comparison and invariants of taa-harness run", ""});
  v.object("report", s.report,
           Meta{"what the report shows beyond golden against actual: A/B and zoom", ""});
}

}  // namespace taa::spec
