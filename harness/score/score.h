// The scorecard of users' resolves: it replays every case of a library where a resolve
// applies, once per lane (the built-in resolve at its defaults, then each user shader with
// its parameters), all lanes in lockstep against one supersampled reference, and measures
// error (FLIP, RMSE), flicker, convergence, ghosting on mover cases, non-finite output and
// cost. Everything but the cost is a function of the cases, the shaders and their
// parameters, so two scorecards made on lavapipe compare number for number.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/device.h"
#include "api/reference_cache.h"

namespace taa::score {

// One lane as the command line or a lanes file names it.
struct LaneSpec {
  std::string name;       // unique in the scorecard; "default" is the built-in lane
  nlohmann::json taa;     // merged into each case's (dropped) taa section; {}: built-in defaults
  std::filesystem::path shaderRoot;  // taa.shader is relative to it; empty: no user shader
  std::string describe;   // "minimal_clamp.comp alpha=0.2": for the table's legend
};

// "Converged at": the first frame from which the lane's FLIP stays settled, or -1 with the
// reason. Settled means within 10% of the run's fall (the first frame's FLIP minus the level
// of the last quarter) above that level; a lane whose error falls by less than 10% of its
// first frame's, or rises, never converged; nor one still outside the band within the last
// quarter (still falling at the end). A lane whose level is at the reference's floor (FLIP
// at most kFloorFlip against the reference, which scores 0 against itself) converged at the
// first frame from which it stays within the floor band.
struct Convergence {
  int frame = -1;
  std::string why;  // frame -1: "error rose (0.0241 -> 0.0263)", ...
};
inline constexpr double kFloorFlip = 0.001;
inline constexpr double kSettleShare = 0.1;
Convergence convergence(const std::vector<double>& flipPerFrame);

struct LaneScore {
  std::string lane;
  std::string skipped;   // why the lane did not run this case ("" when it did)
  double flip = 0.0;     // mean over the frames of LDR-FLIP's mean, finite samples
  double rmse = 0.0;     // mean over the frames, linear RGB, over finite samples
  double flicker = 0.0;  // mean |tonemapped luma(f) - luma(f-1)|, finite samples
  Convergence converged;
  bool ghostingMeasured = false;
  double ghosting = 0.0;    // no_ghosting's worst mean error, on mover cases
  long long nonFinite = 0;  // output samples that are NaN or infinite, over every frame
  double taaMs = 0.0;       // median per frame of run/timing.h's TAA ms
  std::vector<double> flipPerFrame;
};

struct CaseScore {
  std::string name;
  bool movers = false;  // a mover moves: ghosting is measured
  bool stress = false;  // checks.labels has "stress"
  int frames = 0;
  double referenceFlicker = 0.0;
  std::vector<LaneScore> lanes;  // in the order of Scorecard::lanes
};

struct Scorecard {
  std::vector<LaneSpec> lanes;  // "default" first
  std::string device;
  std::vector<CaseScore> cases;
  std::vector<std::string> skipped;  // "name: why a resolve does not apply"
  ReferenceCacheStats references;    // timing, not a result: not in the scorecard's files
};

struct ScoreOptions {
  std::vector<LaneSpec> lanes;  // the user's lanes; the built-in default is added first
  std::filesystem::path casesDir;
  int maxCases = 0;  // 0: all; --quick takes the first few
  std::function<void(const std::string& caseName, const std::string& lane, int frame, int frames)>
      progress;
};

// A lane of SHADER with "NAME=V,..." parameters (V: a number, true or false), named `name`
// or, if empty, after the shader (and its parameters when `qualify`). UsageError-like
// cases::CaseError on a malformed list.
LaneSpec shaderLane(const std::filesystem::path& shader, const std::string& params,
                    const std::string& name, bool qualify);

// Bounds of a lanes file (docs/trust.md): each lane renders every case, so the count bounds the
// work and the memory of the scorecard (about 0.4 MB of results a lane).
inline constexpr size_t kMaxLanes = 256;
inline constexpr size_t kMaxLaneNameBytes = 100;

// The lanes of a lanes file: {"name": {"shader": "x.hlsl", "shader_params": [...], ...}, ...},
// each a taa section (a sweep preset's "taa" object); shaders relative to the file's folder.
// Throws cases::CaseError naming the file, the lane and the key: over kMaxLanes lanes, a name
// empty, too long or holding a control character, a shader that is not a string.
std::vector<LaneSpec> loadLanes(const std::filesystem::path& file);

// Each case's lanes run as one lanes::LaneRunner, the built-in lane rendering the reference.
// Throws cases::CaseError for a case that does not load, a shader that does not compile or
// two lanes of one name.
Scorecard runScore(Device& device, const ScoreOptions& options);

// score.md, score.json, score.html (with the plot), score.svg.
void writeScorecard(const std::filesystem::path& dir, const Scorecard& s);
std::string scoreMarkdown(const Scorecard& s);

}  // namespace taa::score
