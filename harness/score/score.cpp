#include "score/score.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "compare/flip.h"
#include "compare/metrics.h"
#include "core/input_file.h"
#include "core/json_guard.h"
#include "core/output_file.h"
#include "invariants/flicker_meter.h"
#include "invariants/invariant_support.h"
#include "invariants/registry.h"
#include "renderer.h"
#include "run/timing.h"
#include "scene/build_scene.h"
#include "user/glsl_compiler.h"
#include "user/user_resolve.h"

namespace taa::score {

namespace fs = std::filesystem;

namespace {

// One replay of a case: the built-in resolve or the user's.
struct ScoreLane {
  LaneScore score;
  cases::LoadedCase loaded;
  scene::Scene scene;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<invariants::Invariant> ghosting;
  std::vector<double> ms;
  invariants::FlickerMeter flicker;
};

double scoreMean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / double(v.size());
}

// The first frame from which FLIP stays within 10% (plus 0.001) of its level over the last
// quarter of the script: how long the resolve takes to settle, resets included.
int convergenceFrame(const std::vector<double>& flip) {
  if (flip.empty()) return 0;
  const size_t tail = std::max<size_t>(1, flip.size() / 4);
  const double level = scoreMean(std::vector<double>(flip.end() - long(tail), flip.end()));
  const double bound = level * 1.1 + 1e-3;
  int first = int(flip.size());
  for (int f = int(flip.size()) - 1; f >= 0 && flip[size_t(f)] <= bound; --f) first = f;
  return first;
}

// Why the user's resolve cannot stand in for this case's, or "".
std::string notApplicable(const spec::CheckedCase& s) {
  if (s.taa.mode != spec::TaaMode::Full)
    return std::string("taa.mode is ") + spec::enumToString(s.taa.mode);
  if (s.debug.output != spec::DebugOutput::None) return "it shows a debug view";
  return {};
}

nlohmann::json readCaseJson(const fs::path& file) {
  try {
    return nlohmann::json::parse(readInputFile(file, kMaxCaseFileBytes));
  } catch (const InputFileError& e) {
    throw cases::CaseError({e.what()});
  } catch (const nlohmann::json::exception& e) {
    throw cases::CaseError({file.string() + ": not valid JSON (" + jsonErrorWithoutContent(e.what()) + ")"});
  }
}

// The case with its resolve settings and checks dropped: both lanes start from the built-in
// defaults, and nothing in the case can refuse the other lane's resolve.
cases::LoadedCase laneCase(const nlohmann::json& base, const fs::path& file,
                           const fs::path& shader) {
  nlohmann::json j = base;
  j.erase("taa");
  j.erase("checks");
  cases::LoadedCase loaded = cases::parseCase(j.dump(2), file);
  if (!shader.empty()) {
    // The shader is named on the command line, outside the case: its own folder is its root.
    loaded.spec.taa.shader = fs::absolute(shader).string();
  }
  return loaded;
}

bool hasLabel(const spec::CheckedCase& s, const char* label) {
  return std::find(s.checks.labels.begin(), s.checks.labels.end(), label) != s.checks.labels.end();
}

const Image* scoreAux(const FrameRecord& r, const char* name) {
  for (const auto& a : r.aux)
    if (a.name == name) return &a.image;
  return nullptr;
}

CaseScore scoreCase(Device& device, const fs::path& file, const nlohmann::json& base,
                    const ScoreOptions& o) {
  std::vector<std::unique_ptr<ScoreLane>> lanes;
  for (const char* name : {"default", "user"}) {
    auto lane = std::make_unique<ScoreLane>();
    lane->score.lane = name;
    lane->loaded = laneCase(base, file, std::string(name) == "user" ? o.shader : fs::path());
    lanes.push_back(std::move(lane));
  }
  const auto& first = lanes.front()->loaded.spec;
  CaseScore c;
  c.name = file.stem().string();
  c.frames = first.script.frames;
  c.movers = invariants::inapplicable("no_ghosting", first).empty();
  for (size_t i = 0; i < lanes.size(); ++i) {
    auto& l = *lanes[i];
    l.scene = scene::buildScene(l.loaded.spec);
    RenderOptions ro;
    ro.reference = i == 0;  // one reference, shared
    ro.captureIds = c.movers;
    l.renderer = std::make_unique<Renderer>(device, l.loaded.spec, l.scene, ro);
    if (c.movers) l.ghosting = invariants::makeInvariant("no_ghosting", l.loaded.spec);
  }
  invariants::FlickerMeter referenceFlicker;
  for (int f = 0; f < c.frames; ++f) {
    Image reference;
    for (size_t i = 0; i < lanes.size(); ++i) {
      auto& l = *lanes[i];
      if (o.progress) o.progress(c.name, l.score.lane, f, c.frames);
      FrameRecord r = l.renderer->renderFrame(f, true);
      double ms = 0.0;
      for (const auto& [pass, t] : r.gpuMs)
        if (pass != "reference" && pass.rfind("gbuffer", 0) != 0) ms += t;
      l.ms.push_back(ms);
      if (i == 0) reference = r.reference;
      for (float v : r.color.data) l.score.nonFinite += std::isfinite(v) ? 0 : 1;
      l.flicker.add(r.color, f > 0);
      l.score.rmse += compare::computeMetrics(reference, r.color).rmse / c.frames;
      l.score.flipPerFrame.push_back(compare::flipLdrFromHdr(reference, r.color).mean);
      if (l.ghosting && f >= l.loaded.spec.checks.from_frame) {
        invariants::FrameView v;
        v.frame = f;
        v.historyReset = r.historyReset;
        v.output = &r.color;
        v.reference = &reference;
        v.ids = scoreAux(r, "material_id");
        l.ghosting->observe(v);
      }
    }
    referenceFlicker.add(reference, f > 0);
  }
  c.referenceFlicker = referenceFlicker.mean();
  for (auto& lp : lanes) {
    auto& l = *lp;
    l.score.flip = scoreMean(l.score.flipPerFrame);
    l.score.flicker = l.flicker.mean();
    l.score.convergence = convergenceFrame(l.score.flipPerFrame);
    l.score.frameMs = run::percentile(l.ms, 50.0);
    if (l.ghosting) {
      const invariants::Outcome out = l.ghosting->finish();
      for (const auto& [k, v] : out.values)
        if (k == "worst_mean_error") {
          l.score.ghosting = v;
          l.score.ghostingMeasured = true;
        }
    }
    c.lanes.push_back(std::move(l.score));
  }
  return c;
}

}  // namespace

