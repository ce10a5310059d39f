// A named check over a case's frame sequence. The runner feeds every frame the
// invariant needs, in order, then asks for the outcome. Invariants never touch
// Vulkan: they see read-back images only.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "spec/checked_case.h"

namespace taa::invariants {

// One frame as an invariant sees it; pointers are null for what was not read back.
struct FrameView {
  int frame = 0;
  bool historyReset = false;        // frame 0, camera cut or scripted reset
  const Image* output = nullptr;    // the final output (linear HDR RGBA, output size)
  const Image* reference = nullptr; // supersampled ground truth (output size)
  const Image* current = nullptr;   // the resolve's input colour this frame (render size)
  const Image* ids = nullptr;       // object id, material id, mover flag (render size)
  const Image* velocity = nullptr;  // pixels (render size)
  const Image* resolved = nullptr;      // adaptive mode: the resolve's output before tracing
  const Image* segmentation = nullptr;  // adaptive mode: ADAPTIVE_MASK_* per pixel
  const Image* cmaa = nullptr;      // TSCMAA: the CMAA image (output size)
  const Image* edgeMask = nullptr;  // TSCMAA: TSCMAA_EDGE_* / TSCMAA_TAA bits (output size)
  std::string sha256;               // of the output
};

// What the runner must read back for an invariant.
struct Needs {
  bool reference = false;
  bool current = false;
  bool ids = false;
  bool velocity = false;
  bool tscmaa = false;     // the CMAA image and the edge mask
  bool secondRun = false;  // determinism: the runner renders the case again
  bool adaptive = false;   // the resolve's output before tracing and the segmentation mask
};

struct Outcome {
  std::string name;  // set by the runner from the invariant's table row
  bool passed = false;
  std::string detail;  // one line: what was measured against what bound, where it failed
  std::vector<std::pair<std::string, double>> values;  // measured figures for the report
};

// Built by its row in invariants/registry.h. The runner decides which frames reach
// observe() (checks.from_frame and the row's Frames), so an invariant judges every frame
// it is given.
class Invariant {
 public:
  virtual ~Invariant() = default;
  virtual void observe(const FrameView& frame) = 0;
  // Frames of the second render, for invariants whose Needs ask for one.
  virtual void observeRepeat(const FrameView&) {}
  virtual Outcome finish() = 0;
};

}  // namespace taa::invariants
