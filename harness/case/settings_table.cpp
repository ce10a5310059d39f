#include "case/settings_table.h"

#include <nlohmann/json.hpp>
#include <sstream>

namespace taa::cases {

namespace {
// Lists read better with a space after each comma than nlohmann's compact dump gives.
std::string tableValue(const nlohmann::json& v) {
  if (!v.is_array()) return v.dump();
  std::string out = "[";
  for (size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + tableValue(v[i]);
  return out + "]";
}
}  // namespace

std::string settingsMarkdownTable(const nlohmann::json& schema) {
  std::ostringstream out;
  out << "| key | type | default | range / values | meaning |\n|---|---|---|---|---|\n";
  for (const auto& r : schema) {
    std::string values;
    if (r.contains("range")) values = r["range"][0].dump() + " .. " + r["range"][1].dump();
    if (r.contains("allowed"))
      for (size_t i = 0; i < r["allowed"].size(); ++i)
        values += (i ? ", " : "") + r["allowed"][i].get<std::string>();
    out << "| `" << r["key"].get<std::string>() << "` | " << r["type"].get<std::string>() << " | `"
        << tableValue(r["default"]) << "` | " << values << " | " << r["doc"].get<std::string>() << " |\n";
  }
  return out.str();
}

}  // namespace taa::cases
