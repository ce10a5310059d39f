// The settings audit (docs/settings-audit.md): each key of `techniques --json` that can change
// pixels, set to another legal value, is refused or changes the output, on each path. In ctest:
// the resolve's own keys (taa_settings.h) on the default full path. With
// TAA_SETTINGS_AUDIT=full (ci/audit-settings.sh): every key on every path.
#include "support/settings_audit.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "case/case_loader.h"
// The audit renders on the shared test device; ci/sanitize.sh leaves out suites including this.

namespace taa {
namespace {

using test::audit::Verdict;

bool settingsAuditFull() {
  const char* env = std::getenv("TAA_SETTINGS_AUDIT");
  return env && std::string(env) == "full";
}

// The resolve's settings of shaders/common/taa_settings.h: taa.* but the mode (the paths),
// the moving set and a user's shader (files).
bool resolveSetting(const std::string& key) {
  return key.rfind("taa.", 0) == 0 && key != "taa.mode" && key.rfind("taa.moving.", 0) != 0 &&
         key.rfind("taa.shader", 0) != 0;
}

TEST(SettingsAudit, ListsNameKeysThatExist) {
  std::set<std::string> keys;
  for (const auto& row : cases::settingsSchema()) keys.insert(row["key"].get<std::string>());
  for (const auto& e : test::audit::exclusions()) {
    bool any = false;
    for (const auto& k : keys) any = any || test::audit::excluded(k) == &e;
    EXPECT_TRUE(any) << "exclusion " << e.key << " covers no key of techniques --json";
  }
  for (const auto& a : test::audit::allowances()) {
    EXPECT_TRUE(keys.count(a.key)) << "allowance " << a.key << " names no key";
    EXPECT_FALSE(std::string(a.provedBy).empty())
        << "allowance " << a.key << " names no proving test";
  }
}

TEST(SettingsAudit, EveryKeyActsOrIsRefused) {
  const bool full = settingsAuditFull();
  std::vector<test::audit::AuditRow> rows;
  int combos = 0;
  for (const auto& row : cases::settingsSchema()) {
    const std::string key = row["key"];
    if (!full && !resolveSetting(key)) continue;
    if (const auto* e = test::audit::excluded(key)) {
      if (full) std::printf("excluded: %s (%s)\n", key.c_str(), e->why);
      continue;
    }
    for (const auto& path : test::audit::auditPaths(full)) {
      if (test::audit::alternatives(row, path).empty()) {
        ADD_FAILURE() << key << ": the audit has no other value to try; give it one or exclude it";
        continue;
      }
      ++combos;
      for (auto& r : test::audit::auditKey(row, path)) rows.push_back(std::move(r));
    }
  }
  std::printf("key | path | value | verdict | message\n%s", test::audit::table(rows).c_str());
  int findings = 0, refused = 0, acts = 0, allowed = 0;
  for (const auto& r : rows) {
    refused += r.verdict == Verdict::Refused;
    acts += r.verdict == Verdict::Acts;
    allowed += r.verdict == Verdict::Allowed;
    if (r.verdict == Verdict::Identical || r.verdict == Verdict::Failed) {
      ++findings;
      ADD_FAILURE() << r.key << " on path " << r.path << " = " << r.value << ": "
                    << test::audit::verdictName(r.verdict) << ": " << r.message;
    }
  }
  std::printf(
      "%d key x path combinations, %zu values: %d act, %d refused, %d allowlisted, %d findings\n",
      combos, rows.size(), acts, refused, allowed, findings);
}

}  // namespace
}  // namespace taa
