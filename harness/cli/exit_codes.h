// The harness's exit codes, as documented in README.md and relied on by ci/bisect.sh.
#pragma once

namespace taa::cli {
enum ExitCode : int {
  kPass = 0,         // every check passed
  kRegression = 1,   // a golden comparison or invariant failed
  kBadInput = 2,     // a case file, track, scene or argument is wrong
  kEnvironment = 3,  // no Vulkan device, missing shaders or dependency
};
}  // namespace taa::cli
