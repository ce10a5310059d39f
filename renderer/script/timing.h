// The script's only clock: frame n happens at n / fps seconds, whatever the
// machine's speed, so every replay sees the same times.
#pragma once

#include "spec/script_spec.h"

namespace taa::script {

inline double frameTime(const spec::TimingSpec& timing, int frame) {
  return static_cast<double>(frame) / static_cast<double>(timing.fps);
}

}  // namespace taa::script
