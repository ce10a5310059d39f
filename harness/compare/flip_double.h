// The previous LDR-FLIP implementation: separable passes over whole planes, single-threaded, in
// double. Slower and heavier than flipLdr (flip.h) but simpler; it is kept as the reference the
// fast float code is tested (tests/compare) and benchmarked (bench/) against.
#pragma once

#include "compare/flip.h"

namespace taa::compare {

// The same contract and result as flipLdr, up to float rounding.
FlipResult flipLdrDouble(const Image& referenceSrgb, const Image& testSrgb,
                         const FlipOptions& options = {});

}  // namespace taa::compare
