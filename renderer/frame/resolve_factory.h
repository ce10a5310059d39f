// The one place that turns a case's mode (spec/taa_modes.h's kModeRules) into the
// temporal resolve the renderer runs.
#pragma once

#include <memory>

#include "api/renderer.h"
#include "frame/pass_plan.h"
#include "passes/resolve_stage.h"
#include "spec/case_spec.h"

namespace taa {

// The case's resolve, or null when its mode runs none (taa.mode off).
std::unique_ptr<ResolveStage> makeResolveStage(vk::Context& ctx, const spec::CaseSpec& spec,
                                               const PassPlan& plan, const RenderOptions& options);

}  // namespace taa
