// Which case file a golden set belongs to. A set's folder is named after the case's file name
// (goldens/NAME), so two case files of one name in sibling folders (a/same.json, b/same.json)
// share one folder: without this, blessing one replaced the other's goldens, and running one
// read as the other's case "changed since its goldens were blessed".
#pragma once

#include <filesystem>
#include <string>

#include "golden/manifest.h"

namespace taa::golden {

// What a manifest records as "case_file": the case file's folder name and file name
// ("cases/foo.json"), the part that tells two such files apart.
std::string caseFileLabel(const std::filesystem::path& caseFile);

// Whether `label` is one caseFileLabel can give: one or two path components, neither empty,
// "." or "..", no NUL, at most 512 bytes (a forged manifest must not name any other path).
bool validCaseFileLabel(const std::string& label);

// Empty, or why `caseFile` must not use the set under `root` that `m` describes: `root` lies
// beside the case's folder (the default goldens folder), the manifest names another case file,
// and that file still exists there (one that is gone was moved or renamed, and its set passes
// to the case now using it). Goldens given from elsewhere are not checked.
std::string otherCaseProblem(const Manifest& m, const std::filesystem::path& root,
                             const std::filesystem::path& caseFile);

}  // namespace taa::golden
