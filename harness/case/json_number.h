// Whole numbers read from JSON as written: nlohmann's get<int>() takes 2.5 for 2 and wraps
// 10^12, or a uint64 past int64's range, into another value, so a forged number would be
// checked, and reported, as one it is not. Case files, results.json and golden manifests
// read their integers through it.
#pragma once

#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>

namespace taa {

// True, with `out` set, when `j` is a whole number from `lo` to `hi`.
inline bool jsonWholeIn(const nlohmann::json& j, int64_t lo, int64_t hi, int64_t& out) {
  if (j.is_number_unsigned()) {
    if (j.get<uint64_t>() > uint64_t(std::numeric_limits<int64_t>::max())) return false;
  } else if (!j.is_number_integer()) {
    return false;
  }
  out = j.get<int64_t>();
  return out >= lo && out <= hi;
}

}  // namespace taa
