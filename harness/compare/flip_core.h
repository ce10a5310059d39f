// The fast LDR-FLIP error map (flip.cpp), parameterized by how input samples become linear RGB so
// that LDR-FLIP (sRGB-encoded input) and each exposure of HDR-FLIP (linear input, exposed and
// tonemapped) share one implementation without building intermediate images.
#pragma once

#include "compare/flip.h"

namespace taa::compare::flipdetail {

struct InputMapping {
  enum class Kind {
    Srgb,           // samples are sRGB-encoded: NaN -> 0, clamp to [0, 1], decode
    ExposedToneMap  // samples are linear: times `exposure`, then toneMap, clamped to [0, 1]
  };
  Kind kind = Kind::Srgb;
  float exposure = 1.0f;
  // Per channel (a x^2 + b x + c) / (d x^2 + e x + f), the paper's tone curve family.
  float toneMap[6] = {0, 1, 0, 0, 1, 1};
};

// The per-pixel FLIP error (1 channel) between two images of the same, non-empty shape; the
// caller has validated them. Rows are processed in strips on options.threads threads; every
// pixel's value is the same whatever the strip split or thread count.
Image flipErrorMap(const Image& reference, const Image& test, const InputMapping& mapping,
                   const FlipOptions& options);

}  // namespace taa::compare::flipdetail
