// The run's closing line is what a developer reads to see what a change cost and whether the
// reference cache worked: each figure must come from its own counter.
#include <gtest/gtest.h>

#include <string>

#include "run/batch_runner.h"

namespace taa::throughput_line_test {

run::BatchOutcome outcomeOfEightFrames() {
  run::BatchOutcome o;
  o.results.cases.resize(2);
  o.results.cases[0].framesRendered = 3;
  o.results.cases[1].framesRendered = 5;
  o.workers = 2;
  o.pipelinesCreated = 4;
  o.pipelinesReused = 6;
  o.referencesRendered = 1;
  o.referencesFromDisk = 2;
  o.referencesReused = 7;
  return o;
}

TEST(ThroughputLine, SaysEachCounterOnce) {
  const std::string line = run::throughputLine(outcomeOfEightFrames(), 4.0, run::cpuTimes());
  EXPECT_NE(line.find("run: 8 frames in 4.0 s (2.0 frames/s)"), std::string::npos) << line;
  EXPECT_NE(line.find("with 2 workers; pipelines: 4 compiled, 6 reused; references: 1 rendered, "
                      "2 from disk, 7 reused"),
            std::string::npos)
      << line;
}

TEST(ThroughputLine, NoWallTimeGivesNoRateRatherThanADivisionByZero) {
  const std::string line = run::throughputLine(outcomeOfEightFrames(), 0.0, run::cpuTimes());
  EXPECT_NE(line.find("8 frames in 0.0 s (0.0 frames/s)"), std::string::npos) << line;
  EXPECT_NE(line.find("CPU/wall 0.00 with"), std::string::npos) << line;
}

}  // namespace taa::throughput_line_test
