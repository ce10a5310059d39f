// Reads a JSON object into a spec struct through its `fields` description,
// collecting every problem (wrong type, out of range, unknown key) with its key path.
#pragma once

#include <cmath>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "case/case_error.h"
#include "case/json_number.h"
#include "spec/fields.h"

namespace taa::cases {

struct ReadContext {
  std::string file;                   // shown at the start of every problem
  std::vector<std::string> problems;  // collected, reported together
  std::set<std::string> present;      // key paths the file sets explicitly
};

template <class E>
std::vector<std::string> enumNameList() {
  std::vector<std::string> out;
  for (const auto& n : enumNames(E{})) out.emplace_back(n.name);
  return out;
}

std::string joinNames(const std::vector<std::string>& names);
std::string formatNumber(double value);

class JsonReader {
 public:
  JsonReader(const nlohmann::json& node, std::string path, ReadContext& ctx)
      : node_(node), path_(std::move(path)), ctx_(ctx) {}

  // Reports keys of this object that no field visited; call after `fields(reader, spec)`.
  void finish() {
    if (!node_.is_object()) return;
    for (const auto& item : node_.items()) {
      if (visited_.count(item.key())) continue;
      std::string msg = "unknown key";
      const std::string guess = closestMatch(item.key(), visitedList_);
      if (!guess.empty())
        msg += "; did you mean '" + keyPath(guess) + "'?";
      else
        msg += "; allowed keys here: " + joinNames(visitedList_);
      problem(keyPath(item.key()), msg);
    }
  }

  template <class T>
  void field(const char* key, T& value, const spec::Meta&) {
    if (const auto* j = take(key)) read(*j, keyPath(key), value);
  }

  template <class T>
  void field(const char* key, T& value, spec::Range<T> range, const spec::Meta&) {
    if (const auto* j = take(key)) {
      if (read(*j, keyPath(key), value)) checkRange(keyPath(key), value, range);
    }
  }

  template <class T>
  void field(const char* key, std::vector<T>& value, spec::Range<T> range, const spec::Meta&) {
    if (const auto* j = take(key)) {
      if (!read(*j, keyPath(key), value)) return;
      for (size_t i = 0; i < value.size(); ++i)
        checkRange(keyPath(key) + "[" + std::to_string(i) + "]", value[i], range);
    }
  }

  template <class S>
  void object(const char* key, S& sub, const spec::Meta&) {
    const auto* j = take(key);
    if (!j) return;
    if (!j->is_object()) return problem(keyPath(key), "expected an object {...}");
    JsonReader child(*j, keyPath(key), ctx_);
    fields(child, sub);
    child.finish();
  }

  template <class S>
  void list(const char* key, std::vector<S>& items, const spec::Meta&) {
    const auto* j = take(key);
    if (!j) return;
    if (!j->is_array()) return problem(keyPath(key), "expected an array of objects [{...}]");
    items.assign(j->size(), S{});
    for (size_t i = 0; i < j->size(); ++i) {
      const std::string path = keyPath(key) + "[" + std::to_string(i) + "]";
      if (!(*j)[i].is_object()) {
        problem(path, "expected an object {...}");
        continue;
      }
      ctx_.present.insert(path);
      JsonReader child((*j)[i], path, ctx_);
      fields(child, items[i]);
      child.finish();
    }
  }

 private:
  const nlohmann::json* take(const char* key) {
    if (!visited_.count(key)) visitedList_.emplace_back(key);
    visited_.insert(key);
    if (!node_.is_object() || !node_.contains(key)) return nullptr;
    ctx_.present.insert(keyPath(key));
    return &node_[key];
  }

  std::string keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  void problem(const std::string& path, const std::string& msg) {
    ctx_.problems.push_back(ctx_.file + ": " + path + ": " + msg);
  }

  bool typeError(const std::string& path, const char* expected) {
    problem(path, std::string("expected ") + expected);
    return false;
  }

