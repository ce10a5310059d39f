#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>

#include "case/coverage.h"
#include "case/resolve_lines.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/batch_args.h"
#include "cli/options.h"
#include "run/run_folder.h"

namespace taa::cli {

namespace {

const char* kCoverageUsage =
    "taa-harness coverage CASE|DIR... [--results FILE] [--json] [--fail-on-holes]\n"
    "  for every value of every taa.* setting (the settings table), the cases in which it is in\n"
    "  force; with --results (a results.json of `taa-harness run` over the same cases), also\n"
    "  every value of every specialization constant of taa_resolve.comp, from each case's\n"
    "  trace of the constants in force, and the source lines of taa_resolve.comp and its\n"
    "  includes that no case's specialization runs. Values and lines no case reaches are\n"
    "  listed last as holes.\n"
    "  --fail-on-holes: exit 1 when there is one.";

// Each case's log from a results.json, read through the one reader of a run's folder (inside
// it after resolving links, regular: a FIFO is refused, never waited on; bounded; every key of
// the format). A traced constant that is no number is bad input naming the file and the key.
std::map<std::string, std::vector<std::string>> runLogs(const std::string& file) {
  const std::string fix = "run `taa-harness run CASES --out DIR` and pass DIR/results.json";
  const run::RunResults results = run::RunFolder::ofResultsFile(file).readResults(fix);
  std::vector<std::pair<std::string, std::vector<std::string>>> logs;
  for (const auto& c : results.cases) logs.emplace_back(c.name, c.log);
  try {
    return cases::checkedRunLogs(logs);
  } catch (const std::invalid_argument& e) {
    throw UsageError("--results " + file + ": " + e.what() +
                     "; pass the results.json that `run` writes");
  }
}

size_t printSection(const std::string& title, const std::vector<cases::CoverageRow>& rows) {
  std::cout << title << "\n";
  size_t holes = 0;
  for (const auto& r : rows) {
    std::string label = r.key + "=" + r.value;
    std::cout << "  " << label << std::string(label.size() < 44 ? 44 - label.size() : 1, ' ')
              << r.cases.size() << " ";
    for (size_t i = 0; i < r.cases.size() && i < 4; ++i) std::cout << (i ? ", " : "") << r.cases[i];
    if (r.cases.size() > 4) std::cout << ", ...";
    std::cout << "\n";
    holes += r.cases.empty();
  }
  return holes;
}

// A run of consecutive code lines of one file that no case reaches, for printing.
struct Unreached {
  std::string file;
  int first, last, lines;
};

// The path below the shader folder (shaders/taa/rectify.glsl), as a developer reads it.
std::string shaderPath(const std::string& file) {
  const auto at = file.rfind("/shaders/");
  return at == std::string::npos ? file : file.substr(at + 1);
}

// Consecutive code lines (no reached code line between them) join one range.
std::vector<Unreached> unreachedRanges(const std::vector<cases::SourceLine>& lines) {
  std::vector<Unreached> out;
  bool open = false;
  for (const auto& l : lines) {
    if (!l.cases.empty()) {
      open = false;
      continue;
    }
    const std::string file = shaderPath(l.file);
    if (open && out.back().file == file) {
      out.back().last = l.line;
      ++out.back().lines;
    } else {
      out.push_back({file, l.line, l.line, 1});
    }
    open = true;
  }
  return out;
}

std::string rangeName(const Unreached& r) {
  return r.file + ":" + std::to_string(r.first) +
         (r.last != r.first ? "-" + std::to_string(r.last) : "");
}

nlohmann::json rowsJson(const std::vector<cases::CoverageRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows)
    out.push_back({{"key", r.key}, {"value", r.value}, {"cases", r.cases}});
  return out;
}

}  // namespace

int cmdCoverage(const Args& args) {
  const auto a = parseArgs(args, {"--json", "--fail-on-holes"}, {"--results"}, kCoverageUsage);
  if (a.positional.empty())
    throw UsageError(std::string("no case given\nusage: ") + kCoverageUsage);
  const run::CaseBatch batch = loadBatch(a.positional, "");
  std::vector<spec::CheckedCase> specs;
  for (const auto& c : batch.cases) specs.push_back(c.spec);
  const auto settings = cases::settingValueCoverage(specs);
  std::vector<cases::CoverageRow> branches;
  std::vector<cases::SourceLine> lines;
  if (a.values.count("--results")) {
    auto logs = runLogs(a.value("--results"));
    std::map<std::string, std::vector<std::string>> ours;  // the run's cases among the given ones
    for (const auto& s : specs)
      if (logs.count(s.name)) ours[s.name] = std::move(logs[s.name]);
    std::map<std::string, std::map<int, int>> constants;
    for (const auto& [name, log] : ours)
      if (auto traced = cases::tracedConstants(log); !traced.empty())
        constants[name] = std::move(traced);
    branches = cases::resolveBranchCoverage(ours);
    lines = cases::resolveLineCoverage(cases::loadResolveWithLines(), constants);
  }
  const auto unreached = unreachedRanges(lines);
  std::vector<std::string> holes;
  for (const auto& r : settings)
    if (r.cases.empty()) holes.push_back(r.key + "=" + r.value);
  for (const auto& r : branches)
    if (r.cases.empty()) holes.push_back(r.key + "=" + r.value);
  for (const auto& r : unreached) holes.push_back(rangeName(r));
  for (const auto& l : lines)
    if (l.partly) holes.push_back(shaderPath(l.file) + ":" + std::to_string(l.line) + " (in part)");
  if (a.has("--json")) {
    nlohmann::json j = {
        {"cases", specs.size()}, {"settings", rowsJson(settings)}, {"holes", holes}};
    if (a.values.count("--results")) {
      j["resolve_constants"] = rowsJson(branches);
      nlohmann::json jl = nlohmann::json::array();
      for (const auto& l : lines)
        jl.push_back({{"file", shaderPath(l.file)},
                      {"line", l.line},
                      {"cases", l.cases},
                      {"in_part", l.partly}});
      j["resolve_lines"] = jl;
    }
    std::cout << j.dump(1) << "\n";
  } else {
    printSection("taa.* setting values in force (" + std::to_string(specs.size()) + " cases):",
                 settings);
    if (a.values.count("--results"))
      printSection("taa_resolve.comp specialization constants in force (traced in " +
                       a.value("--results") + "):",
                   branches);
    if (a.values.count("--results")) {
      size_t reached = 0, partly = 0;
      for (const auto& l : lines) {
        reached += !l.cases.empty();
        partly += l.partly;
      }
      std::cout << "taa_resolve.comp source lines with code: " << lines.size()
                << ", run by some case: " << reached << " (" << partly
                << " of them in part), by none: " << lines.size() - reached << "\n";
      for (const auto& r : unreached)
        std::cout << "  " << rangeName(r) << " (" << r.lines << " line" << (r.lines > 1 ? "s" : "")
                  << " with code)\n";
      for (const auto& l : lines)
        if (l.partly)
          std::cout << "  " << shaderPath(l.file) << ":" << l.line
                    << " in part: its condition runs, what it guards in no case\n";
    } else
      std::cout << "(shader branches: pass --results DIR/results.json of a `taa-harness run` over "
                   "these cases)\n";
    std::cout << "holes: " << holes.size() << (holes.empty() ? "" : ":");
    for (const auto& h : holes) std::cout << " " << h;
    std::cout << "\n";
  }
  return a.has("--fail-on-holes") && !holes.empty() ? kRegression : kPass;
}

}  // namespace taa::cli