Scorecard runScore(Device& device, const ScoreOptions& o) {
  Scorecard s;
  s.shader = o.shader.string();
  s.device = device.identity().name;
  // The shader must compile before anything renders: its errors are the user's first news.
  try {
    user::CompileOptions co;
    co.root = fs::absolute(o.shader).parent_path();
    const auto compiled = user::compileComputeShader(fs::absolute(o.shader), co);
    user::reflectUserInterface(compiled.spirv, o.shader.string());
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const OutputError*>(&e)) throw;
    throw cases::CaseError({o.shader.string() + ": does not compile:\n" + e.what()});
  }
  std::vector<std::string> problems;
  const std::vector<fs::path> files = inputFilesIn(o.casesDir, ".json", problems);
  if (!problems.empty()) throw cases::CaseError(problems);
  for (const auto& file : files) {
    if (o.maxCases > 0 && int(s.cases.size()) >= o.maxCases) break;
    const cases::LoadedCase own = cases::loadCase(file);
    if (const std::string why = notApplicable(own.spec); !why.empty()) {
      s.skipped.push_back(own.spec.name + ": " + why);
      continue;
    }
    s.cases.push_back(scoreCase(device, file, readCaseJson(file), o));
    // The lanes drop the case's checks; its labels still say what the case is for.
    s.cases.back().stress = hasLabel(own.spec, "stress");
  }
  if (s.cases.empty())
    throw cases::CaseError({o.casesDir.string() +
                            ": no case where a resolve applies (taa.mode full); pass --cases DIR"});
  return s;
}

}  // namespace taa::score
