// Blessing: turning a case's current frames into its goldens, with the record of why.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "case/case_loader.h"
#include "core/image.h"
#include "golden/environment.h"
#include "golden/manifest.h"

namespace taa::golden {

// "YYYY-MM-DD" in UTC.
std::string todayUtc();

// The source tree's commit (git rev-parse HEAD), with "-dirty" when it has local
// changes, or "unknown" outside a git checkout.
std::string rendererCommit();

// Every rendered frame's pixel hash and quality signature, in frame order.
struct FrameDigests {
  std::vector<std::string> sha256;
  std::vector<std::string> signatures;
};

// The manifest for blessing `frames` (the stored ones) of `loaded` with the digests of every
// rendered frame, carrying the previous manifest's record into its history. Throws
// std::logic_error when a stored frame's hash disagrees with the digests.
Manifest makeManifest(const cases::LoadedCase& loaded, const Environment& env,
                      const std::map<int, Image>& frames, const FrameDigests& digests,
                      const std::string& reason, const Manifest* previous);

}  // namespace taa::golden
