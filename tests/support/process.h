// Running the taa-harness executable from tests, for behaviour that only a fresh
// process shows (driver environment variables, exit codes).
#pragma once

#include <string>

namespace taa::test {

struct ProcessResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Runs `env TAA-HARNESS args` through the shell; env is e.g. "LP_NUM_THREADS=1".
ProcessResult runHarness(const std::string& args, const std::string& env = "");

}  // namespace taa::test
