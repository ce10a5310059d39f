// Subcommands of taa-harness. Each takes the arguments after its name and returns
// an exit code from exit_codes.h.
#pragma once

#include <string>
#include <vector>

namespace taa::cli {

using Args = std::vector<std::string>;

int dispatch(int argc, char** argv);
int cmdValidate(const Args& args);
int cmdTechniques(const Args& args);
int cmdRender(const Args& args);
int cmdRun(const Args& args);
int cmdBless(const Args& args);
int cmdNewCase(const Args& args);
int cmdSweep(const Args& args);
int cmdScore(const Args& args);
int cmdBake(const Args& args);
int cmdCompare(const Args& args);
int cmdCoverage(const Args& args);
int cmdMerge(const Args& args);

}  // namespace taa::cli
