// Stress pass: writes NaN or +-Inf into chosen pixels of the rendered colour on
// chosen frames, before anything reads it.
#pragma once

#include "common/shared.h"
#include "spec/case_spec.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// The pass's push constants: up to 8 pixels two to a vec4, the count and the value; the slots
// past the count stay zero.
gpu::InjectPush makeInjectPush(const spec::InjectSpec& inject);

class InjectPass {
 public:
  InjectPass(vk::Context& ctx, const spec::CaseSpec& spec);
  bool appliesTo(int frame) const;
  void record(VkCommandBuffer cmd, vk::Image& color);

 private:
  vk::Context& ctx_;
  const spec::CaseSpec& spec_;
  vk::Pipeline pipeline_;
};

}  // namespace taa
