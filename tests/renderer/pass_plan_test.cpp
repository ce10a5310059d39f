// The G-buffer a case gets is the union of what its passes say they read: the resolve's
// needs follow its settings, the plan adds the case's own outputs, and a previous-frame
// copy brings the target it copies. A rendered case allocates exactly those targets.
#include "frame/pass_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "passes/taa_resolve.h"
#include "scene/build_scene.h"
#include "support/gpu.h"

namespace taa {
namespace {

// A mover, so that anti-ghosting has something to act on.
spec::CaseSpec planTestCase(const std::string& taa, const std::string& rest = "") {
  std::string json = R"({"render": {"width": 64, "height": 36}, "script": {"frames": 2},
    "movers": [{"shape": "sphere", "start": [-1, 0.5, 1], "end": [1, 0.5, 1], "speed": 2}],
    "taa": {)" + taa +
                     "}";
  if (!rest.empty()) json += ", " + rest;
  return test::caseFromJson(json + "}", "pass_plan");
}

TEST(GBufferNeeds, UnionKeepsEveryTargetOfEitherSide) {
  const GBufferNeeds fields[] = {{.velocity = true},     {.normal = true},     {.ids = true},
                                 {.prevDepth = true},    {.prevNormal = true}, {.prevIds = true},
                                 {.prevVelocity = true}, {.depth = true}};
  for (const GBufferNeeds& a : fields) {
    EXPECT_EQ(a | GBufferNeeds{}, a);
    EXPECT_EQ(GBufferNeeds{} | a, a);
    for (const GBufferNeeds& b : fields) {
      const GBufferNeeds u = a | b;
      EXPECT_EQ(u | a, u);  // a is inside the union
      EXPECT_EQ(u | b, u);
      if (!(a == b)) {
        EXPECT_FALSE(u == a);  // and b added something
      }
    }
  }
}

TEST(GBufferNeeds, ResolveReadsWhatItsSettingsUse) {
  // Anti-ghosting compares this and last frame's ids and velocity.
  const GBufferNeeds ghost = taaResolveNeeds(
      planTestCase(R"("mode": "full", "anti_ghosting": true, "use_velocity": "off")"));
  EXPECT_TRUE(ghost.velocity && ghost.ids && ghost.prevIds && ghost.prevVelocity);
  EXPECT_FALSE(ghost.normal || ghost.prevNormal || ghost.prevDepth);
  // Accumulation turns consistency on: depth, normal and ids of both frames.
  const GBufferNeeds acc = taaResolveNeeds(planTestCase(R"("mode": "accumulate")"));
  EXPECT_TRUE(acc.normal && acc.ids && acc.prevDepth && acc.prevNormal && acc.prevIds);
  // The basic blend reads colour alone, whatever the full path's defaults would read.
  EXPECT_EQ(taaResolveNeeds(planTestCase(R"("mode": "basic")")), GBufferNeeds{});
  EXPECT_EQ(taaResolveNeeds(planTestCase(R"("mode": "tscmaa")")), GBufferNeeds{});
  // Beyond the G-buffer: every path reads the colour, all but pass-through their history,
  // and a setting's row adds what it reads only where the path runs it.
  EXPECT_EQ(taaResolveInputs(planTestCase(R"("mode": "pass_through")")),
            ResolveInputSet{ResolveInput::Color});
  EXPECT_EQ(taaResolveInputs(planTestCase(R"("mode": "basic")")),
            (ResolveInputSet{ResolveInput::Color, ResolveInput::History}));
  EXPECT_TRUE(taaResolveInputs(planTestCase(R"("mode": "full", "depth_culling": true)"))
                  .has(ResolveInput::PrevDepth));
  EXPECT_FALSE(taaResolveInputs(planTestCase(R"("mode": "full")")).has(ResolveInput::PrevDepth));
}

TEST(GBufferNeeds, PlanAddsTheCaseOutputsAndTheTargetsCopiesComeFrom) {
  const spec::CaseSpec plain = planTestCase(R"("mode": "basic")");
  const GBufferConfig none = planGBuffer(planPasses(plain), {}, {64, 36});
  EXPECT_FALSE(none.velocity || none.normal || none.ids || none.deferred);
  EXPECT_EQ(none.width, 64u);
  EXPECT_EQ(none.height, 36u);

  const GBufferConfig copies =
      planGBuffer(planPasses(plain), {.prevNormal = true, .prevIds = true}, {64, 36});
  EXPECT_TRUE(copies.normal && copies.ids);
  EXPECT_FALSE(copies.velocity);

  const spec::CaseSpec aux =
      planTestCase(R"("mode": "basic")", R"("output": {"aux": ["velocity"]})");
  const GBufferConfig withAux = planGBuffer(planPasses(aux), {}, {64, 36});
  EXPECT_TRUE(withAux.velocity);
  EXPECT_FALSE(withAux.normal || withAux.ids);
}

bool planTestLogged(const std::vector<std::string>& log, const std::string& prefix) {
  return std::any_of(log.begin(), log.end(),
                     [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
}

std::vector<std::string> planTestLog(const spec::CaseSpec& spec) {
  const auto scene = scene::buildScene(spec);
  Renderer renderer(test::gpu(), spec, scene);
  renderer.renderFrame(0, true);
  return renderer.log();
}

TEST(GBufferNeeds, RenderedCaseAllocatesTheUnionOfItsPassesNeeds) {
  // Anti-ghosting (resolve) and motion blur (before it) both read velocity: one target.
  const auto ghost =
      planTestLog(planTestCase(R"("mode": "full", "anti_ghosting": true, "use_velocity": "off")",
                               R"("post": {"motion_blur": true})"));
  EXPECT_TRUE(planTestLogged(ghost, "buffer velocity "));
  EXPECT_TRUE(planTestLogged(ghost, "buffer prev_velocity "));
  EXPECT_TRUE(planTestLogged(ghost, "buffer prev_ids "));
  EXPECT_FALSE(planTestLogged(ghost, "buffer prev_depth "));
  EXPECT_FALSE(planTestLogged(ghost, "buffer normal "));
  // TSCMAA reads colour and depth only: no velocity, no previous frame.
  const auto tscmaa = planTestLog(planTestCase(R"("mode": "tscmaa")"));
  EXPECT_FALSE(planTestLogged(tscmaa, "buffer velocity "));
  EXPECT_FALSE(planTestLogged(tscmaa, "buffer prev_"));
}

}  // namespace
}  // namespace taa
