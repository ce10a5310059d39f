#include "frame/pass_plan.h"

#include <algorithm>

#include "spec/taa_modes.h"

namespace taa {

namespace {
bool planWantsAux(const spec::CaseSpec& s, spec::AuxBuffer b) {
  return std::find(s.output.aux.begin(), s.output.aux.end(), b) != s.output.aux.end();
}
}  // namespace

PassPlan planPasses(const spec::CaseSpec& s) {
  using namespace spec;
  PassPlan p;
  // What runs comes from the mode's rule; what each pass reads, from the pass.
  const ModeRule& rule = modeRule(s.taa.mode);
  p.taa = runsTaa(rule);
  p.adaptive = rule.adaptive;
  p.motionBlur = s.post.motion_blur;
  p.deferred = s.render.path == RenderPath::Deferred;
  p.msaa = s.render.msaa;
  p.own.velocity = planWantsAux(s, AuxBuffer::Velocity);
  p.own.ids = planWantsAux(s, AuxBuffer::MaterialId);
  p.own.normal = p.deferred || planWantsAux(s, AuxBuffer::Normal);
  p.sharpen = s.post.sharpen == Sharpen::Gradient;
  p.cas = s.post.sharpen == Sharpen::Cas;
  p.fxaa = s.post.fxaa;
  p.debugView = s.debug.output != DebugOutput::None;
  return p;
}

GBufferConfig planGBuffer(const PassPlan& plan, const GBufferNeeds& passes,
                          glm::ivec2 maxRenderSize) {
  const GBufferNeeds n = plan.own | passes;
  GBufferConfig c;
  c.width = uint32_t(maxRenderSize.x);
  c.height = uint32_t(maxRenderSize.y);
  c.deferred = plan.deferred;
  c.samples = uint32_t(plan.msaa);
  // Last frame's copy of a target needs this frame's target to copy from.
  c.velocity = n.velocity || n.prevVelocity;
  c.normal = n.normal || n.prevNormal;
  c.ids = n.ids || n.prevIds;
  return c;
}

std::vector<std::string> PassPlan::describe() const {
  std::vector<std::string> out;
  out.push_back(std::string("pass gbuffer (") + (deferred ? "deferred" : "forward") +
                (msaa > 1 ? ", " + std::to_string(msaa) + "x MSAA" : "") + ")");
  if (deferred) out.push_back("pass deferred_lighting");
  // The resolve stage and the passes around it list themselves with their settings.
  return out;
}

}  // namespace taa
