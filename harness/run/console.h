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

// " (worst: cell 2/255 at frame 7, channel mean 0.0004 at frame 3)" for a signature check (a
// measure that never rose above zero: "no cell differs"; neither: " (no difference)"), else "".
std::string sequenceWorst(const CaseResult::SequenceCheck& q);

}  // namespace taa::run
