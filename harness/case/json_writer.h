// Writes a spec struct back to JSON with every value in force (validate --print),
// and lists every setting with its type, range and default (techniques --json).
#pragma once

#include <charconv>
#include <cstdlib>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "spec/fields.h"

namespace taa::cases {

// Floats print as their shortest decimal form (0.2, not 0.20000000298023224).
inline double shortest(float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::strtod(std::string(buf, r.ptr).c_str(), nullptr);
}

template <class T>
nlohmann::json toJson(const T& value) {
  if constexpr (std::is_same_v<T, float>) {
    return shortest(value);
  } else if constexpr (std::is_enum_v<T>) {
    return spec::enumToString(value);
  } else if constexpr (std::is_same_v<T, spec::NumberOrBool>) {
    if (!value.list.empty()) return nlohmann::json(value.list);
    return value.isBool ? nlohmann::json(value.number != 0.0) : nlohmann::json(value.number);
  } else if constexpr (std::is_same_v<T, glm::vec2>) {
    return nlohmann::json::array({shortest(value.x), shortest(value.y)});
  } else if constexpr (std::is_same_v<T, glm::vec3>) {
    return nlohmann::json::array({shortest(value.x), shortest(value.y), shortest(value.z)});
  } else {
    return value;
  }
}

template <class T>
nlohmann::json toJson(const std::vector<T>& values) {
  auto out = nlohmann::json::array();
  for (const auto& v : values) out.push_back(toJson(v));
  return out;
}

class JsonWriter {
 public:
  explicit JsonWriter(nlohmann::json& out) : out_(out) { out_ = nlohmann::json::object(); }

  template <class T>
  void field(const char* key, T& value, const spec::Meta&) { out_[key] = toJson(value); }
  template <class T, class R>
  void field(const char* key, T& value, spec::Range<R>, const spec::Meta&) { out_[key] = toJson(value); }
  template <class S>
  void object(const char* key, S& sub, const spec::Meta&) {
    JsonWriter child(out_[key]);
    fields(child, sub);
  }
  template <class S>
  void list(const char* key, std::vector<S>& items, const spec::Meta&) {
    auto& arr = out_[key] = nlohmann::json::array();
    for (auto& item : items) {
      nlohmann::json entry;
      JsonWriter child(entry);
      fields(child, item);
      arr.push_back(std::move(entry));
    }
  }

 private:
  nlohmann::json& out_;
};

template <class T> struct TypeName { static constexpr const char* value = "?"; };
template <> struct TypeName<bool> { static constexpr const char* value = "bool"; };
template <> struct TypeName<int> { static constexpr const char* value = "int"; };
template <> struct TypeName<float> { static constexpr const char* value = "number"; };
template <> struct TypeName<spec::NumberOrBool> { static constexpr const char* value = "number, bool or list of numbers"; };
template <> struct TypeName<double> { static constexpr const char* value = "number"; };
template <> struct TypeName<std::string> { static constexpr const char* value = "string"; };
template <> struct TypeName<glm::vec2> { static constexpr const char* value = "vec2"; };
template <> struct TypeName<glm::vec3> { static constexpr const char* value = "vec3"; };
template <class T> struct TypeName<std::vector<T>> { static constexpr const char* value = "list"; };

template <class T> struct IsStdVector : std::false_type {};
template <class T> struct IsStdVector<std::vector<T>> : std::true_type {};

// One row per setting: key path, type, default, range or allowed names, doc, implementation.
class SchemaLister {
 public:
  SchemaLister(nlohmann::json& rows, std::string path) : rows_(rows), path_(std::move(path)) {}

  template <class T>
  void field(const char* key, T& value, const spec::Meta& meta) { add(key, value, meta, nullptr); }
  template <class T, class R>
  void field(const char* key, T& value, spec::Range<R> range, const spec::Meta& meta) {
    nlohmann::json r = nlohmann::json::array({toJson(range.lo), toJson(range.hi)});
    add(key, value, meta, &r);
  }
  template <class S>
  void object(const char* key, S& sub, const spec::Meta&) {
    SchemaLister child(rows_, keyPath(key));
    fields(child, sub);
  }
  template <class S>
  void list(const char* key, std::vector<S>& items, const spec::Meta& meta) {
    rows_.push_back({{"key", keyPath(key)}, {"type", "list of objects"}, {"default", toJsonList(items)},
                     {"doc", meta.doc}, {"impl", meta.impl}});
    S element{};
    SchemaLister child(rows_, keyPath(key) + "[]");
    fields(child, element);
  }

 private:
  template <class S>
  static nlohmann::json toJsonList(std::vector<S>& items) {
    nlohmann::json out;
    JsonWriter(out).list("v", items, spec::Meta{});
    return out["v"];
  }
  std::string keyPath(const char* key) const { return path_.empty() ? key : path_ + "." + key; }

  template <class T>
  void add(const char* key, const T& value, const spec::Meta& meta, const nlohmann::json* range) {
    nlohmann::json row = {{"key", keyPath(key)}, {"default", toJson(value)}, {"doc", meta.doc}, {"impl", meta.impl}};
    if (*meta.drives) row["drives"] = meta.drives;
    if (*meta.when) row["when"] = meta.when;
    if constexpr (std::is_enum_v<T>) {
      row["type"] = "enum";
      auto names = nlohmann::json::array();
      for (const auto& n : enumNames(T{})) names.push_back(n.name);
      row["allowed"] = names;
    } else if constexpr (IsStdVector<T>::value) {
      using E = typename T::value_type;
      if constexpr (std::is_enum_v<E>) {
        row["type"] = "list of enum";
        auto names = nlohmann::json::array();
        for (const auto& n : enumNames(E{})) names.push_back(n.name);
        row["allowed"] = names;
      } else {
        row["type"] = std::string("list of ") + TypeName<E>::value;
      }
    } else {
      row["type"] = TypeName<T>::value;
    }
    if (range) row["range"] = *range;
    rows_.push_back(std::move(row));
  }

  nlohmann::json& rows_;
  std::string path_;
};

}  // namespace taa::cases
