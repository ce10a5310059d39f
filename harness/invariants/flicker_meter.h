// Temporal flicker of a frame sequence, as the sweep and the scorecard report it: the mean
// absolute change of tonemapped luma between consecutive frames, averaged over the pairs
// counted. Both measure their lanes and the reference with it, so their figures compare.
#pragma once

#include <cmath>
#include <utility>

#include "core/image.h"
#include "invariants/invariant_support.h"

namespace taa::invariants {

class FlickerMeter {
 public:
  // Takes the next frame; its change from the previous one counts when `count` is set
  // (frames before a case's from_frame only become the previous frame).
  void add(const Image& frame, bool count) {
    Image luma(frame.width, frame.height, 1);
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x) luma.at(x, y) = tonemappedLuma(frame, x, y);
    if (count && !previous_.data.empty()) {
      double sum = 0.0;
      for (size_t i = 0; i < luma.data.size(); ++i)
        sum += std::fabs(double(luma.data[i]) - double(previous_.data[i]));
      sum_ += luma.data.empty() ? 0.0 : sum / double(luma.data.size());
      ++pairs_;
    }
    previous_ = std::move(luma);
  }

  double mean() const { return pairs_ ? sum_ / pairs_ : 0.0; }

 private:
  Image previous_;
  double sum_ = 0.0;
  int pairs_ = 0;
};

}  // namespace taa::invariants
