// bit_stable: in a static scene the history reaches a fixed point. From frame after_frame on
// the output must not change at all: for every frame f > after_frame, sha256(f) equals
// sha256(f - 1). Keeps only the previous hash.
#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

class BitStable : public Invariant {
 public:
  explicit BitStable(const CheckedCase& spec) : after_(spec.checks.bit_stable.after_frame) {}

  void observe(const FrameView& f) override {
    if (f.frame < after_) return;
    if (f.sha256.empty()) {
      if (error_.empty()) error_ = "frame " + std::to_string(f.frame) + " has no hash";
      return;
    }
    if (prevFrame_ >= 0) {
      ++compared_;
      if (f.frame != prevFrame_ + 1 && error_.empty())
        error_ = "frame " + std::to_string(prevFrame_ + 1) + " was not observed";
      if (f.sha256 != prev_) {
        ++changes_;
        if (firstChange_ < 0) firstChange_ = f.frame;
      }
    }
    prev_ = f.sha256;
    prevFrame_ = f.frame;
  }

  Outcome finish() override {
    Outcome o;
    o.values = {{"after_frame", after_},
                {"frames_compared", double(compared_)},
                {"changes", double(changes_)}};
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    if (compared_ == 0) {
      o.detail = "no frame after bit_stable.after_frame " + std::to_string(after_) + " to compare";
      return o;
    }
    o.passed = changes_ == 0;
    if (!o.passed) o.values.push_back({"first_change_frame", firstChange_});
    o.detail = o.passed ? "output unchanged over " + std::to_string(compared_) +
                              " frame(s) after frame " + std::to_string(after_)
                        : "output changed in " + std::to_string(changes_) + " of " +
                              std::to_string(compared_) + " frame(s) after frame " +
                              std::to_string(after_) + "; first at frame " +
                              std::to_string(firstChange_);
    return o;
  }

 private:
  int after_;
  std::string error_, prev_;
  int prevFrame_ = -1, compared_ = 0, changes_ = 0, firstChange_ = -1;
};

std::string bitStableInapplicable(const CheckedCase& spec) {
  const std::string name = "bit_stable";
  const int after = spec.checks.bit_stable.after_frame;
  if (after >= spec.script.frames - 1)
    return name + " compares frames after bit_stable.after_frame " + std::to_string(after) +
           ", but the last frame is " + std::to_string(spec.script.frames - 1) +
           "; lower bit_stable.after_frame or raise script.frames";
  if (auto what = whatMoves(spec); !what.empty())
    return name + " needs a static scene, but " + what +
           "; remove it from checks.invariants or stop the motion";
  for (int r : spec.script.reset_history_at)
    if (r > after)
      return name +
             " needs an undisturbed history, but script.reset_history_at resets it at frame " +
             std::to_string(r) + " after bit_stable.after_frame " + std::to_string(after) +
             "; raise bit_stable.after_frame or move the reset";
  // A moving jitter changes every frame's samples, so the output never settles.
  // (The projection is jittered whatever taa.mode is.)
  if (auto why = jitterVaries(spec); !why.empty())
    return name + " needs an unchanging input, but " + why +
           "; remove it from checks.invariants or set jitter.pattern to none (or jitter.lock)";
  return "";
}

std::unique_ptr<Invariant> makeBitStable(const CheckedCase& spec) {
  return std::make_unique<BitStable>(spec);
}

}  // namespace

const InvariantInfo bit_stable_invariant = {
    "bit_stable", {}, Frames::FromFrame, "bit_stable", bitStableInapplicable, makeBitStable};

}  // namespace taa::invariants
