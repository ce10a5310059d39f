// Reference frames shared across a run (api/reference_cache.h, run/reference_key.h): a
// shared reference must be the one a render of the case would read back. The key misses when
// anything the reference pass reads changes, and every setting the key leaves out is shown,
// by rendering, not to move the reference bits.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "api/reference_cache.h"
#include "run/reference_key.h"
#include "support/gpu.h"
#include "support/settings_audit.h"

namespace taa {
namespace {

// The audit scene (strafing camera, a moving and a still mover), small, with a reference on
// every frame, on a path (a merge patch).
nlohmann::json referenceBase(const std::string& pathPatch) {
  nlohmann::json j = nlohmann::json::parse(test::audit::auditBase());
  j.merge_patch(nlohmann::json::parse(pathPatch));
  j.merge_patch(nlohmann::json::parse(R"({"render": {"width": 32, "height": 18},
    "script": {"frames": 2}, "output": {"frames": [0, 1]}, "reference": {"samples": 4}})"));
  return j;
}

spec::CaseSpec specOf(const nlohmann::json& j) { return test::caseFromJson(j.dump(), "reference_key"); }

// The base case with KEY set to VALUE; nothing where the path refuses that value.
std::optional<spec::CaseSpec> withSetting(const nlohmann::json& base, const std::string& key,
                                          const nlohmann::json& value) {
  nlohmann::json j = base;
  j.merge_patch(test::audit::patchFor(key, value));
  try {
    return specOf(j);
  } catch (const cases::CaseError&) {
    return std::nullopt;
  }
}

std::vector<FrameRecord> renderReferences(const spec::CaseSpec& spec, ReferenceCache* cache) {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  if (cache) {
    o.referenceCache = cache;
    o.referenceKey = run::referenceKey(spec);
  }
  return test::renderCaseWith(spec, o);
}

// Whether two runs' references are bit for bit the same; "" or the first difference.
std::string sameReferences(const std::vector<FrameRecord>& a, const std::vector<FrameRecord>& b) {
  if (a.size() != b.size()) return "frame counts differ";
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].hasReference != b[i].hasReference) return "frame " + std::to_string(i) + " lacks a reference";
    if (a[i].reference.data != b[i].reference.data || !a[i].reference.sameShape(b[i].reference))
      return "frame " + std::to_string(i) + " differs";
  }
  return "";
}

nlohmann::json resolved(const spec::CaseSpec& s) {
  spec::CheckedCase c;
  static_cast<spec::CaseSpec&>(c) = s;
  return cases::resolvedJson(c);
}

bool leftOutOfTheKey(const std::string& key) {
  for (const char* prefix : {"description", "checks.", "report.", "output.", "taa.", "adaptive.",
                             "post.", "inject.", "jitter.", "camera.", "script.", "render.msaa",
                             "render.scale_schedule", "render.upsample", "debug.output",
                             "debug.channels", "debug.scale", "tscmaa.blurriness",
                             "tscmaa.edge_threshold", "tscmaa.history_weight",
                             "tscmaa.non_dominant_edge_removal", "tscmaa.taa_share"})
    if (key.rfind(prefix, 0) == 0) return true;
  return false;
}

TEST(ReferenceCache, StillFramesRenderOnceMovingFramesEach) {
  ReferenceCache cache;
  auto still = referenceBase("{}");
  still["camera"] = nlohmann::json::object();
  still["movers"] = nlohmann::json::array({still["movers"][1]});  // the mover that stays put
  still["script"]["frames"] = 5;
  still["output"]["frames"] = {0, 1, 2, 3, 4};
  const auto stillSpec = specOf(still);
  const auto shared = renderReferences(stillSpec, &cache);
  // Frame 0's previous camera is its own, so all five frames draw the same bytes.
  EXPECT_EQ(cache.stats().rendered, 1u);
  EXPECT_EQ(cache.stats().reused, 4u);
  EXPECT_EQ(sameReferences(shared, renderReferences(stillSpec, nullptr)), "");

  ReferenceCache moving;
  renderReferences(specOf(referenceBase("{}")), &moving);
  EXPECT_EQ(moving.stats().rendered, 2u);  // the camera strafes: every frame is new
  EXPECT_EQ(moving.stats().reused, 0u);
}

TEST(ReferenceCache, AnotherResolveSharesTheReference) {
  ReferenceCache cache;
  const auto base = specOf(referenceBase("{}"));
  renderReferences(base, &cache);
  auto other = referenceBase("{}");
  other["taa"] = {{"history_filter", "bilinear"}, {"rectify", "clamp"}};
  other["jitter"] = {{"pattern", "uniform4"}};
  const auto otherSpec = specOf(other);
  const auto shared = renderReferences(otherSpec, &cache);
  EXPECT_EQ(cache.stats().reused, 2u);
  EXPECT_EQ(sameReferences(shared, renderReferences(otherSpec, nullptr)), "");
}

