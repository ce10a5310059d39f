// A user's loose uniforms (user_interface.h's UserUniform: HLSL's $Global, or a GLSL block at
// TAA_USER_BINDING_PARAMS) filled by member name from taa.shader_params: a scalar from a
// number (or true/false), a vector or matrix from a list of numbers in the order the shader
// indexes it. Members no entry names stay zero, and the run log says which.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spec/case_spec.h"
#include "user/user_interface.h"

namespace taa::user {

// The 32 bits a value of type `t` takes for the one number `v`, or why it cannot ("an int
// takes a whole number ..."). `boolAsNumber`: HLSL's bool in a uniform block is a uint,
// which takes true and false as 1 and 0.
std::string scalarBits(ParamType t, const spec::NumberOrBool& v, uint32_t& bits,
                       bool boolAsNumber = false);

// Empty, or why `v` does not fit member `m`, naming its type and what it takes.
std::string uniformValueProblem(const UserUniform& m, const spec::NumberOrBool& v);

// The block's bytes (u.uniformBytes) with each member taa.shader_params sets (validated
// beforehand) written at its offset; every other byte zero.
std::vector<uint8_t> userUniformBytes(const spec::TaaSpec& taa, const UserInterface& u);

// The run log's line: "loose uniforms $Global (96 bytes): _Sharpness=0.5 (float),
// _Blend=[1, 0, 0, 1] (float4); zero, not set: _Unused (float3)"; "" without a block.
std::string describeUserUniforms(const spec::TaaSpec& taa, const UserInterface& u);

}  // namespace taa::user
