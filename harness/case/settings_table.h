// The "Every key" table of docs/case-format.md, generated from the one schema so the
// document cannot drift from what the reader accepts (taa-harness techniques --markdown).
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace taa::cases {

// One markdown row per schema row: key, type, default, range or allowed values, meaning.
std::string settingsMarkdownTable(const nlohmann::json& schema);

}  // namespace taa::cases
