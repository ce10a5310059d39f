// Error against run time: one script replayed with several technique presets, each
// frame compared with the supersampled reference (rendered once, shared by all), and
// each preset's GPU time taken from the timestamp queries.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "api/device.h"
#include "case/presets.h"

namespace taa::sweep {

struct PresetResult {
  std::string name;
  std::string patch;          // the preset as compact JSON
  double rmse = 0.0;          // mean over the measured frames, linear RGB against the reference
  double flipMean = 0.0;      // mean over the measured frames of LDR-FLIP's mean
  double flicker = 0.0;       // mean |tonemapped luma(f) - (f-1)|, all pixels
  double referenceFlicker = 0.0;
  double taaMs = 0.0;         // median per frame of run/timing.h's TAA ms and frame ms
  double frameMs = 0.0;
  std::vector<double> taaMsPerFrame, frameMsPerFrame;  // the measured frames', as rmsePerFrame
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

// Replays the case once per preset (cases::presetLane), all presets as lanes of one
// lanes::LaneRunner, the first one also rendering the reference. Throws CaseError when a
// patched case is invalid.
SweepResult runSweep(Device& device, const std::filesystem::path& caseFile, const cases::Presets& presets,
                     const std::vector<std::string>& names, const SweepOptions& options);

// Writers: sweep.csv (one row per preset), frames.csv (per frame), sweep.md (a markdown
// table, Pareto-optimal rows marked), sweep.svg (FLIP mean against whole-frame ms, the
// Pareto front of those two highlighted) and report.html (plot and table in the report).
void writeSweep(const std::filesystem::path& dir, const SweepResult& r);
std::string markdownTable(const SweepResult& r);

}  // namespace taa::sweep
