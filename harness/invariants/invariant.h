// A named check over a case's frame sequence. The runner feeds every frame the
// invariant needs, in order, then asks for the outcome. Invariants never touch
// Vulkan: they see read-back images only.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "api/captures.h"
#include "api/frame_record.h"
#include "core/image.h"
#include "spec/checked_case.h"

namespace taa::invariants {

// One frame as an invariant sees it; images are null for what was not read back.
struct FrameView {
  int frame = 0;
  bool historyReset = false;      // frame 0, camera cut or scripted reset
  const Image* output = nullptr;  // the final output (linear HDR RGBA, output size)
  std::string sha256;             // of the output
  // The captures (api/captures.h: the reference, the resolve's input, ids, ...).
  std::array<const Image*, kCaptureCount> captures{};

  const Image* capture(Capture c) const { return captures[size_t(c)]; }
  void set(Capture c, const Image* image) { captures[size_t(c)] = image; }
  // A rendered frame as the invariants see it: its output (when read, or hashed every frame)
  // and every capture it carries.
  static FrameView of(const FrameRecord& r);
};

// What the runner must read back for an invariant, and whether it renders the case twice.
struct Needs {
  CaptureSet captures;
  bool secondRun = false;  // determinism: the runner renders the case again

  Needs& operator|=(const Needs& o) {
    captures |= o.captures;
    secondRun = secondRun || o.secondRun;
    return *this;
  }
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
