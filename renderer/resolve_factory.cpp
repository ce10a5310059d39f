#include "resolve_factory.h"

#include "passes/taa_resolve.h"
#include "passes/tscmaa.h"
#include "spec/taa_modes.h"

namespace taa {

std::unique_ptr<ResolveStage> makeResolveStage(vk::Context& ctx, const spec::CaseSpec& spec,
                                               const PassPlan& plan, const RenderOptions& options) {
  const spec::ModeRule& rule = spec::modeRule(spec.taa.mode);
  if (rule.tscmaa)
    return std::make_unique<TscmaaPass>(ctx, spec, options.captureCurrent, options.captureTscmaa);
  if (rule.resolve) return std::make_unique<TaaResolvePass>(ctx, spec, plan);
  return nullptr;
}

}  // namespace taa
