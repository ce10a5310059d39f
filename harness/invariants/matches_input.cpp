// matches_input: every output pixel equals the resolve's input colour bit for bit (RGB),
// in every frame. What pass-through and alpha 1 promise: the temporal pass adds nothing.

#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

class MatchesInput : public Invariant {
 public:
  void observe(const FrameView& f) override {
    if (!error_.empty()) return;
    if (!f.output || !f.capture(Capture::Current)) {
      error_ = "frame " + std::to_string(f.frame) + ": no " + (f.output ? "input colour" : "output") + " image";
      return;
    }
    const Image& out = *f.output;
    const Image& in = *f.capture(Capture::Current);
    if (out.width != in.width || out.height != in.height) {
      error_ = "frame " + std::to_string(f.frame) + ": output and input sizes differ";
      return;
    }
    ++frames_;
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const float a = out.at(x, y, c), b = in.at(x, y, c);
          if (sameBits(a, b)) continue;
          if (differing_++ == 0)
            first_ = "frame " + std::to_string(f.frame) + " (" + std::to_string(x) + ", " + std::to_string(y) +
                     ") channel " + std::to_string(c) + ": " + num(a) + " vs input " + num(b);
        }
  }

  Outcome finish() override {
    Outcome o;
    o.detail = error_;
    if (!error_.empty()) return o;
    o.values = {{"differing_samples", double(differing_)}, {"frames", double(frames_)}};
    if (frames_ == 0) {
      o.detail = "no frames observed";
      return o;
    }
    o.passed = differing_ == 0;
    o.detail = o.passed ? "output equals the input colour bit for bit in " + std::to_string(frames_) + " frame(s)"
                        : std::to_string(differing_) + " sample(s) differ; first at " + first_;
    return o;
  }

 private:
  std::string error_;
  std::string first_;
  long long differing_ = 0;
  int frames_ = 0;
};

std::unique_ptr<Invariant> makeMatchesInput(const spec::CheckedCase&) {
  return std::make_unique<MatchesInput>();
}

std::string matchesInputInapplicable(const spec::CheckedCase& spec) {
  const std::string name = "matches_input";
  if (auto r = renderSizeReason(name, spec); !r.empty()) return r;
  if (spec.post.sharpen != spec::Sharpen::None || spec.post.fxaa || spec.post.motion_blur)
    return name + " compares the output with the resolve's input, but a post pass changes one of them; remove "
                  "it from checks.invariants or disable post.*";
  if (spec.debug.output != spec::DebugOutput::None)
    return name + " compares the output with the input, but debug.output replaces the output";
  return "";
}

}  // namespace

const InvariantInfo matches_input_invariant = {
    "matches_input", {.captures = {Capture::Current}}, Frames::FromFrame,
    nullptr,         matchesInputInapplicable,         makeMatchesInput};

}  // namespace taa::invariants
