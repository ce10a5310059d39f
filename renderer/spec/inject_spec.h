// Stress input: non-finite values written into the rendered colour before the
// resolve, to prove they never reach the history or later frames.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "spec/fields.h"

namespace taa::spec {

enum class InjectValue { Nan, PosInf, NegInf };
TAA_ENUM_NAMES(InjectValue, {InjectValue::Nan, "nan"}, {InjectValue::PosInf, "inf"}, {InjectValue::NegInf, "-inf"})

struct InjectSpec {
  std::vector<int> frames;        // empty: nothing is injected
  std::vector<glm::vec2> pixels;  // render-target pixel coordinates
  InjectValue value = InjectValue::Nan;
};

template <class V>
void fields(V& v, InjectSpec& s) {
  const char* impl = "shaders/inject.comp";
  v.field("frames", s.frames, Range<int>{0, 99999}, Meta{"frames whose rendered colour gets the value", impl});
  v.field("pixels", s.pixels, Meta{"pixels [x, y] of the render target that get it (at most 8)", impl});
  v.field("value", s.value, Meta{"what is written into every channel: nan, inf or -inf", impl});
}

}  // namespace taa::spec