TEST(ReferenceCache, HoldsNoMoreThanItsBytes) {
  ReferenceCache cache(3 * 16 * 16 * 4 * sizeof(float));
  for (int i = 0; i < 5; ++i) cache.insert("k" + std::to_string(i), Image(16, 16, 4, float(i)));
  EXPECT_EQ(cache.stats().bytes, 3u * 16 * 16 * 4 * sizeof(float));
  EXPECT_EQ(cache.find("k0"), nullptr);  // the least recently used went first
  EXPECT_EQ(cache.find("k1"), nullptr);
  ASSERT_NE(cache.find("k2"), nullptr);
  cache.insert("k5", Image(16, 16, 4, 5.0f));  // k3 is now the oldest
  EXPECT_EQ(cache.find("k3"), nullptr);
  ASSERT_NE(cache.find("k2"), nullptr);
  EXPECT_EQ(cache.find("k2")->data[0], 2.0f);
}

// Every setting the reference key keeps: another value is another key (no render needed:
// another key is a miss, and a miss renders).
TEST(ReferenceKey, MissesWhenASettingItKeepsChanges) {
  const test::audit::AuditPath path{"full", "{}"};
  const nlohmann::json base = referenceBase(path.patch);
  const std::string baseKey = run::referenceKey(specOf(base));
  int checked = 0;
  for (const auto& row : cases::settingsSchema()) {
    const std::string key = row["key"];
    if (leftOutOfTheKey(key) || test::audit::excluded(key)) continue;
    for (const auto& value : test::audit::alternatives(row, path)) {
      const auto variant = withSetting(base, key, value);
      if (!variant) continue;  // refused here: nothing to share
      const spec::CaseSpec& spec = *variant;
      if (resolved(spec) == resolved(specOf(base))) continue;  // the path's value already
      EXPECT_NE(run::referenceKey(spec), baseKey) << key << " = " << value.dump();
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
  // The case's folder: files named in a case are relative to it.
  auto elsewhere = specOf(base);
  elsewhere.file = "/elsewhere/reference_key.json";
  EXPECT_NE(run::referenceKey(elsewhere), baseKey);
}

// Every setting the key leaves out, on the paths whose reference it could touch: where the
// case's reference of a frame has the key of one the base case rendered (so a run holding both
// would share it), a render of the case draws the same bits. Settings that move the frame
// (camera, script) miss by their frame bytes.
struct LeftOutPath {
  const char* name;
  const char* patch;
};

class ReferenceKeyLeftOut : public ::testing::TestWithParam<LeftOutPath> {};

TEST_P(ReferenceKeyLeftOut, SettingsLeftOutLeaveTheReferenceAsRendered) {
  const test::audit::AuditPath path{GetParam().name, GetParam().patch};
  const nlohmann::json base = referenceBase(path.patch);
  ReferenceCache baseCache;
  renderReferences(specOf(base), &baseCache);
  int shared = 0;
  for (const auto& row : cases::settingsSchema()) {
    const std::string key = row["key"];
    if (!leftOutOfTheKey(key) || test::audit::excluded(key)) continue;
    // The first value the path accepts: one render per setting keeps the test short.
    for (const auto& value : test::audit::alternatives(row, path)) {
      const auto variant = withSetting(base, key, value);
      if (!variant) continue;
      const spec::CaseSpec& spec = *variant;
      // Its own cache: each of its frames' references as rendered, under its key.
      ReferenceCache own;
      renderReferences(spec, &own);
      bool sharesOne = false;
      for (const auto& k : own.keys()) {
        const auto fromBase = baseCache.find(k);
        if (!fromBase) continue;
        sharesOne = true;
        const auto rendered = own.find(k);
        EXPECT_TRUE(rendered->data == fromBase->data && rendered->sameShape(*fromBase))
            << key << " = " << value.dump() << " on " << path.name
            << ": the reference key leaves out a setting the reference reads";
      }
      shared += sharesOne;
      break;
    }
  }
  EXPECT_GT(shared, 20);
}

// Deferred shading with shadows (the atlas the sub-samples read; one cascade, as each 1024x1024
// map costs more than the 32x18 frame), and TSCMAA's two eyes.
INSTANTIATE_TEST_SUITE_P(
    Paths, ReferenceKeyLeftOut,
    ::testing::Values(LeftOutPath{"deferred_shadows", R"({"render": {"path": "deferred"},
                                                          "lighting": {"shadows": true, "cascades": 1}})"},
                      LeftOutPath{"tscmaa_eyes2", R"({"taa": {"mode": "tscmaa"}, "tscmaa": {"eyes": 2}})"}),
    [](const auto& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace taa
