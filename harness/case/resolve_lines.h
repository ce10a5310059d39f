// Which source lines of taa_resolve.comp (and of the includes it compiles) keep code under
// the specialization constants some case runs it with: a line that no case's specialization
// keeps is a line no case executes, so no case can catch a bug planted there.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace taa::cases {

struct SourceLine {
  std::string file;  // as glslang named it (the path given at build time)
  int line = 0;
  std::vector<std::string> cases;  // the cases that run some of its code, in name order
  bool partly = false;  // run, but a block of it (a statement after its condition) by no case
};

// `spirv`: taa_resolve.comp compiled with debug line information (OpLine). `constants`: for
// each case, the spec constant values in force (id -> value, as the run log traces them).
// Each case is specialized twice: as traced, and with kHasHistory false (its first frame,
// cuts and resets run that pipeline). Every block of every line carries a marker (a store
// into a buffer of its own); a specialization's constants are folded and its dead branches
// and code removed (SPIRV-Tools), and the markers that survive are the blocks it runs. The
// rows are every line with code in the unspecialized module, in file and line order.
std::vector<SourceLine> resolveLineCoverage(const std::vector<uint32_t>& spirv,
                                            const std::map<std::string, std::map<int, int>>& constants);

// The compiled resolve with line information, from the build's (or install's) shader folder.
std::vector<uint32_t> loadResolveWithLines();

}  // namespace taa::cases
