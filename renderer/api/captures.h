// The images beside the output that the harness can ask a run to read back, one list across
// the renderer/harness wall: an invariant's row names the ones it judges, a score or report
// asks for some, RenderOptions carries the union, the renderer reads them back into the
// FrameRecord under their names and FrameView hands them to the invariants.
//
// A new capturable image is a row here and the pass that makes it: its captures() returns
// {Capture::NAME, image, size} when the run's captures have NAME (PassContext::options, or
// the options a resolve stage is built with). Nothing else names it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "common/shared.h"
#include "core/enum_set.h"

namespace taa {

// X(enumerator, name in FrameRecord::aux and on disk, an integer mask read back as float bit
//   values, what it holds)
#define TAA_CAPTURES(X)                                                                    \
  X(Reference, "reference", false,                                                         \
    "the supersampled reference, output size (rendered for the frames read back only)")    \
  X(Current, "current", false,                                                             \
    "the resolve's input colour, render size (TSCMAA stereo: every eye's, side by side)")  \
  X(Ids, "material_id", false, "object id, material id and mover flag, render size")       \
  X(Velocity, "velocity", false, "motion in render pixels, render size")                   \
  X(Resolved, "taa_resolve", false, "adaptive mode: the resolve's output before tracing")  \
  X(Segmentation, "segmentation", true, "adaptive mode: ADAPTIVE_MASK_* per output pixel") \
  X(Cmaa, "cmaa", false, "TSCMAA: the CMAA image, output size")                            \
  X(EdgeMask, "tscmaa_mask", true, "TSCMAA: TSCMAA_EDGE_* and TSCMAA_TAA bits, output size")

#define TAA_CAPTURE_ENUMERATOR(cxx, name, bits, doc) cxx,
enum class Capture : uint32_t { TAA_CAPTURES(TAA_CAPTURE_ENUMERATOR) };
#undef TAA_CAPTURE_ENUMERATOR

struct CaptureInfo {
  Capture capture;
  const char* name;
  bool bits;
  const char* doc;
};
#define TAA_CAPTURE_INFO(cxx, name, bits, doc) {Capture::cxx, name, bits, doc},
inline constexpr CaptureInfo kCaptures[] = {TAA_CAPTURES(TAA_CAPTURE_INFO)};
#undef TAA_CAPTURE_INFO
inline constexpr size_t kCaptureCount = std::size(kCaptures);

constexpr const CaptureInfo& captureInfo(Capture c) {
  return kCaptures[size_t(c)];
}
constexpr const char* captureName(Capture c) {
  return captureInfo(c).name;
}

using CaptureSet = EnumSet<Capture>;

// The values the mask captures hold, for the harness (which reads no GPU header).
namespace mask {
inline constexpr uint32_t kAdaptiveNone = ADAPTIVE_MASK_NONE;  // the resolve's output stands
inline constexpr uint32_t kAdaptiveFxaa = ADAPTIVE_MASK_FXAA;  // out of history, not traced
inline constexpr uint32_t kTscmaaEdges = TSCMAA_EDGES;         // any TSCMAA_EDGE_* side
inline constexpr uint32_t kTscmaaTaa = TSCMAA_TAA;             // in the TAA share
}  // namespace mask

}  // namespace taa
