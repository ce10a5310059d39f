#include "lanes/lane_runner.h"

#include "api/renderer.h"

namespace taa::lanes {

struct LaneRunner::Lane {
  LaneSetup setup;
  std::shared_ptr<const scene::Scene> ownScene;
  std::unique_ptr<Renderer> renderer;
  LaneCost cost;
};

LaneRunner::LaneRunner(Device& device, std::vector<LaneSetup> lanes) {
  for (auto& setup : lanes) {
    auto lane = std::make_unique<Lane>();
    lane->setup = std::move(setup);
    const spec::CaseSpec& spec = *lane->setup.spec;
    if (!lane->setup.scene) {
      lane->ownScene = buildCaseScene(spec);
      lane->setup.scene = lane->ownScene.get();
    }
    lane->renderer =
        std::make_unique<Renderer>(device, spec, *lane->setup.scene, lane->setup.options);
    lanes_.push_back(std::move(lane));
  }
}

LaneRunner::~LaneRunner() = default;

void LaneRunner::run(const std::function<void(LaneFrame&)>& each, int measureFrom,
                     const std::function<void(size_t, int)>& before) {
  static const Image none;
  if (lanes_.empty()) return;
  const int frames = lanes_.front()->setup.spec->script.frames;
  for (int f = 0; f < frames; ++f) {
    // Lane 0's record lives through the frame: its reference serves every lane.
    FrameRecord first;
    for (size_t i = 0; i < lanes_.size(); ++i) {
      Lane& l = *lanes_[i];
      if (before) before(i, f);
      FrameRecord r = l.renderer->renderFrame(f, !l.setup.reads || l.setup.reads(f));
      if (f >= measureFrom) {
        l.cost.taaMs.push_back(run::taaMilliseconds(r.gpuMs));
        l.cost.frameMs.push_back(run::frameMilliseconds(r.gpuMs));
        l.cost.passes.add(r.gpuMs);
      }
      if (i == 0) first = std::move(r);
      LaneFrame frame{i, i == 0 ? first : r, first.hasReference ? first.reference : none};
      each(frame);
    }
  }
}

const std::vector<std::string>& LaneRunner::log(size_t lane) const {
  return lanes_.at(lane)->renderer->log();
}

const LaneCost& LaneRunner::cost(size_t lane) const {
  return lanes_.at(lane)->cost;
}

}  // namespace taa::lanes
