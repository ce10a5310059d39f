// `taa-harness coverage`: which values of the resolve's settings (taa.*) and which branches of
// taa_resolve.comp (its specialization constants) the cases reach, and which none does, so the
// next unexercised class of bug shows up before a mutant finds it (docs/mutation.md).
#pragma once

#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

#include "spec/checked_case.h"

namespace taa::cases {

struct CoverageRow {
  std::string key;    // taa.history_filter, or a constant of taa_resolve.comp (kHistoryFilter)
  std::string value;  // catmull_rom_9 / true / default / other / blended; a constant's GLSL name
  std::vector<std::string> cases;  // the cases in which the value is in force, in input order
};

// Every value of every taa.* setting, from the settings table (shaders/common/taa_settings.h):
// taa.mode's values; an enum's values, a switch's true and false, a float's "default" and
// "other" (any other value) wherever the case's mode and the key's rule make the setting
// count; taa.moving's floats "blended" where the case gives them a moving value of their own,
// and its ramp keys "default"/"other"; taa.shader "set". A value no case reaches is a row
// without cases.
std::vector<CoverageRow> settingValueCoverage(const std::vector<spec::CheckedCase>& cases);

// Every value of every specialization constant of taa_resolve.comp, from each case's trace of
// the constants in force (its run log's "taa_resolve spec constants:" line, as `run` writes
// it into results.json); `logs` maps a case's name to its log. The log shows the history
// pipeline; the no-history one (frame 0, cuts, resets) differs from it in kHasHistory only,
// so every traced case reaches kHasHistory 0 too.
// The specialization constants a run log traces ("taa_resolve spec constants: 0=2 1=1 ..."),
// id -> value; empty when no built-in resolve ran. Throws std::invalid_argument, naming the
// word, when the line holds something other than ID=VALUE whole numbers in int's range.
std::map<int, int> tracedConstants(const std::vector<std::string>& log);

// Each case's log (name, lines, in results.json's order) as `coverage --results` uses it:
// name -> lines, every traced constant checked (tracedConstants). Throws
// std::invalid_argument naming the case's place ("cases[3].log: ...").
std::map<std::string, std::vector<std::string>> checkedRunLogs(
    const std::vector<std::pair<std::string, std::vector<std::string>>>& logs);

std::vector<CoverageRow> resolveBranchCoverage(
    const std::map<std::string, std::vector<std::string>>& logs);

}  // namespace taa::cases
