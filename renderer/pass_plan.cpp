#include "pass_plan.h"

#include <algorithm>

#include "spec/taa_modes.h"

namespace taa {

namespace {
bool wantsAux(const spec::CaseSpec& s, spec::AuxBuffer b) {
  return std::find(s.output.aux.begin(), s.output.aux.end(), b) != s.output.aux.end();
}
}  // namespace

PassPlan planPasses(const spec::CaseSpec& s) {
  using namespace spec;
  PassPlan p;
  // What runs comes from the mode's rule, with the settings it runs with.
  const ModeRule& rule = modeRule(s.taa.mode);
  const TaaSpec t = effectiveTaa(s.taa);
  p.taa = rule.resolve || rule.tscmaa;
  p.tscmaa = rule.tscmaa;
  // A user's resolve (taa.shader) reads what its shader declares (addUserNeeds), not what
  // the built-in settings would.
  p.userResolve = rule.resolve && !s.taa.shader.empty();
  const bool full = rule.resolve && rule.path == Resolve::Full && !p.userResolve;
  const bool reprojectsByVelocity = full && t.use_velocity != UseVelocity::Off;
  const bool antiGhost = full && t.anti_ghosting;
  const bool consistency = full && t.consistency;
  p.motionBlur = s.post.motion_blur;
  p.velocity =
      reprojectsByVelocity || antiGhost || p.motionBlur || wantsAux(s, AuxBuffer::Velocity);
  // Adaptive ray tracing segments by material id and normal derivatives.
  p.adaptive = rule.adaptive;
  p.ids = (full && t.use_velocity == UseVelocity::Movers) || antiGhost || consistency ||
          p.adaptive || wantsAux(s, AuxBuffer::MaterialId);
  p.deferred = s.render.path == RenderPath::Deferred;
  p.normal = consistency || p.deferred || p.adaptive || wantsAux(s, AuxBuffer::Normal);
  p.prevDepth = full && (t.depth_culling || consistency);
  p.prevNormal = consistency;
  p.prevIds = consistency || antiGhost;
  p.prevVelocity = antiGhost;
  p.sharpen = s.post.sharpen == Sharpen::Gradient;
  p.cas = s.post.sharpen == Sharpen::Cas;
  p.fxaa = s.post.fxaa;
  p.debugView = s.debug.output != DebugOutput::None;
  return p;
}

std::vector<std::string> PassPlan::describe() const {
  std::vector<std::string> out;
  out.push_back(std::string("pass gbuffer (") + (deferred ? "deferred" : "forward") + ")");
  if (deferred) out.push_back("pass deferred_lighting");
  if (tscmaa) {
    out.push_back("pass tscmaa_edges");
    out.push_back("pass tscmaa_cmaa (indirect over the edge list)");
    out.push_back("pass tscmaa_taa (indirect over the TAA list)");
  } else if (userResolve) {
    out.push_back("pass user_resolve (taa.shader)");
  } else if (taa) {
    out.push_back("pass taa_resolve");
    if (adaptive) out.push_back("pass adaptive (segmentation, trace, masked fxaa)");
  }
  // The post chain lists its own passes with their settings.
  return out;
}

}  // namespace taa
