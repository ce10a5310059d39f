// Whether each of a case's shader_defines can select anything: a keyword that no file of the
// compile names (a typo such as USE_YCOGC for USE_YCOCG) would build the default variant and
// pass silently, a setting accepted and ignored.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace taa::user {

// One message per define whose NAME appears as a whole identifier in none of `files` (the
// shader and every file its compile included, the harness's headers among them), with the
// nearest identifier those files do hold when it is plausibly a typo. Empty when each is used.
// Throws ShaderCompileError when a file cannot be read (as the compile that read it would).
std::vector<std::string> unusedDefineProblems(const std::vector<std::string>& defines,
                                              const std::vector<std::filesystem::path>& files,
                                              const std::string& shader);

}  // namespace taa::user
