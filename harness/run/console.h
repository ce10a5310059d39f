// Line-per-check console output: what CI logs show and what people grep.
#pragma once

#include <ostream>

#include "run/results.h"

namespace taa::run {

// One line per checked frame and per invariant, then the case's verdict.
void printCase(std::ostream& out, const CaseResult& c);

// "summary: N cases, ..." with the failing names.
void printSummary(std::ostream& out, const RunResults& r, double seconds);

bool caseFailed(const CaseResult& c);

}  // namespace taa::run
