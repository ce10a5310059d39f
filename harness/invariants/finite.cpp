// finite: no NaN or infinity in any channel of any output pixel, in every frame (the output
// is what the resolve stores as history, so this covers the history too). Every frame is
// checked, warm-up included: a NaN is a defect whenever it appears.
#include <bit>
#include <cmath>
#include <cstdint>

#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

class Finite : public Invariant {
 public:
  void observe(const FrameView& f) override {
    if (!error_.empty()) return;
    if (error_ = requireImage(f, f.output, "output", 1); !error_.empty()) return;
    ++frames_;
    const Image& img = *f.output;
    // Nearly every frame is finite throughout: one branch-free pass over the bits says so, and
    // only a frame that is not is walked pixel by pixel.
    uint32_t nonFinite = 0;
    for (const float v : img.data)
      nonFinite |= uint32_t((std::bit_cast<uint32_t>(v) & 0x7f800000u) == 0x7f800000u);
    if (nonFinite == 0) return;
    long long here = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        bool finite = true;
        for (int c = 0; c < img.channels; ++c) finite = finite && std::isfinite(img.at(x, y, c));
        if (finite) continue;
        if (bad_ == 0)
          firstFrame_ = f.frame, firstX_ = x, firstY_ = y, firstValue_ = describe(img, x, y);
        ++bad_, ++here;
      }
    if (here > 0) ++badFrames_;
  }

  Outcome finish() override {
    Outcome o;
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    o.values = {{"nonfinite_pixels", double(bad_)},
                {"frames_with_nonfinite", double(badFrames_)},
                {"frames", double(frames_)}};
    if (frames_ == 0) {
      o.detail = "no frames observed";
      return o;
    }
    o.passed = bad_ == 0;
    if (o.passed) {
      o.detail = "every output pixel finite in " + std::to_string(frames_) + " frame(s)";
    } else {
      o.values.insert(o.values.end(), {{"frame", firstFrame_}, {"x", firstX_}, {"y", firstY_}});
      o.detail = std::to_string(bad_) + " non-finite pixel(s) in " + std::to_string(badFrames_) +
                 " frame(s); first at frame " + std::to_string(firstFrame_) + " (" +
                 std::to_string(firstX_) + ", " + std::to_string(firstY_) + "): " + firstValue_;
    }
    return o;
  }

 private:
  static std::string describe(const Image& img, int x, int y) {
    std::string s = "(";
    for (int c = 0; c < img.channels; ++c) s += (c ? ", " : "") + num(img.at(x, y, c));
    return s + ")";
  }

  std::string error_;
  int frames_ = 0, badFrames_ = 0;
  long long bad_ = 0;
  int firstFrame_ = -1, firstX_ = -1, firstY_ = -1;
  std::string firstValue_;
};

std::unique_ptr<Invariant> makeFinite(const spec::CheckedCase&) {
  return std::make_unique<Finite>();
}

}  // namespace

const InvariantInfo finite_invariant = {"finite", {}, Frames::All, nullptr, nullptr, makeFinite};

}  // namespace taa::invariants
