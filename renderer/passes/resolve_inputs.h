// The C++ side of shaders/common/resolve_inputs.h: every image a resolve can sample, as an
// enum, a set, one row of facts each (kResolveInputs) and the images a frame hands a
// resolve (ResolveInputs). The built-in resolve, a user's resolve and the renderer loop
// over the rows; none of them names an input it does not itself sample.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>

#include "common/resolve_inputs.h"
#include "core/enum_set.h"
#include "passes/gbuffer_needs.h"
#include "spec/taa_spec.h"

namespace taa {

namespace vk {
class Image;
}

#define TAA_INPUT_ENUMERATOR(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, \
                             udoc)                                                                \
  cxx,
enum class ResolveInput : uint32_t { TAA_RESOLVE_INPUTS(TAA_INPUT_ENUMERATOR) };
#undef TAA_INPUT_ENUMERATOR

#define TAA_INPUT_COUNT_ONE(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, \
                            udoc)                                                                \
  +1
inline constexpr size_t kResolveInputCount = 0 TAA_RESOLVE_INPUTS(TAA_INPUT_COUNT_ONE);
#undef TAA_INPUT_COUNT_ONE

// A set of inputs: what a setting, a resolve or a user's shader reads.
using ResolveInputSet = EnumSet<ResolveInput>;
static_assert(kResolveInputCount <= 64, "ResolveInputSet holds 64 inputs");

// A setting's `reads` column (common/taa_settings.h): `inputs` when `on`, else none.
constexpr ResolveInputSet readsIf(bool on, std::initializer_list<ResolveInput> inputs) {
  return on ? ResolveInputSet(inputs) : ResolveInputSet{};
}
constexpr ResolveInputSet kReadsNothing(const spec::TaaSpec&) {
  return {};
}

// Where the image of an input comes from.
enum class InputSource {
  Color,    // the resolve's input colour (lit, or motion-blurred)
  Own,      // the stage's own previous output: its history
  GBuffer,  // a G-buffer image (ResolveInputInfo::need)
};

struct ResolveInputInfo {
  ResolveInput input;
  const char* name;  // in the run log and errors: "colour", "prev_depth"
  uint32_t binding;  // taa_resolve.comp's
  bool uintTexels;   // a usampler2D: its stand-in is an R32_UINT image
  VkFormat format;   // what the renderer allocates; UNDEFINED: the stage's own output's
  VkFilter filter;   // the sampler it is read through
  InputSource source;
  bool GBufferNeeds::*need;  // source GBuffer: the image, which the plan allocates
  int userBinding;           // taa_user.h's; -1: a user's shader cannot declare it
  const char* userName;      // "taa_depth"
  const char* userMacro;     // "TAA_USE_DEPTH"; "TAA_USER_ALWAYS": always declared
  const char* userDoc;
};

#define TAA_SOURCE_COLOR InputSource::Color, nullptr
#define TAA_SOURCE_OWN InputSource::Own, nullptr
#define TAA_SOURCE_GBUF(n) InputSource::GBuffer, &GBufferNeeds::n
#define TAA_INPUT_INFO(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, udoc) \
  {ResolveInput::cxx,                                                                             \
   log,                                                                                           \
   bind,                                                                                          \
   std::string_view(#stype)[0] == 'u',                                                            \
   VK_FORMAT_##fmt,                                                                               \
   VK_FILTER_##filter,                                                                            \
   TAA_SOURCE_##src,                                                                              \
   ubind,                                                                                         \
   #uname,                                                                                        \
   #umacro,                                                                                       \
   udoc},
inline constexpr ResolveInputInfo kResolveInputs[] = {TAA_RESOLVE_INPUTS(TAA_INPUT_INFO)};
#undef TAA_INPUT_INFO
#undef TAA_SOURCE_COLOR
#undef TAA_SOURCE_OWN
#undef TAA_SOURCE_GBUF

constexpr const ResolveInputInfo& inputInfo(ResolveInput i) {
  return kResolveInputs[size_t(i)];
}

// Rows in enum order, so inputInfo indexes them; the built-in resolve's bindings unique
// and clear of its own (uniforms, outputs), a user's likewise within taa_user.h.
constexpr bool resolveInputBindingsValid(std::initializer_list<uint32_t> builtinOwn,
                                         std::initializer_list<uint32_t> userOwn) {
  for (size_t a = 0; a < kResolveInputCount; ++a) {
    const ResolveInputInfo& r = kResolveInputs[a];
    if (size_t(r.input) != a) return false;
    for (uint32_t b : builtinOwn)
      if (r.binding == b) return false;
    for (uint32_t b : userOwn)
      if (r.userBinding == int(b)) return false;
    for (size_t o = a + 1; o < kResolveInputCount; ++o) {
      if (kResolveInputs[o].binding == r.binding) return false;
      if (r.userBinding >= 0 && kResolveInputs[o].userBinding == r.userBinding) return false;
    }
  }
  return true;
}

// The G-buffer images a set of inputs reads.
constexpr GBufferNeeds gbufferNeeds(ResolveInputSet reads) {
  GBufferNeeds n;
  for (const ResolveInputInfo& r : kResolveInputs)
    if (r.need && reads.has(r.input)) n.*r.need = true;
  return n;
}

// What a resolve may read this frame, at render size with the top-left renderSize pixels
// valid: one image per input, null where the pass plan allocated none (a stage that reads
// an input says so in its needs(), and never binds a null). Own inputs are the stage's.
struct ResolveInputs {
  std::array<vk::Image*, kResolveInputCount> images{};
  vk::Image*& operator[](ResolveInput i) { return images[size_t(i)]; }
  vk::Image* operator[](ResolveInput i) const { return images[size_t(i)]; }
};

}  // namespace taa
