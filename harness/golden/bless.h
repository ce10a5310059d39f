// Blessing: turning a case's current frames into its goldens, with the record of why.
#pragma once

#include <filesystem>
#include <map>
#include <string>

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

// The manifest for blessing `frames` of `loaded`, carrying the previous manifest's
// record into its history.
Manifest makeManifest(const cases::LoadedCase& loaded, const Environment& env, const std::map<int, Image>& frames,
                      const std::string& reason, const Manifest* previous);

}  // namespace taa::golden
