// Error against run time: one script replayed with several technique presets, each
// frame compared with the supersampled reference (rendered once, shared by all), and
// each preset's GPU time taken from the timestamp queries.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/device.h"
#include "case/case_loader.h"

namespace taa::sweep {

// Named presets: each a JSON merge patch (RFC 7386) applied to the case file's JSON.
using Presets = std::map<std::string, nlohmann::json>;

// Reads a presets file ({"name": {patch}, ...}); CaseError naming the file on bad input.
Presets loadPresets(const std::filesystem::path& file);

struct PresetResult {
  std::string name;
  std::string patch;          // the preset as compact JSON
  double rmse = 0.0;          // mean over the measured frames, linear RGB against the reference
  double flipMean = 0.0;      // mean over the measured frames of LDR-FLIP's mean
  double flicker = 0.0;       // mean |tonemapped luma(f) - (f-1)|, all pixels
  double referenceFlicker = 0.0;
  double taaMs = 0.0;         // median per frame: every pass but the raster and the reference
  double frameMs = 0.0;       // median per frame: every pass but the reference
  std::vector<double> rmsePerFrame;
  std::vector<double> flipPerFrame;
  std::vector<std::string> passes;  // what ran, from the renderer log
  // The case's invariants this preset cannot meet ("no_ghosting: taa.mode is off ..."): not
  // applicable for this lane (a sweep measures; it judges no invariant).
  std::vector<std::string> notApplicable;
  // Why the lane did not run ("" when it did): its shader lacks a capability the case needs.
  std::string skipped;
};

struct SweepOptions {
  int fromFrame = 0;  // frames before this warm up and are not measured
  // The presets file's folder: a preset's taa.shader that names no file beside the case is
  // looked up there (its includes then stay in that folder).
  std::filesystem::path presetsDir;
  std::function<void(const std::string&, int, int)> progress;  // (preset, frame, frames)
};

struct SweepResult {
  std::string caseName;
  std::string device;
  int frames = 0;
  int fromFrame = 0;
  int referenceSamples = 0;
  std::vector<PresetResult> presets;
};

// The case file's JSON with a preset merged in, parsed as a lane: its checks dropped (the
// invariants it cannot meet go to `notApplicable`), its taa.shader found beside the case or
// else in `presetsDir`, a missing capability left for the caller to skip. CaseError when the
// merged case is invalid.
cases::LoadedCase presetLane(const nlohmann::json& base, const nlohmann::json& patch,
                             const std::filesystem::path& caseFile,
                             const std::filesystem::path& presetsDir,
                             std::vector<std::string>* notApplicable = nullptr);

// Replays `base` once per preset, all presets in lockstep frame by frame, the first
// one also rendering the reference. Throws CaseError when a patched case is invalid.
SweepResult runSweep(Device& device, const std::filesystem::path& caseFile, const Presets& presets,
                     const std::vector<std::string>& names, const SweepOptions& options);

// Writers: sweep.csv (one row per preset), frames.csv (per frame), sweep.md (a markdown
// table, Pareto-optimal rows marked), sweep.svg (FLIP mean against whole-frame ms, the
// Pareto front of those two highlighted) and report.html (plot and table in the report).
void writeSweep(const std::filesystem::path& dir, const SweepResult& r);
std::string markdownTable(const SweepResult& r);

}  // namespace taa::sweep
