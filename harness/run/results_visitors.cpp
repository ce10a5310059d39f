#include "run/results_visitors.h"

#include "case/json_number.h"
#include "compare/metric_table.h"

namespace taa::run {

nlohmann::json encodeNumber(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

void ResultsWriter::metrics(const char* key, ImageMetrics& m) {
  auto& o = out_[key] = nlohmann::json::object();
  for (const auto* row : compare::goldenMetrics()) o[row->name] = encodeNumber(m.*row->golden);
}

void ResultsWriter::namedNumbers(const char* key,
                                 std::vector<std::pair<std::string, double>>& values) {
  auto& o = out_[key] = nlohmann::json::object();
  for (const auto& [k, v] : values) o[k] = encodeNumber(v);
}

ResultsReader::ResultsReader(const nlohmann::json& node, std::string path)
    : node_(node), path_(std::move(path)) {}

std::string ResultsReader::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void ResultsReader::fail(const std::string& path, const std::string& what) const {
  throw ResultsFormatError(path + ": " + what);
}

bool ResultsReader::has(const char* key) {
  visited_.insert(key);
  return node_.contains(key);
}

const nlohmann::json& ResultsReader::at(const char* key) {
  if (!has(key)) fail(keyPath(key), "missing (this format writes it)");
  return node_[key];
}

void ResultsReader::finish() const {
  for (const auto& item : node_.items())
    if (!visited_.count(item.key()))
      fail(keyPath(item.key().substr(0, 80)), "unknown key (not in this format)");
}

void ResultsReader::version(const char* key, int expected) {
  if (!node_.is_object()) fail("(top level)", "expected an object");
  visited_.insert(key);
  const auto it = node_.find(key);
  if (it == node_.end())
    fail(key, "missing: written before results.json carried a format version (this build reads " +
                  std::to_string(expected) + "); run the cases again to write it");
  int64_t found = 0;
  if (!jsonWholeIn(*it, 0, std::numeric_limits<int>::max(), found) || found != expected)
    fail(key, (it->is_number() ? "format " + it->dump() : std::string("not a version number")) +
                  ", where this build reads format " + std::to_string(expected) +
                  "; run the cases again with this build to write it");
}

void ResultsReader::number(const char* key, double& value) {
  const auto& j = at(key);
  if (j.is_number()) {
    value = j.get<double>();
    return;
  }
  const std::string text = j.is_string() ? j.get<std::string>() : "";
  if (text == "inf") value = std::numeric_limits<double>::infinity();
  else if (text == "-inf") value = -std::numeric_limits<double>::infinity();
  else if (text == "nan") value = std::numeric_limits<double>::quiet_NaN();
  else fail(keyPath(key), "expected a number, \"inf\", \"-inf\" or \"nan\"");
}

void ResultsReader::ints(const char* key, std::initializer_list<int*> values, int lo, int hi) {
  const auto& j = at(key);
  const std::string what = "a list of " + std::to_string(values.size()) + " whole numbers from " +
                           std::to_string(lo) + " to " + std::to_string(hi);
  if (!j.is_array() || j.size() != values.size()) fail(keyPath(key), "expected " + what);
  size_t i = 0;
  for (int* v : values) {
    // 4294967298 must not wrap to 2, nor 2.5 truncate to 2.
    int64_t x = 0;
    if (!jsonWholeIn(j[i++], lo, hi, x)) fail(keyPath(key), "expected " + what);
    *v = int(x);
  }
}

void ResultsReader::require(bool holds, const char* key, const char* what) {
  if (!holds) fail(keyPath(key), what);
}

void ResultsReader::metrics(const char* key, ImageMetrics& m) {
  const auto& j = at(key);
  expect(j.is_object(), keyPath(key), "an object");
  ResultsReader child(j, keyPath(key));
  for (const auto* row : compare::goldenMetrics()) child.number(row->name, m.*row->golden);
  child.finish();
}

void ResultsReader::namedNumbers(const char* key,
                                 std::vector<std::pair<std::string, double>>& values) {
  const auto& j = at(key);
  expect(j.is_object(), keyPath(key), "an object");
  ResultsReader child(j, keyPath(key));
  values.clear();
  for (const auto& item : j.items()) {
    values.emplace_back(item.key(), 0.0);
    child.number(item.key().c_str(), values.back().second);
  }
}

void ResultsReader::read(const nlohmann::json& j, const std::string& path, std::string& out) {
  expect(j.is_string(), path, "a string");
  out = j.get<std::string>();
}

void ResultsReader::read(const nlohmann::json& j, const std::string& path, bool& out) {
  expect(j.is_boolean(), path, "true or false");
  out = j.get<bool>();
}

void ResultsReader::read(const nlohmann::json& j, const std::string& path, int& out) {
  int64_t x = 0;
  expect(jsonWholeIn(j, std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), x), path,
         "a whole number within 32 bits");
  out = int(x);
}

void ResultsReader::read(const nlohmann::json& j, const std::string& path, size_t& out) {
  expect(j.is_number_unsigned(), path, "a whole number of at least 0");
  out = j.get<size_t>();
}

// A NaN or infinity written as a plain number comes out of nlohmann's dump as null.
void ResultsReader::read(const nlohmann::json& j, const std::string& path, double& out) {
  if (j.is_null()) {
    out = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  expect(j.is_number(), path, "a number");
  out = j.get<double>();
}

}  // namespace taa::run
