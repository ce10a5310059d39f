// The one description of every case-file setting. Each spec struct has a
// `fields(V&, S&)` template that names its keys, ranges and documentation once;
// visitors (JSON reader, JSON writer, schema lister) walk it, so parsing,
// `validate --print` and `techniques --json` can never disagree.
#pragma once

#include <array>
#include <span>
#include <string_view>
#include <vector>

namespace taa::spec {

// Documentation carried by a setting: what it does and where it is implemented.
struct Meta {
  const char* doc = "";
  const char* impl = "";    // shader or C++ unit that implements the setting
  const char* drives = "";  // the specialization constant or uniform slot it sets, if declared
  const char* when = "";    // the condition under which it means something, beyond its modes
};

// A value that is a number, or JSON true/false (a user shader's bool constant); `number`
// holds 1 or 0 for a bool, so a check of its type needs no second field. A list of numbers
// (`list`, at most kMaxNumberList) sets a user shader's vector or matrix uniform.
struct NumberOrBool {
  double number = 0.0;
  bool isBool = false;       // given as true or false
  std::vector<double> list;  // given as [numbers]: `number` is then unused
};
inline constexpr size_t kMaxNumberList = 16;  // a float4x4

template <class T>
struct Range {
  T lo;
  T hi;
};

template <class E>
struct EnumName {
  E value;
  const char* name;
};

// Looks up the name table of an enum through ADL: every enum used in a spec
// declares `std::span<const EnumName<E>> enumNames(E)` next to itself.
template <class E>
const char* enumToString(E value) {
  for (const auto& n : enumNames(E{}))
    if (n.value == value) return n.name;
  return "?";
}

template <class E>
bool enumFromString(std::string_view text, E& out) {
  for (const auto& n : enumNames(E{}))
    if (text == n.name) {
      out = n.value;
      return true;
    }
  return false;
}

}  // namespace taa::spec

#define TAA_ENUM_NAMES(E, ...)                                          \
  inline std::span<const ::taa::spec::EnumName<E>> enumNames(E) {       \
    static constexpr ::taa::spec::EnumName<E> kNames[] = {__VA_ARGS__}; \
    return kNames;                                                      \
  }
