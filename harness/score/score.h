// The scorecard of a user's resolve: it replays every case of a library where a resolve
// applies, once with the built-in resolve at its defaults and once with the user's shader,
// and measures both against the same supersampled reference: error (FLIP, RMSE), flicker,
// convergence, ghosting on mover cases, non-finite output on the stress cases and cost.
// Everything but the cost is a function of the cases and the shader, so two scorecards made
// on lavapipe compare number for number.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "api/device.h"

namespace taa::score {

struct LaneScore {
  std::string lane;      // "default" (the built-in resolve) or "user"
  double flip = 0.0;     // mean over the frames of LDR-FLIP's mean against the reference
  double rmse = 0.0;     // mean over the frames, linear RGB
  double flicker = 0.0;  // mean |tonemapped luma(f) - luma(f-1)|
  int convergence = 0;   // first frame from which FLIP stays within 10% (+0.001) of its final level
  bool ghostingMeasured = false;
  double ghosting = 0.0;    // no_ghosting's worst mean error, on mover cases
  long long nonFinite = 0;  // output samples that are NaN or infinite, over every frame
  double frameMs = 0.0;     // median per frame of every pass but the raster and the reference
  std::vector<double> flipPerFrame;
};

struct CaseScore {
  std::string name;
  bool movers = false;  // a mover moves: ghosting is measured
  bool stress = false;  // checks.labels has "stress"
  int frames = 0;
  double referenceFlicker = 0.0;
  std::vector<LaneScore> lanes;  // default, user
};

struct Scorecard {
  std::string shader;
  std::string device;
  std::vector<CaseScore> cases;
  std::vector<std::string> skipped;  // "name: why a resolve does not apply"
};

struct ScoreOptions {
  std::filesystem::path shader;
  std::filesystem::path casesDir;
  int maxCases = 0;  // 0: all; --quick takes the first few
  std::function<void(const std::string& caseName, const std::string& lane, int frame, int frames)>
      progress;
};

// Throws cases::CaseError for a case that does not load or a shader that does not compile.
Scorecard runScore(Device& device, const ScoreOptions& options);

// score.md, score.json, score.html (with the plot), score.svg.
void writeScorecard(const std::filesystem::path& dir, const Scorecard& s);
std::string scoreMarkdown(const Scorecard& s);

}  // namespace taa::score
