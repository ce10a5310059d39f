#include "sweep/sweep.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "api/reference_cache.h"
#include "api/reference_store.h"
#include "api/user_shader.h"
#include "case/case_error.h"
#include "case/case_loader.h"
#include "compare/flip.h"
#include "compare/metrics.h"
#include "invariants/flicker_meter.h"
#include "lanes/lane_runner.h"
#include "run/reference_key.h"
#include "run/timing.h"

namespace taa::sweep {

namespace fs = std::filesystem;

namespace {

// One preset's replay: its own case; the lane runner renders it.
struct Lane {
  std::string name;
  std::string patch;
  cases::LoadedCase loaded;
  invariants::FlickerMeter flicker;
  std::vector<std::string> notApplicable;
  std::string skipped;
};

}  // namespace

SweepResult runSweep(Device& device, const fs::path& caseFile, const cases::Presets& presets,
                     const std::vector<std::string>& names, const SweepOptions& options) {
  const nlohmann::json base = cases::readJsonFile(caseFile);
  std::vector<std::unique_ptr<Lane>> lanes, skippedLanes;
  std::vector<std::string> problems;
  for (const auto& name : names) {
    const auto it = presets.find(name);
    if (it == presets.end()) {
      std::vector<std::string> known;
      for (const auto& [k, v] : presets) known.push_back(k);
      std::string msg = "unknown preset '" + name + "'";
      const std::string guess = cases::closestMatch(name, known);
      msg += guess.empty() ? "" : "; did you mean '" + guess + "'?";
      problems.push_back(msg);
      continue;
    }
    auto lane = std::make_unique<Lane>();
    lane->name = name;
    lane->patch = it->second.dump();
    try {
      lane->loaded = cases::presetLane(base, it->second, caseFile, options.presetsDir, &lane->notApplicable);
    } catch (const cases::CaseError& e) {
      for (const auto& p : e.problems()) problems.push_back("preset " + name + ": " + p);
      continue;
    }
    const auto& spec = lane->loaded.spec;
    if (!spec.taa.shader.empty()) {
      const auto missing = LoadedUserShader(spec).missingCapabilities(spec);
      for (const auto& why : missing) lane->skipped += (lane->skipped.empty() ? "" : "; ") + why;
    }
    (lane->skipped.empty() ? lanes : skippedLanes).push_back(std::move(lane));
  }
  if (!problems.empty()) throw cases::CaseError(problems);
  if (lanes.empty() && !skippedLanes.empty())
    throw cases::CaseError({"every preset's shader lacks what the case needs: " +
                            skippedLanes.front()->skipped});
  if (lanes.empty()) throw cases::CaseError({"no preset given"});
  const auto& first = lanes.front()->loaded.spec;
  for (const auto& l : lanes) {
    const auto& s = l->loaded.spec;
    if (s.render.width != first.render.width || s.render.height != first.render.height ||
        s.script.frames != first.script.frames)
      throw cases::CaseError({"preset " + l->name + " changes the output size or frame count; presets of one "
                              "sweep must share the script and output so one reference serves them all"});
  }

  SweepResult result;
  result.caseName = caseFile.stem().string();
  result.device = device.identity().name;
  result.frames = first.script.frames;
  result.fromFrame = std::clamp(options.fromFrame, 0, first.script.frames - 1);
  result.referenceSamples = first.reference.samples;
  // The frame before the first measured one is read too: flicker needs a predecessor.
  const auto read = [&](int f) { return f + 1 >= result.fromFrame; };
  std::vector<lanes::LaneSetup> setups;
  // Kept across runs: a sweep after a run (or another sweep) of the case renders no reference.
  const auto store = ReferenceStore::fromEnvironment(std::cerr);
  ReferenceCache references(kDefaultReferenceMemoryBytes, store.get());
  for (const auto& l : lanes) {
    lanes::LaneSetup s{&l->loaded.spec, nullptr, {}, read};
    if (setups.empty()) {
      s.options.captures = {Capture::Reference};  // rendered once, for every preset
      run::shareReferences(s.options, &references, l->loaded.spec, device.identity());
    }
    setups.push_back(std::move(s));
  }
  lanes::LaneRunner runner(device, std::move(setups));
  std::vector<PresetResult> out(lanes.size());
  invariants::FlickerMeter referenceFlicker;
  runner.run(
      [&](lanes::LaneFrame& lf) {
        const int f = lf.record.frame;
        if (!read(f)) return;
        const Image& reference = lf.reference;
        // A measured frame's flicker is its change from the frame before, read for it.
        if (lf.lane == 0) referenceFlicker.add(reference, f >= result.fromFrame);
        lanes[lf.lane]->flicker.add(lf.record.color, f >= result.fromFrame);
        if (f < result.fromFrame) return;
        auto& p = out[lf.lane];
        p.rmsePerFrame.push_back(compare::computeMetrics(reference, lf.record.color).rmse);
        p.flipPerFrame.push_back(compare::flipLdrFromHdr(reference, lf.record.color).mean);
      },
      result.fromFrame,
      [&](size_t lane, int f) {
        if (options.progress) options.progress(lanes[lane]->name, f, result.frames);
      });
  for (size_t i = 0; i < lanes.size(); ++i) {
    auto& l = *lanes[i];
    auto& p = out[i];
    p.name = l.name;
    p.patch = l.patch;
    p.rmse = run::mean(p.rmsePerFrame);
    p.flipMean = run::mean(p.flipPerFrame);
    p.flicker = l.flicker.mean();
    p.referenceFlicker = referenceFlicker.mean();
    p.notApplicable = l.notApplicable;
    p.taaMsPerFrame = runner.cost(i).taaMs;
    p.frameMsPerFrame = runner.cost(i).frameMs;
    p.taaMs = run::percentile(p.taaMsPerFrame, 50.0);
    p.frameMs = run::percentile(p.frameMsPerFrame, 50.0);
    for (const auto& line : runner.log(i))
      if (line.rfind("pass ", 0) == 0) p.passes.push_back(line.substr(5));
  }
  for (const auto& l : skippedLanes) {
    PresetResult p;
    p.name = l->name;
    p.patch = l->patch;
    p.skipped = l->skipped;
    out.push_back(std::move(p));
  }
  result.presets = std::move(out);
  if (store) store->trim();
  return result;
}

}  // namespace taa::sweep
