// History reset: a scripted reset frame and a camera cut both discard the history, so that
// frame's output is its own input; the frames around them blend as usual.
#include <gtest/gtest.h>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;

const char* kBase = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"strafe": {"speed": 1.0}},
  "render": {"width": 96, "height": 54},
  "script": {"frames": 12}
})";

const std::vector<int> kHistoryResetAll = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};

RenderOptions currentHistoryReset() {
  RenderOptions o;
  o.captures |= {Capture::Current};
  return o;
}

bool outputIsInput(const FrameRecord& r) {
  return test::rgbIdentical(r.color, test::capturedImage(r, Capture::Current));
}

TEST(EffectHistoryReset, ScriptedResetFrameOutputsTheCurrentFrame) {
  const auto& run = renderOnce(kBase, R"({"script": {"reset_history_at": [5]}})", kHistoryResetAll, currentHistoryReset());
  const auto& plain = renderOnce(kBase, "{}", kHistoryResetAll, currentHistoryReset());
  EXPECT_TRUE(run[5].historyReset);
  EXPECT_TRUE(outputIsInput(run[5]));
  EXPECT_FALSE(outputIsInput(plain[5]));  // without the reset, frame 5 has history
  for (int f : {4, 6, 7}) EXPECT_FALSE(outputIsInput(run[f])) << "frame " << f;
  EXPECT_TRUE(outputIsInput(run[0]));  // frame 0 never has history
}

TEST(EffectHistoryReset, CameraCutOutputsTheCurrentFrame) {
  const auto& run = renderOnce(
      kBase,
      R"({"camera": {"cuts": [{"frame": 7, "position": [3, 2, 4], "target": [0, 0.5, -2]}]}})",
      kHistoryResetAll, currentHistoryReset());
  EXPECT_TRUE(run[7].cameraCut);
  EXPECT_TRUE(run[7].historyReset);
  EXPECT_TRUE(outputIsInput(run[7]));
  for (int f : {6, 8, 9}) EXPECT_FALSE(outputIsInput(run[f])) << "frame " << f;
}

}  // namespace
}  // namespace taa
