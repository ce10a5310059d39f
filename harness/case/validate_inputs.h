// Case keys that name files or decide what a case writes, checked as classes: every path
// key (present but empty, or holding a NUL or control character: a string the file system
// would truncate and the log would print raw), and the volume of images a case would write.
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "spec/checked_case.h"

namespace taa::cases {

// The most image data one case may write (its output frames and their aux buffers, as
// uncompressed samples): 100,000 frames of 320x180 would be about 20 GB on disk.
inline constexpr uint64_t kMaxCaseOutputBytes = uint64_t(4) << 30;

using KeyProblems = std::vector<std::pair<std::string, std::string>>;

// Every string anywhere in the case JSON with a character below U+0020 other than tab,
// line feed and carriage return, by its key path ("movers[0].gltf").
KeyProblems controlCharacterProblems(const nlohmann::json& root);

// Path keys given but empty (which would silently mean "no file": the built-in scene, the
// built-in resolve).
KeyProblems emptyPathProblems(const spec::CaseSpec& spec, const std::set<std::string>& present);

// Output frames listed twice, and the estimate of what the case writes against
// kMaxCaseOutputBytes, with the figure.
KeyProblems outputVolumeProblems(const spec::CaseSpec& spec);

}  // namespace taa::cases
