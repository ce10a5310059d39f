#include "run/results.h"

#include <nlohmann/json.hpp>

#include "run/results_format.h"

namespace taa::run {

const char* toString(FrameStatus s) {
  return spec::enumToString(s);
}

const char* toString(CaseStatus s) {
  return spec::enumToString(s);
}

CaseStatus worse(CaseStatus a, CaseStatus b) {
  return int(a) >= int(b) ? a : b;
}

nlohmann::json toJson(const RunResults& r) {
  nlohmann::json out;
  RunResults copy = r;  // the visitor walks mutable fields, as the case writer does
  ResultsWriter writer(out);
  fields(writer, copy);
  return out;
}

RunResults runResultsFromJson(const nlohmann::json& j) {
  RunResults r;
  ResultsReader reader(j, "");
  fields(reader, r);
  reader.finish();
  return r;
}

}  // namespace taa::run
