#include "case/coverage.h"

#include <algorithm>
#include <charconv>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "spec/taa_modes.h"
#include "spec/taa_spec.h"

namespace taa::cases {

namespace {

using namespace spec;

class Table {
 public:
  // A row for every value first, so values no case reaches stay in the table, in order.
  void value(const std::string& key, const std::string& value) {
    index_[{key, value}] = rows_.size();
    rows_.push_back({key, value, {}});
  }
  void reach(const std::string& key, const std::string& value, const std::string& name) {
    const auto it = index_.find({key, value});
    if (it == index_.end()) return;
    auto& cases = rows_[it->second].cases;
    if (cases.empty() || cases.back() != name) cases.push_back(name);
  }
  std::vector<CoverageRow> take() { return std::move(rows_); }

 private:
  std::vector<CoverageRow> rows_;
  std::map<std::pair<std::string, std::string>, size_t> index_;
};

template <class E>
void enumValues(Table& table, const std::string& key, E) {
  for (const auto& n : enumNames(E{})) table.value(key, n.name);
}

// The built-in resolve reads taa.* only where it runs; a user's shader reads none of them.
bool builtInResolve(const CaseSpec& s) {
  return modeRule(s.taa.mode).resolve && s.taa.shader.empty();
}

}  // namespace

std::vector<CoverageRow> settingValueCoverage(const std::vector<spec::CheckedCase>& cases) {
  Table table;
  enumValues(table, "taa.mode", TaaMode{});
  table.value("taa.shader", "set");
#define COV_ROWS_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  enumValues(table, "taa." #key, type{});
#define COV_ROWS_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  table.value("taa." #key, "true");                                      \
  table.value("taa." #key, "false");
#define COV_ROWS_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  table.value("taa." #key, "default");                                             \
  table.value("taa." #key, "other");
  TAA_SETTINGS(COV_ROWS_E, COV_ROWS_B, COV_ROWS_F)
  for (const char* ramp : {"taa.moving.from_px", "taa.moving.to_px", "taa.moving.depth"}) {
    table.value(ramp, "default");
    table.value(ramp, "other");
  }
#define COV_MOVING_ROWS_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define COV_MOVING_ROWS_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define COV_MOVING_ROWS_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  table.value("taa.moving." #key, "blended");
  TAA_SETTINGS(COV_MOVING_ROWS_E, COV_MOVING_ROWS_B, COV_MOVING_ROWS_F)

  const TaaMovingSpec movingDefaults;
  for (const auto& c : cases) {
    const std::string& n = c.name;
    table.reach("taa.mode", enumToString(c.taa.mode), n);
    if (!c.taa.shader.empty()) table.reach("taa.shader", "set", n);
    if (!builtInResolve(c)) continue;
    const TaaSpec e = effectiveTaa(c.taa);
    const uint32_t bit = modeBit(c.taa.mode);
    // A setting counts where its mode takes it and its rule holds (the rules validation
    // applies to a key the case sets, here applied to every value in force).
#define COV_IN_FORCE(modes, rule) ((modes & bit) != 0 && rule(e))
#define COV_REACH_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  if (COV_IN_FORCE(modes, rule)) table.reach("taa." #key, enumToString(e.key), n);
#define COV_REACH_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  if (COV_IN_FORCE(modes, rule)) table.reach("taa." #key, e.key ? "true" : "false", n);
#define COV_REACH_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  if (COV_IN_FORCE(modes, rule)) table.reach("taa." #key, e.key == def ? "default" : "other", n);
    TAA_SETTINGS(COV_REACH_E, COV_REACH_B, COV_REACH_F)
    const TaaMovingSpec& m = c.taa.moving;
    if (!m.active) continue;
    table.reach("taa.moving.from_px", m.from_px == movingDefaults.from_px ? "default" : "other", n);
    table.reach("taa.moving.to_px", m.to_px == movingDefaults.to_px ? "default" : "other", n);
    table.reach("taa.moving.depth", m.depth == movingDefaults.depth ? "default" : "other", n);
    // The loader copies the still value into every float taa.moving leaves out.
#define COV_REACH_MOVING_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define COV_REACH_MOVING_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define COV_REACH_MOVING_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  if (COV_IN_FORCE(modes, rule) && m.key != e.key) table.reach("taa.moving." #key, "blended", n);
    TAA_SETTINGS(COV_REACH_MOVING_E, COV_REACH_MOVING_B, COV_REACH_MOVING_F)
#undef COV_IN_FORCE
  }
  return table.take();
}

namespace {

// One constant of taa_resolve.comp: its GLSL name and the names of its values by number.
struct Constant {
  int id;
  std::string name;
  std::vector<std::pair<int, std::string>> values;
};

#define COV_GLSL_VALUE(cxx, glsl, value, text) {value, #glsl},
const std::vector<std::pair<int, std::string>> kBoolValues = {{0, "false"}, {1, "true"}};

std::vector<Constant> resolveConstants() {
  std::vector<Constant> out = {
      {TAA_SPEC_RESOLVE, "kResolve", {TAA_RESOLVE_VALUES(COV_GLSL_VALUE)}},
      {TAA_SPEC_HAS_HISTORY, "kHasHistory", kBoolValues},
      {TAA_SPEC_UPSAMPLE, "kUpsample", kBoolValues},
      {TAA_SPEC_DEBUG, "kDebug", {TAA_DEBUG_OUTPUT_VALUES(COV_GLSL_VALUE)}},
      {TAA_SPEC_REJECT_MASK, "kRejectMask", kBoolValues}};
#define COV_CONST_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  out.push_back({id, #name, {values(COV_GLSL_VALUE)}});
#define COV_CONST_B(key, def, id, name, modes, reads, rule, text, doc, impl) \
  out.push_back({id, #name, kBoolValues});
#define COV_CONST_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl)
  TAA_SETTINGS(COV_CONST_E, COV_CONST_B, COV_CONST_F)
  return out;
}

}  // namespace

std::map<int, int> tracedConstants(const std::vector<std::string>& log) {
  static const std::string kPrefix = "taa_resolve spec constants:";
  std::map<int, int> out;
  for (const auto& line : log) {
    if (line.rfind(kPrefix, 0) != 0) continue;
    std::istringstream words(line.substr(kPrefix.size()));
    std::string word;
    while (words >> word) {
      const auto eq = word.find('=');
      if (eq == std::string::npos) continue;
      // Whole numbers in int's range, or the log is not one `run` wrote.
      int id = 0, value = 0;
      const char* end = word.data() + word.size();
      const auto a = std::from_chars(word.data(), word.data() + eq, id);
      const auto b = std::from_chars(word.data() + eq + 1, end, value);
      if (a.ec != std::errc() || a.ptr != word.data() + eq || b.ec != std::errc() || b.ptr != end)
        throw std::invalid_argument("the line '" + kPrefix + " ...' holds '" + word.substr(0, 40) +
                                    "', not ID=VALUE with whole numbers of at most 10 digits");
      out[id] = value;
    }
  }
  return out;
}

std::map<std::string, std::vector<std::string>> checkedRunLogs(
    const std::vector<std::pair<std::string, std::vector<std::string>>>& logs) {
  std::map<std::string, std::vector<std::string>> out;
  for (size_t i = 0; i < logs.size(); ++i) {
    const auto& [name, lines] = logs[i];
    if (lines.empty()) continue;
    try {
      tracedConstants(lines);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("cases[" + std::to_string(i) + "].log: " + e.what());
    }
    out[name] = lines;
  }
  return out;
}

std::vector<CoverageRow> resolveBranchCoverage(
    const std::map<std::string, std::vector<std::string>>& logs) {
  Table table;
  const auto constants = resolveConstants();
  for (const auto& c : constants)
    for (const auto& [value, name] : c.values) table.value(c.name, name);
  for (const auto& [caseName, log] : logs) {
    const auto traced = tracedConstants(log);
    if (traced.empty()) continue;  // no built-in resolve ran
    for (const auto& c : constants) {
      const auto it = traced.find(c.id);
      if (it == traced.end()) continue;
      for (const auto& [value, name] : c.values)
        if (value == it->second || (c.id == TAA_SPEC_HAS_HISTORY && value == 0))
          table.reach(c.name, name, caseName);
    }
  }
  return table.take();
}

}  // namespace taa::cases