  bool read(const nlohmann::json& j, const std::string& path, bool& out) {
    if (!j.is_boolean()) return typeError(path, "true or false");
    out = j.get<bool>();
    return true;
  }
  bool read(const nlohmann::json& j, const std::string& path, int& out) {
    if (!j.is_number_integer()) return typeError(path, "an integer");
    int64_t wide = 0;
    if (!jsonWholeIn(j, std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), wide))
      return typeError(path, "an integer within 32 bits");
    out = static_cast<int>(wide);
    return true;
  }
  bool read(const nlohmann::json& j, const std::string& path, float& out) {
    if (!j.is_number()) return typeError(path, "a number");
    const double d = j.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > 3.0e38) return typeError(path, "a finite number within float range");
    out = static_cast<float>(d);
    return true;
  }
  bool read(const nlohmann::json& j, const std::string& path, spec::NumberOrBool& out) {
    if (j.is_boolean()) {
      out = {j.get<bool>() ? 1.0 : 0.0, true, {}};
      return true;
    }
    if (j.is_array()) {  // a uniform's vector or matrix
      const char* what = "a number, true or false, or a list of 1 to 16 finite numbers";
      if (j.empty() || j.size() > spec::kMaxNumberList) return typeError(path, what);
      out = {0.0, false, {}};
      for (const auto& x : j) {
        if (!x.is_number() || !std::isfinite(x.get<double>())) return typeError(path, what);
        out.list.push_back(x.get<double>());
      }
      return true;
    }
    if (!j.is_number()) return typeError(path, "a number, or true or false");
    out = {j.get<double>(), false, {}};
    if (!std::isfinite(out.number)) return typeError(path, "a finite number");
    return true;
  }
  bool read(const nlohmann::json& j, const std::string& path, double& out) {
    if (!j.is_number()) return typeError(path, "a number");
    out = j.get<double>();
    if (!std::isfinite(out)) return typeError(path, "a finite number");
    return true;
  }
  bool read(const nlohmann::json& j, const std::string& path, std::string& out) {
    if (!j.is_string()) return typeError(path, "a string");
    out = j.get<std::string>();
    return true;
  }
  template <int N>
  bool read(const nlohmann::json& j, const std::string& path, glm::vec<N, float>& out) {
    static const std::string expected = "an array of " + std::to_string(N) + " numbers";
    if (!j.is_array() || j.size() != static_cast<size_t>(N)) return typeError(path, expected.c_str());
    for (int i = 0; i < N; ++i)
      if (!read(j[i], path + "[" + std::to_string(i) + "]", out[i])) return false;
    return true;
  }
  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  bool read(const nlohmann::json& j, const std::string& path, E& out) {
    const auto names = enumNameList<E>();
    if (!j.is_string()) {
      problem(path, "expected one of " + joinNames(names));
      return false;
    }
    const auto text = j.get<std::string>();
    if (spec::enumFromString(text, out)) return true;
    std::string msg = "'" + text + "' is not one of " + joinNames(names);
    const std::string guess = closestMatch(text, names);
    if (!guess.empty()) msg += "; did you mean '" + guess + "'?";
    problem(path, msg);
    return false;
  }
  template <class T>
  bool read(const nlohmann::json& j, const std::string& path, std::vector<T>& out) {
    if (!j.is_array()) return typeError(path, "an array");
    out.assign(j.size(), T{});
    bool ok = true;
    for (size_t i = 0; i < j.size(); ++i) ok = read(j[i], path + "[" + std::to_string(i) + "]", out[i]) && ok;
    return ok;
  }

  template <class T>
  void checkRange(const std::string& path, T value, spec::Range<T> range) {
    if (value >= range.lo && value <= range.hi) return;
    problem(path, formatNumber(static_cast<double>(value)) + " is out of range; allowed [" +
                      formatNumber(static_cast<double>(range.lo)) + ", " +
                      formatNumber(static_cast<double>(range.hi)) + "]");
  }

  const nlohmann::json& node_;
  std::string path_;
  ReadContext& ctx_;
  std::set<std::string> visited_;
  std::vector<std::string> visitedList_;
};

}  // namespace taa::cases
