// Several parameter sets (lanes) of one script replayed in lock-step: frame f of every lane
// before frame f + 1 of any, lane 0 the reference lane, whose supersampled reference (when it
// renders one) every lane of that frame is measured against. The sweep's presets, the
// scorecard's resolves and the report's A/B sides are lanes; one loop serves them, so they read
// frames, share the reference and count the cost alike.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "api/device.h"
#include "api/frame_record.h"
#include "api/render_options.h"
#include "api/scene_loading.h"
#include "run/timing.h"
#include "spec/case_spec.h"

namespace taa::lanes {

struct LaneSetup {
  const spec::CaseSpec* spec = nullptr;  // outlives the runner
  const scene::Scene* scene = nullptr;   // null: built from `spec` and owned by the runner
  RenderOptions options;                 // lane 0 asks for Capture::Reference to share one
  std::function<bool(int frame)> reads;  // the frames whose images are read back; unset: all
};

// One lane's frame as it comes. `reference` is lane 0's reference of this frame (empty when it
// rendered none); lane 0's own callback must leave it in place for the lanes after it.
struct LaneFrame {
  size_t lane = 0;
  FrameRecord& record;
  const Image& reference;
};

// A lane's GPU cost, every frame from the run's `measureFrom` on (run/timing.h's definitions).
struct LaneCost {
  std::vector<double> taaMs, frameMs;
  run::TimingLog passes;
};

class LaneRunner {
 public:
  // Builds each lane's scene (unless given) and renderer, in lane order.
  LaneRunner(Device& device, std::vector<LaneSetup> lanes);
  ~LaneRunner();
  LaneRunner(const LaneRunner&) = delete;
  LaneRunner& operator=(const LaneRunner&) = delete;

  // Replays lane 0's script.frames (the callers see that the lanes agree): for each frame, each
  // lane in order is rendered and handed to `each`; `before(lane, frame)`, when set, runs
  // before each render (progress).
  void run(const std::function<void(LaneFrame&)>& each, int measureFrom = 0,
           const std::function<void(size_t, int)>& before = {});

  size_t size() const { return lanes_.size(); }
  const std::vector<std::string>& log(size_t lane) const;  // the renderer's passes and buffers
  const LaneCost& cost(size_t lane) const;

 private:
  struct Lane;
  std::vector<std::unique_ptr<Lane>> lanes_;
};

}  // namespace taa::lanes
