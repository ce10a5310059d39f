#include "frame/resolve_factory.h"

#include "passes/taa_resolve.h"
#include "passes/tscmaa.h"
#include "spec/taa_modes.h"
#include "user/user_resolve.h"

namespace taa {

std::unique_ptr<ResolveStage> makeResolveStage(vk::Context& ctx, const spec::CaseSpec& spec,
                                               const PassPlan& plan, const RenderOptions& options) {
  const spec::ModeRule& rule = spec::modeRule(spec.taa.mode);
  if (rule.tscmaa) return std::make_unique<TscmaaPass>(ctx, spec, options.captures);
  // A user's shader (taa.shader, validated to run in taa.mode full) replaces the built-in one.
  if (rule.resolve && !spec.taa.shader.empty())
    return std::make_unique<UserResolvePass>(ctx, spec, loadUserShader(spec));
  if (rule.resolve) return std::make_unique<TaaResolvePass>(ctx, spec, plan);
  return nullptr;
}

}  // namespace taa
