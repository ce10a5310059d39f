// determinism: rendering the case a second time gives the same output, bit for bit: every
// frame's sha256 (pixelSha256 of the output) in the repeat equals the first run's. Keeps one
// hash per frame, not the images.
#include <map>

#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

class Determinism : public Invariant {
 public:
  void observe(const FrameView& f) override { first_[f.frame] = f.sha256; }

  void observeRepeat(const FrameView& f) override {
    ++repeated_;
    seen_[f.frame] = true;
    const auto it = first_.find(f.frame);
    const bool same = it != first_.end() && !f.sha256.empty() && it->second == f.sha256;
    if (same) return;
    ++mismatches_;
    if (firstBad_ < 0) {
      firstBad_ = f.frame;
      why_ = it == first_.end() ? "the first run has no frame " + std::to_string(f.frame)
             : f.sha256.empty()
                 ? "frame " + std::to_string(f.frame) + " has no hash"
                 : "frame " + std::to_string(f.frame) + ": " + it->second.substr(0, 12) +
                       "... then " + f.sha256.substr(0, 12) + "...";
    }
  }

  Outcome finish() override {
    Outcome o;
    for (const auto& [frame, hash] : first_)
      if (!seen_.count(frame)) {
        ++mismatches_;
        if (firstBad_ < 0 || frame < firstBad_)
          firstBad_ = frame, why_ = "the repeat has no frame " + std::to_string(frame);
      }
    o.values = {{"frames", double(first_.size())},
                {"repeated_frames", double(repeated_)},
                {"mismatches", double(mismatches_)}};
    if (first_.empty() || repeated_ == 0) {
      o.detail = first_.empty() ? "no frames observed" : "the case was not rendered a second time";
      return o;
    }
    o.passed = mismatches_ == 0;
    if (!o.passed) o.values.push_back({"first_mismatch_frame", firstBad_});
    o.detail = o.passed ? "a second render gave identical hashes for all " +
                              std::to_string(first_.size()) + " frame(s)"
                        : std::to_string(mismatches_) +
                              " frame(s) differ in the second render; first: " + why_;
    return o;
  }

 private:
  std::map<int, std::string> first_;
  std::map<int, bool> seen_;
  int repeated_ = 0, mismatches_ = 0, firstBad_ = -1;
  std::string why_;
};

std::unique_ptr<Invariant> makeDeterminism(const spec::CheckedCase&) {
  return std::make_unique<Determinism>();
}

}  // namespace

const InvariantInfo determinism_invariant = {
    "determinism", {.secondRun = true}, Frames::FromFrame, nullptr, nullptr, makeDeterminism};

}  // namespace taa::invariants
