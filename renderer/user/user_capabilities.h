// What a user's resolve declares it can run (common/user_frame.h's TAA_USER_CAPABILITIES:
// upsampling, dynamic resolution), read from the pragmas its headers' TAA_SUPPORTS_* macros
// write, and what a case needs of it. A case needing what its shader does not declare is
// refused by run (exit 2) and skipped by score and sweep, naming the capability and the fix.
#pragma once

#include <string>
#include <vector>

#include "common/user_frame.h"
#include "spec/case_spec.h"

namespace taa::user {

struct CapabilityInfo {
  const char* name;   // "upsampling": what taa.shader's capabilities are called
  const char* macro;  // "TAA_SUPPORTS_UPSAMPLING": what a shader defines before the include
  const char* doc;
};

#define TAA_USER_CAPABILITY_INFO(name, macro, doc) {#name, #macro, doc},
inline constexpr CapabilityInfo kCapabilities[] = {
    TAA_USER_CAPABILITIES(TAA_USER_CAPABILITY_INFO)};
#undef TAA_USER_CAPABILITY_INFO

// The capabilities a shader's preprocessed text declares: its `#pragma taa_supports(NAME)`
// lines, sorted and unique. Throws ShaderCompileError naming `file` for an unknown NAME.
std::vector<std::string> declaredCapabilities(const std::string& preprocessed,
                                              const std::string& file);

// Why the case cannot run on a shader declaring `declared`: one sentence per capability it
// needs and the shader lacks ("the case upsamples (render.upsample 2): ..."), empty if none.
std::vector<std::string> missingCapabilities(const spec::CaseSpec& spec,
                                             const std::vector<std::string>& declared,
                                             const std::string& shader);

}  // namespace taa::user
