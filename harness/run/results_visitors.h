// The two visitors of results.json's one declaration (run/results_format.h): ResultsWriter
// turns the structs into JSON, ResultsReader reads them back and refuses, by key path, a key
// the declaration lacks, a key it has that the file lacks, a value of the wrong type and a file
// of another format version. Like the case file's JsonReader/JsonWriter (harness/case/), but
// this format is the harness's own output: every key is written, so none may be missing.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "run/results.h"
#include "spec/fields.h"

namespace taa::run {

// A results.json that is not of this format: the message is the key path and what is wrong
// ("cases[2].golden_status: missing"); the reader of the file adds its name and the fix.
class ResultsFormatError : public InputError {
 public:
  using InputError::InputError;
};

// JSON has no infinities: a number() (PSNR of identical images, an error over NaN pixels) is
// written as the string "inf", "-inf" or "nan" when it is not finite.
nlohmann::json encodeNumber(double v);

class ResultsWriter {
 public:
  explicit ResultsWriter(nlohmann::json& out) : out_(out) { out_ = nlohmann::json::object(); }

  void version(const char* key, int v) { out_[key] = v; }
  template <class T>
  void field(const char* key, T& value) {
    if constexpr (std::is_enum_v<T>)
      out_[key] = spec::enumToString(value);
    else
      out_[key] = value;
  }
  void number(const char* key, double& value) { out_[key] = encodeNumber(value); }
  void derived(const char* key, const std::string& value) { out_[key] = value; }
  void ints(const char* key, std::initializer_list<int*> values, int, int) {
    auto& a = out_[key] = nlohmann::json::array();
    for (const int* v : values) a.push_back(*v);
  }
  void require(bool, const char*, const char*) {}
  void metrics(const char* key, ImageMetrics& m);
  void namedNumbers(const char* key, std::vector<std::pair<std::string, double>>& values);

  template <class S>
  void object(const char* key, S& sub) {
    ResultsWriter child(out_[key]);
    fields(child, sub);
  }
  // Written only when `written` is true (a check that did not run leaves no object).
  template <class S>
  void optionalObject(const char* key, S& sub, bool written) {
    if (written) object(key, sub);
  }
  template <class S>
  void list(const char* key, std::vector<S>& items) {
    auto& a = out_[key] = nlohmann::json::array();
    for (auto& item : items) {
      nlohmann::json entry;
      ResultsWriter child(entry);
      fields(child, item);
      a.push_back(std::move(entry));
    }
  }
  // Left out when empty.
  template <class S>
  void optionalList(const char* key, std::vector<S>& items) {
    if (!items.empty()) list(key, items);
  }

 private:
  nlohmann::json& out_;
};

class ResultsReader {
 public:
  ResultsReader(const nlohmann::json& node, std::string path);

  // Checked before anything else is read: another version is refused as a whole.
  void version(const char* key, int expected);
  template <class T>
  void field(const char* key, T& value) {
    read(at(key), keyPath(key), value);
  }
  void number(const char* key, double& value);
  void derived(const char* key, const std::string&) {
    std::string ignored;
    field(key, ignored);
  }
  void ints(const char* key, std::initializer_list<int*> values, int lo, int hi);
  void require(bool holds, const char* key, const char* what);
  void metrics(const char* key, ImageMetrics& m);
  void namedNumbers(const char* key, std::vector<std::pair<std::string, double>>& values);

  template <class S>
  void object(const char* key, S& sub) {
    const auto& j = at(key);
    expect(j.is_object(), keyPath(key), "an object");
    ResultsReader child(j, keyPath(key));
    fields(child, sub);
    child.finish();
  }
  template <class S>
  void optionalObject(const char* key, S& sub, bool) {
    if (has(key)) object(key, sub);
  }
  template <class S>
  void list(const char* key, std::vector<S>& items) {
    const auto& j = at(key);
    expect(j.is_array(), keyPath(key), "a list");
    items.assign(j.size(), S{});
    for (size_t i = 0; i < j.size(); ++i) {
      const std::string path = keyPath(key) + "[" + std::to_string(i) + "]";
      expect(j[i].is_object(), path, "an object");
      ResultsReader child(j[i], path);
      fields(child, items[i]);
      child.finish();
    }
  }
  template <class S>
  void optionalList(const char* key, std::vector<S>& items) {
    if (has(key)) list(key, items);
  }

  // Refuses a key of this object that the declaration did not visit.
  void finish() const;

 private:
  bool has(const char* key);
  const nlohmann::json& at(const char* key);
  std::string keyPath(const std::string& key) const;
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  void expect(bool ok, const std::string& path, const char* type) const {
    if (!ok) fail(path, std::string("expected ") + type);
  }

  void read(const nlohmann::json& j, const std::string& path, std::string& out);
  void read(const nlohmann::json& j, const std::string& path, bool& out);
  void read(const nlohmann::json& j, const std::string& path, int& out);
  void read(const nlohmann::json& j, const std::string& path, size_t& out);
  void read(const nlohmann::json& j, const std::string& path, double& out);
  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void read(const nlohmann::json& j, const std::string& path, E& out) {
    expect(j.is_string(), path, "a string");
    if (!spec::enumFromString(j.get_ref<const std::string&>(), out))
      fail(path, "'" + j.get<std::string>().substr(0, 40) + "' is not a value this format knows");
  }
  template <class T>
  void read(const nlohmann::json& j, const std::string& path, std::vector<T>& out) {
    expect(j.is_array(), path, "a list");
    out.assign(j.size(), T{});
    for (size_t i = 0; i < j.size(); ++i) read(j[i], path + "[" + std::to_string(i) + "]", out[i]);
  }
  template <class T>
  void read(const nlohmann::json& j, const std::string& path, std::map<std::string, T>& out) {
    expect(j.is_object(), path, "an object");
    out.clear();
    for (const auto& item : j.items()) read(item.value(), path + "." + item.key(), out[item.key()]);
  }

  const nlohmann::json& node_;
  std::string path_;
  std::set<std::string> visited_;
};

}  // namespace taa::run
