#include "score/score.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "api/reference_store.h"
#include "api/user_shader.h"
#include "case/case_error.h"
#include "case/case_loader.h"
#include "compare/flip.h"
#include "compare/metrics.h"
#include "core/input_file.h"
#include "invariants/flicker_meter.h"
#include "invariants/registry.h"
#include "lanes/lane_runner.h"
#include "run/reference_key.h"
#include "run/timing.h"
#include "spec/taa_modes.h"

namespace taa::score {

namespace fs = std::filesystem;

namespace {

// One lane's case and what it measures; the lane runner renders it.
struct ScoreLane {
  LaneScore score;
  cases::LoadedCase loaded;
  std::unique_ptr<invariants::Invariant> ghosting;
  invariants::FlickerMeter flicker;
};

// Why no resolve can stand in for this case's, or "".
std::string notApplicable(const spec::CheckedCase& s) {
  if (!spec::modeRule(s.taa.mode).standIn)
    return std::string("taa.mode is ") + spec::enumToString(s.taa.mode);
  if (s.debug.output != spec::DebugOutput::None) return "it shows a debug view";
  return {};
}

// The case with its resolve settings and checks dropped and the lane's taa section merged
// in: every lane starts from the built-in defaults, and nothing in the case refuses a lane.
cases::LoadedCase laneCase(const nlohmann::json& base, const fs::path& file, const LaneSpec& lane) {
  nlohmann::json j = base;
  j.erase("taa");
  j.erase("checks");
  if (!lane.taa.empty()) j["taa"] = lane.taa;
  cases::LaneParse parse;
  parse.shaderRoot = lane.shaderRoot;
  parse.capabilitiesUnchecked = true;
  try {
    return cases::parseCase(j.dump(2), file, parse);
  } catch (const cases::CaseError& e) {
    std::vector<std::string> problems;
    for (const auto& p : e.problems()) problems.push_back("lane " + lane.name + ": " + p);
    throw cases::CaseError(problems);
  }
}

bool hasLabel(const spec::CheckedCase& s, const char* label) {
  return std::find(s.checks.labels.begin(), s.checks.labels.end(), label) != s.checks.labels.end();
}

// The output with every pixel holding a non-finite RGB sample given the reference's, so the
// error columns measure the finite samples; `nonFinite` counts the non-finite samples (all
// channels), `finitePixels` the pixels kept.
Image finiteOnly(const Image& out, const Image& reference, long long& nonFinite, size_t& finitePixels) {
  Image f = out;
  finitePixels = 0;
  for (size_t p = 0; p < out.pixelCount(); ++p) {
    bool bad = false;
    for (int c = 0; c < out.channels; ++c) {
      const bool finite = std::isfinite(out.data[p * size_t(out.channels) + size_t(c)]);
      nonFinite += finite ? 0 : 1;
      bad |= !finite && c < 3;
    }
    if (!bad) {
      ++finitePixels;
      continue;
    }
    for (int c = 0; c < std::min(3, out.channels); ++c)
      f.data[p * size_t(out.channels) + size_t(c)] = reference.data[p * size_t(reference.channels) + size_t(c)];
  }
  return f;
}

CaseScore scoreCase(Device& device, ReferenceCache& references, const fs::path& file,
                    const nlohmann::json& base, const ScoreOptions& o,
                    const std::vector<LaneSpec>& specs) {
  std::vector<std::unique_ptr<ScoreLane>> lanes;
  for (const auto& spec : specs) {
    auto lane = std::make_unique<ScoreLane>();
    lane->score.lane = spec.name;
    lane->loaded = laneCase(base, file, spec);
    const auto& s = lane->loaded.spec;
    if (!s.taa.shader.empty())
      for (const auto& why : LoadedUserShader(s).missingCapabilities(s))
        lane->score.skipped += (lane->score.skipped.empty() ? "" : "; ") + why;
    lanes.push_back(std::move(lane));
  }
  const auto& first = lanes.front()->loaded.spec;  // the built-in lane: it runs every case
  CaseScore c;
  c.name = file.stem().string();
  c.frames = first.script.frames;
  c.movers = invariants::inapplicable("no_ghosting", first).empty();
  // The lanes that run; the built-in lane runs every case and renders the one reference.
  std::vector<ScoreLane*> running;
  std::vector<lanes::LaneSetup> setups;
  for (auto& lp : lanes) {
    auto& l = *lp;
    if (!l.score.skipped.empty()) continue;
    lanes::LaneSetup setup{&l.loaded.spec, nullptr, {}, {}};
    if (setups.empty()) {
      setup.options.captures |= {Capture::Reference};
      run::shareReferences(setup.options, &references, l.loaded.spec, device.identity());
    }
    if (c.movers) setup.options.captures |= {Capture::Ids};
    if (c.movers) l.ghosting = invariants::makeInvariant("no_ghosting", l.loaded.spec);
    running.push_back(&l);
    setups.push_back(std::move(setup));
  }
  lanes::LaneRunner runner(device, std::move(setups));
  invariants::FlickerMeter referenceFlicker;
  runner.run(
      [&](lanes::LaneFrame& lf) {
        ScoreLane& l = *running[lf.lane];
        const FrameRecord& r = lf.record;
        const Image& reference = lf.reference;
        if (lf.lane == 0) referenceFlicker.add(reference, r.frame > 0);
        size_t finitePixels = 0;
        const Image finite = finiteOnly(r.color, reference, l.score.nonFinite, finitePixels);
        l.flicker.add(finite, r.frame > 0);
        const double rmse = compare::computeMetrics(reference, finite).rmse;
        // The substituted pixels add no error: scale the mean to the finite pixels alone.
        l.score.rmse += (finitePixels ? rmse * std::sqrt(double(finite.pixelCount()) / double(finitePixels)) : 0.0) /
                        c.frames;
        l.score.flipPerFrame.push_back(compare::flipLdrFromHdr(reference, finite).mean);
        if (l.ghosting && r.frame >= l.loaded.spec.checks.from_frame) {
          invariants::FrameView v = invariants::FrameView::of(r);
          v.set(Capture::Reference, &reference);
          v.output = &finite;
          l.ghosting->observe(v);
        }
      },
      0,
      [&](size_t lane, int f) {
        if (o.progress) o.progress(c.name, running[lane]->score.lane, f, c.frames);
      });
  for (size_t i = 0; i < running.size(); ++i) {
    auto& l = *running[i];
    l.score.flip = run::mean(l.score.flipPerFrame);
    l.score.flicker = l.flicker.mean();
    l.score.converged = convergence(l.score.flipPerFrame);
    l.score.taaMs = run::percentile(runner.cost(i).taaMs, 50.0);
    if (l.ghosting)
      for (const auto& [k, v] : l.ghosting->finish().values)
        if (k == "worst_mean_error") {
          l.score.ghosting = v;
          l.score.ghostingMeasured = true;
        }
  }
  c.referenceFlicker = referenceFlicker.mean();
  for (auto& l : lanes) c.lanes.push_back(std::move(l->score));
  return c;
}

}  // namespace

Scorecard runScore(Device& device, const ScoreOptions& o) {
  Scorecard s;
  s.device = device.identity().name;
  LaneSpec builtin;
  builtin.name = "default";
  builtin.describe = "the built-in resolve at its defaults";
  s.lanes.push_back(builtin);
  std::set<std::string> names{builtin.name};
  for (const auto& l : o.lanes) {
    if (!names.insert(l.name).second)
      throw cases::CaseError({"two lanes are called " + l.name +
                              "; name them apart (--name, or the lanes file's keys)"});
    s.lanes.push_back(l);
  }
  std::vector<std::string> problems;
  const std::vector<fs::path> files = inputFilesIn(o.casesDir, ".json", problems);
  if (!problems.empty()) throw cases::CaseError(problems);
  bool compiled = false;
  // References kept across runs: scoring again after an edit of a shader renders none.
  const auto store = ReferenceStore::fromEnvironment(std::cerr);
  ReferenceCache references(kDefaultReferenceMemoryBytes, store.get());
  for (const auto& file : files) {
    if (o.maxCases > 0 && int(s.cases.size()) >= o.maxCases) break;
    const cases::LoadedCase own = cases::loadCase(file);
    if (const std::string why = notApplicable(own.spec); !why.empty()) {
      s.skipped.push_back(own.spec.name + ": " + why);
      continue;
    }
    const nlohmann::json base = cases::readJsonFile(file);
    // Every lane's shader compiles (or names its error) before anything renders.
    if (!compiled)
      for (const auto& l : s.lanes) laneCase(base, file, l);
    compiled = true;
    s.cases.push_back(scoreCase(device, references, file, base, o, s.lanes));
    // The lanes drop the case's checks; its labels still say what the case is for.
    s.cases.back().stress = hasLabel(own.spec, "stress");
  }
  if (s.cases.empty())
    throw cases::CaseError({o.casesDir.string() +
                            ": no case where a resolve applies (taa.mode full); pass --cases DIR"});
  if (store) store->trim();
  s.references = references.stats();
  return s;
}

}  // namespace taa::score
