#include "sweep/sweep.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "api/renderer.h"
#include "case/case_error.h"
#include "case/case_loader.h"
#include "compare/flip.h"
#include "compare/metrics.h"
#include "invariants/flicker_meter.h"
#include "run/timing.h"
#include "invariants/registry.h"
#include "scene/build_scene.h"
#include "user/user_capabilities.h"
#include "user/user_resolve.h"

namespace taa::sweep {

namespace fs = std::filesystem;

namespace {

// One preset's replay: its own case, scene and renderer.
struct Lane {
  std::string name;
  std::string patch;
  cases::LoadedCase loaded;
  scene::Scene scene;
  std::unique_ptr<Renderer> renderer;
  std::vector<double> taaMs, frameMs;
  invariants::FlickerMeter flicker;
  std::vector<std::string> notApplicable;
  std::string skipped;
};

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / double(v.size());
}

bool isRasterPass(const std::string& pass) { return pass.rfind("gbuffer", 0) == 0; }

}  // namespace

Presets loadPresets(const fs::path& file) {
  const auto j = cases::readJsonFile(file);
  if (!j.is_object()) throw cases::CaseError({file.string() + ": expected an object {\"preset\": {patch}, ...}"});
  Presets out;
  for (const auto& [name, patch] : j.items()) {
    if (!patch.is_object())
      throw cases::CaseError({file.string() + ": " + name + ": a preset is a JSON object merged into the case"});
    out[name] = patch;
  }
  return out;
}

cases::LoadedCase presetLane(const nlohmann::json& base, const nlohmann::json& patch,
                             const fs::path& caseFile, const fs::path& presetsDir,
                             std::vector<std::string>* notApplicable) {
  nlohmann::json merged = base;
  merged.merge_patch(patch);
  const nlohmann::json checks = merged.value("checks", nlohmann::json::object());
  merged.erase("checks");
  cases::LaneParse lane;
  lane.capabilitiesUnchecked = true;
  // A preset's own shader: beside the case as documented, or else beside its presets file.
  if (patch.contains("taa") && patch["taa"].is_object() && patch["taa"].contains("shader") &&
      patch["taa"]["shader"].is_string() && !presetsDir.empty()) {
    const std::string shader = patch["taa"]["shader"].get<std::string>();
    std::error_code ec;
    if (!fs::exists(caseFile.parent_path() / shader, ec) && fs::exists(presetsDir / shader, ec))
      lane.shaderRoot = presetsDir;
  }
  cases::LoadedCase loaded = cases::parseCase(merged.dump(2), caseFile, lane);
  if (notApplicable && checks.contains("invariants") && checks["invariants"].is_array())
    for (const auto& name : checks["invariants"])
      if (name.is_string())
        if (const std::string why = invariants::inapplicable(name.get<std::string>(), loaded.spec);
            !why.empty())
          notApplicable->push_back(name.get<std::string>() + ": " + why);
  return loaded;
}

SweepResult runSweep(Device& device, const fs::path& caseFile, const Presets& presets,
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
      lane->loaded = presetLane(base, it->second, caseFile, options.presetsDir, &lane->notApplicable);
    } catch (const cases::CaseError& e) {
      for (const auto& p : e.problems()) problems.push_back("preset " + name + ": " + p);
      continue;
    }
    const auto& spec = lane->loaded.spec;
    if (!spec.taa.shader.empty()) {
      const auto missing = user::missingCapabilities(spec, loadUserShader(spec).capabilities,
                                                     spec.taa.shader);
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
  for (size_t i = 0; i < lanes.size(); ++i) {
    auto& l = *lanes[i];
    l.scene = scene::buildScene(l.loaded.spec);
    RenderOptions ro;
    if (i == 0)
      ro.captures = {Capture::Reference};  // rendered once; every preset is measured against it
    l.renderer = std::make_unique<Renderer>(device, l.loaded.spec, l.scene, ro);
  }

  SweepResult result;
  result.caseName = caseFile.stem().string();
  result.device = device.identity().name;
  result.frames = first.script.frames;
  result.fromFrame = std::clamp(options.fromFrame, 0, first.script.frames - 1);
  result.referenceSamples = first.reference.samples;
  std::vector<PresetResult> out(lanes.size());
  invariants::FlickerMeter referenceFlicker;
  for (int f = 0; f < result.frames; ++f) {
    // The frame before the first measured one is read too: flicker needs a predecessor.
    const bool read = f + 1 >= result.fromFrame;
    Image reference;
    for (size_t i = 0; i < lanes.size(); ++i) {
      auto& l = *lanes[i];
      if (options.progress) options.progress(l.name, f, result.frames);
      FrameRecord r = l.renderer->renderFrame(f, read);
      double taa = 0.0, all = 0.0;
      for (const auto& [pass, ms] : r.gpuMs) {
        if (pass == "reference") continue;
        all += ms;
        if (!isRasterPass(pass)) taa += ms;
      }
      if (f >= result.fromFrame) {
        l.taaMs.push_back(taa);
        l.frameMs.push_back(all);
      }
      if (!read) continue;
      if (i == 0) reference = r.reference;
      l.flicker.add(r.color, f > result.fromFrame);
      if (f < result.fromFrame) continue;
      out[i].rmsePerFrame.push_back(compare::computeMetrics(reference, r.color).rmse);
      out[i].flipPerFrame.push_back(compare::flipLdrFromHdr(reference, r.color).mean);
    }
    if (read) referenceFlicker.add(reference, f > result.fromFrame);
  }
  for (size_t i = 0; i < lanes.size(); ++i) {
    auto& l = *lanes[i];
    auto& p = out[i];
    p.name = l.name;
    p.patch = l.patch;
    p.rmse = mean(p.rmsePerFrame);
    p.flipMean = mean(p.flipPerFrame);
    p.flicker = l.flicker.mean();
    p.referenceFlicker = referenceFlicker.mean();
    p.notApplicable = l.notApplicable;
    p.taaMs = run::percentile(l.taaMs, 50.0);
    p.frameMs = run::percentile(l.frameMs, 50.0);
    for (const auto& line : l.renderer->log())
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
  return result;
}

}  // namespace taa::sweep
