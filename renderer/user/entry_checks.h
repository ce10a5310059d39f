// Rules a compute resolve's entry point must keep that glslang does not enforce, checked on
// its syntax tree in the compiler's child so the message names the file and line. glslang
// turns an HLSL entry's parameters into pipeline inputs: SV_Position, SV_Target, an SV_
// semantic HLSL does not know, or no semantic at all give inputs (or, for a return value, an
// output) a compute stage does not have, and lavapipe crashes on such SPIR-V; a zero in
// [numthreads] divides by zero when the harness sizes its dispatch.
#pragma once

#include <string>

namespace glslang {
class TIntermediate;
}

namespace taa::user {

// Empty, or "FILE:LINE: what is wrong; the fix" for the first broken rule. `file` names the
// shader's own text; `entry` is the HLSL entry point (GLSL's is main).
std::string entryPointProblem(const glslang::TIntermediate& program, const std::string& file,
                              const std::string& entry);

}  // namespace taa::user
