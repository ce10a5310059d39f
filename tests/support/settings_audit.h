// The settings audit (docs/settings-audit.md): every case key that can change rendered pixels,
// set to another legal value on each path that could accept it, must either be refused by
// validation or change the output. "A setting accepted but ignored is a bug", checked by
// machine rather than by reading.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace taa::test::audit {

// A path: the audit scene with a JSON merge patch (taa.mode, upsampling, deferred lighting...).
struct AuditPath {
  std::string name;
  std::string patch;
};

enum class Verdict {
  Refused,    // validation refused the key there (exit 2): fine
  Acts,       // accepted, and some frame's colour or stats changed: fine
  Allowed,    // accepted and bit-identical, but the audit scene cannot show it (allowlisted)
  Identical,  // accepted and bit-identical: a finding
  Failed,     // accepted, and rendering it threw: a finding
};
const char* verdictName(Verdict v);

struct AuditRow {
  std::string key;
  std::string path;
  std::string value;  // the value tried, as JSON
  Verdict verdict;
  std::string message;  // the refusal, the allowlist's reason, or what went wrong
};

// A key the audit does not try, and why (a key that cannot change pixels by design, or one
// whose value the generic audit cannot invent: a file, a list of objects).
struct Exclusion {
  const char* key;  // a key, or a prefix ending in '*' for a whole group
  const char* why;
};
const std::vector<Exclusion>& exclusions();
// The exclusion covering `key`, or null.
const Exclusion* excluded(const std::string& key);

// A key whose change the audit scene cannot show on a path, with the test proving it acts.
struct Allowance {
  const char* key;
  const char* path;  // "*" for every path
  const char* why;
  const char* provedBy;  // Suite.Test of the existing test that shows the key acting
};
const std::vector<Allowance>& allowances();
const Allowance* allowed(const std::string& key, const std::string& path);

// The audit scene: thin fence geometry, a strafing camera, a cube mover and an HDR highlight.
std::string auditBase();
// Every path (full: all of them; otherwise the default full-resolve path only).
std::vector<AuditPath> auditPaths(bool full);

// The values tried for a schema row (techniques --json), none equal to its default; empty when
// the audit has no way to choose one. Numbers get up to three candidates, tried in order until one
// acts.
std::vector<nlohmann::json> alternatives(const nlohmann::json& row, const AuditPath& path);

// The merge patch setting `key` ("movers[].KEY": the audit scene's first mover) to `value`.
nlohmann::json patchFor(const std::string& key, const nlohmann::json& value);

// Validation's "has no effect unless COND; set that" (Rules::needs) as a merge patch making COND
// hold on `path`; null when COND is not of that form or names only taa.mode (the paths are the
// modes). enablesMore: whether it sets a key the path does not set yet (no going round in
// circles); enabledPath: the path with it merged in, named "full+taa.consistency=true".
nlohmann::json enablerFor(const std::string& refusal, const AuditPath& path);
bool enablesMore(const AuditPath& path, const nlohmann::json& enabler);
AuditPath enabledPath(const AuditPath& path, const nlohmann::json& enabler);

// Runs the audit for one key on one path; renders through the shared test GPU.
std::vector<AuditRow> auditKey(const nlohmann::json& row, const AuditPath& path);

// A table of the rows: key, path, value, verdict, message.
std::string table(const std::vector<AuditRow>& rows);

}  // namespace taa::test::audit
