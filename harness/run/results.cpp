#include "run/results.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "compare/metric_table.h"
#include "core/errors.h"

namespace taa::run {

const char* toString(FrameStatus s) {
  switch (s) {
    case FrameStatus::Exact: return "exact";
    case FrameStatus::WithinTolerance: return "within_tolerance";
    case FrameStatus::Failed: return "failed";
    case FrameStatus::MissingGolden: return "missing_golden";
  }
  return "?";
}

const char* toString(CaseStatus s) {
  switch (s) {
    case CaseStatus::Pass: return "pass";
    case CaseStatus::Fail: return "fail";
    case CaseStatus::Stale: return "stale";
    case CaseStatus::NoGolden: return "no_golden";
    case CaseStatus::Error: return "error";
  }
  return "?";
}

CaseStatus worse(CaseStatus a, CaseStatus b) {
  return int(a) >= int(b) ? a : b;
}

namespace {

template <class E>
E fromString(const std::string& text, std::initializer_list<E> values) {
  for (E v : values)
    if (text == toString(v)) return v;
  throw InputError("results.json: unknown status '" + text +
                   "'; run the cases again to write a new one");
}

// JSON has no infinities: PSNR of identical images (+inf) and errors involving
// NaN or Inf pixels (+inf) are written as the strings "inf" / "-inf".
nlohmann::json number(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

double numberFrom(const nlohmann::json& j, const char* key) {
  if (!j.contains(key)) return 0.0;
  const auto& v = j[key];
  if (v.is_number()) return v.get<double>();
  const std::string s = v.is_string() ? v.get<std::string>() : "nan";
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  return std::numeric_limits<double>::quiet_NaN();
}

nlohmann::json metricsJson(const ImageMetrics& m) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto* row : compare::goldenMetrics()) out[row->name] = number(m.*row->golden);
  return out;
}

ImageMetrics metricsFrom(const nlohmann::json& j) {
  ImageMetrics m;
  for (const auto* row : compare::goldenMetrics()) m.*row->golden = numberFrom(j, row->name);
  return m;
}

}  // namespace

nlohmann::json toJson(const RunResults& r) {
  nlohmann::json out = {{"device", r.device},
                        {"fingerprint", r.fingerprint},
                        {"environment", r.environment.toJson()},
                        {"commit", r.commit},
                        {"build", r.build},
                        {"suite",
                         {{"cases", r.suite.cases},
                          {"sha256", r.suite.sha256},
                          {"shard", {r.suite.shardIndex, r.suite.shardCount}}}},
                        {"not_run", r.notRun},
                        {"cases", nlohmann::json::array()}};
  for (const auto& c : r.cases) {
    nlohmann::json jc = {{"name", c.name},
                         {"file", c.file},
                         {"case_sha256", c.caseSha256},
                         {"goldens_sha256", c.goldensSha256},
                         {"description", c.description},
                         {"status", toString(c.status)},
                         {"resolve", c.resolve},
                         {"golden_status", toString(c.goldenStatus)},
                         {"message", c.message},
                         {"bless_command", c.blessCommand},
                         {"fingerprint", c.fingerprint},
                         {"golden_fingerprint", c.goldenFingerprint},
                         {"golden_mode", c.goldenMode},
                         {"reference_rmse", c.referenceRmse},
                         {"frame_ms", c.frameMs},
                         {"frame_stats", c.frameStats},
                         {"log", c.log},
                         {"frame_sha256", c.frameSha256},
                         {"frame_signatures", c.frameSignatures},
                         {"seconds", c.seconds}};
    if (const auto& q = c.sequenceCheck; !q.mode.empty())
      jc["sequence_check"] = {{"mode", q.mode},
                              {"frames", q.frames},
                              {"worst_cell", q.worstCell},
                              {"worst_cell_frame", q.worstCellFrame},
                              {"worst_mean", q.worstMean},
                              {"worst_mean_frame", q.worstMeanFrame}};
    if (const auto& d = c.firstDifference; d.frame >= 0) {
      nlohmann::json n = nlohmann::json::array();
      for (const auto& g : d.goldenNeighbours)
        n.push_back({{"frame", g.frame}, {"image", g.image}});
      jc["first_difference"] = {{"frame", d.frame},
                                {"detail", d.detail},
                                {"actual_sha256", d.actualSha256},
                                {"golden_sha256", d.goldenSha256},
                                {"actual", d.actual},
                                {"golden_neighbours", n}};
    }
    for (const auto& f : c.frames) {
      const auto& i = f.images;
      jc["frames"].push_back({{"frame", f.frame},
                              {"status", toString(f.status)},
                              {"actual_sha256", f.actualSha256},
                              {"golden_sha256", f.goldenSha256},
                              {"tolerance_mode", f.toleranceMode},
                              {"metrics", metricsJson(f.metrics)},
                              {"failures", f.failures},
                              {"images",
                               {{"golden", i.golden},
                                {"actual", i.actual},
                                {"diff", i.diff},
                                {"zoom_golden", i.zoomGolden},
                                {"zoom_actual", i.zoomActual},
                                {"zoom_diff", i.zoomDiff},
                                {"zoom", {i.zoomX, i.zoomY, i.zoomW, i.zoomH}},
                                {"zoom_chosen", i.zoomChosen},
                                {"ab", i.ab},
                                {"zoom_ab", i.zoomAb},
                                {"ab_label", i.abLabel}}}});
    }
    for (const auto& inv : c.invariants) {
      nlohmann::json values = nlohmann::json::object();
      for (const auto& [k, v] : inv.values) values[k] = number(v);
      jc["invariants"].push_back(
          {{"name", inv.name}, {"passed", inv.passed}, {"detail", inv.detail}, {"values", values}});
    }
    for (const auto& t : c.timings)
      jc["timings"].push_back({{"pass", t.pass}, {"median_ms", t.medianMs}, {"p95_ms", t.p95Ms}});
    out["cases"].push_back(std::move(jc));
  }
  return out;
}

RunResults runResultsFromJson(const nlohmann::json& j) {
  RunResults r;
  r.device = j.value("device", "");
  r.fingerprint = j.value("fingerprint", "");
  if (j.contains("environment")) r.environment = golden::Environment::fromJson(j.at("environment"));
  r.commit = j.value("commit", "");
  r.build = j.value("build", "");
  r.notRun = j.value("not_run", size_t(0));
  if (j.contains("suite") && j["suite"].is_object()) {
    const auto& js = j["suite"];
    r.suite.cases = js.value("cases", std::vector<std::string>{});
    r.suite.sha256 = js.value("sha256", "");
    // Whole numbers as `run --shard I/N` takes them: 4294967298 must not wrap to 2, nor 2.5
    // truncate to 2 (nlohmann converts either silently).
    const auto shard = js.value("shard", nlohmann::json::array({1, 1}));
    auto whole = [](const nlohmann::json& v) {
      return v.is_number_unsigned() && v.get<uint64_t>() >= 1 && v.get<uint64_t>() <= 999999;
    };
    if (!shard.is_array() || shard.size() != 2 || !whole(shard[0]) || !whole(shard[1]) ||
        shard[0].get<uint64_t>() > shard[1].get<uint64_t>())
      throw std::runtime_error(
          "suite.shard is not [I, N] with whole numbers 1 <= I <= N <= 999999");
    r.suite.shardIndex = shard[0].get<int>();
    r.suite.shardCount = shard[1].get<int>();
  }
  for (const auto& jc : j.value("cases", nlohmann::json::array())) {
    CaseResult c;
    c.name = jc.value("name", "");
    c.file = jc.value("file", "");
    c.caseSha256 = jc.value("case_sha256", "");
    c.goldensSha256 = jc.value("goldens_sha256", "");
    c.description = jc.value("description", "");
    c.resolve = jc.value("resolve", "");
    c.status = fromString<CaseStatus>(jc.value("status", "error"), {CaseStatus::Pass, CaseStatus::Fail, CaseStatus::Stale,
                                                                     CaseStatus::NoGolden, CaseStatus::Error});
    c.goldenStatus = fromString<CaseStatus>(
        jc.value("golden_status", jc.value("status", "error")),
        {CaseStatus::Pass, CaseStatus::Fail, CaseStatus::Stale, CaseStatus::NoGolden, CaseStatus::Error});
    c.message = jc.value("message", "");
    c.blessCommand = jc.value("bless_command", "");
    c.fingerprint = jc.value("fingerprint", "");
    c.goldenFingerprint = jc.value("golden_fingerprint", "");
    c.goldenMode = jc.value("golden_mode", "");
    c.referenceRmse = jc.value("reference_rmse", std::vector<double>{});
    c.frameMs = jc.value("frame_ms", std::vector<double>{});
    c.frameStats = jc.value("frame_stats", std::map<std::string, std::vector<double>>{});
    c.log = jc.value("log", std::vector<std::string>{});
    c.seconds = jc.value("seconds", 0.0);
    c.frameSha256 = jc.value("frame_sha256", std::vector<std::string>{});
    c.frameSignatures = jc.value("frame_signatures", std::vector<std::string>{});
    if (jc.contains("sequence_check")) {
      const auto& jq = jc["sequence_check"];
      auto& q = c.sequenceCheck;
      q.mode = jq.value("mode", "");
      q.frames = jq.value("frames", 0);
      q.worstCell = jq.value("worst_cell", 0);
      q.worstCellFrame = jq.value("worst_cell_frame", -1);
      q.worstMean = jq.value("worst_mean", 0.0);
      q.worstMeanFrame = jq.value("worst_mean_frame", -1);
    }
    if (jc.contains("first_difference")) {
      const auto& jd = jc["first_difference"];
      auto& d = c.firstDifference;
      d.frame = jd.value("frame", -1);
      d.detail = jd.value("detail", "");
      d.actualSha256 = jd.value("actual_sha256", "");
      d.goldenSha256 = jd.value("golden_sha256", "");
      d.actual = jd.value("actual", "");
      for (const auto& n : jd.value("golden_neighbours", nlohmann::json::array()))
        d.goldenNeighbours.push_back({n.value("frame", 0), n.value("image", "")});
    }
    for (const auto& jf : jc.value("frames", nlohmann::json::array())) {
      FrameComparison f;
      f.frame = jf.value("frame", 0);
      f.status = fromString<FrameStatus>(jf.value("status", "failed"), {FrameStatus::Exact, FrameStatus::WithinTolerance,
                                                                         FrameStatus::Failed, FrameStatus::MissingGolden});
      f.actualSha256 = jf.value("actual_sha256", "");
      f.goldenSha256 = jf.value("golden_sha256", "");
      f.toleranceMode = jf.value("tolerance_mode", false);
      f.metrics = metricsFrom(jf.value("metrics", nlohmann::json::object()));
      f.failures = jf.value("failures", std::vector<std::string>{});
      const auto ji = jf.value("images", nlohmann::json::object());
      f.images.golden = ji.value("golden", "");
      f.images.actual = ji.value("actual", "");
      f.images.diff = ji.value("diff", "");
      f.images.zoomGolden = ji.value("zoom_golden", "");
      f.images.zoomActual = ji.value("zoom_actual", "");
      f.images.zoomDiff = ji.value("zoom_diff", "");
      f.images.zoomChosen = ji.value("zoom_chosen", false);
      f.images.ab = ji.value("ab", "");
      f.images.zoomAb = ji.value("zoom_ab", "");
      f.images.abLabel = ji.value("ab_label", "");
      const auto zoom = ji.value("zoom", std::vector<int>{0, 0, 0, 0});
      if (zoom.size() == 4) {
        f.images.zoomX = zoom[0];
        f.images.zoomY = zoom[1];
        f.images.zoomW = zoom[2];
        f.images.zoomH = zoom[3];
      }
      c.frames.push_back(std::move(f));
    }
    for (const auto& ji : jc.value("invariants", nlohmann::json::array())) {
      InvariantResult inv;
      inv.name = ji.value("name", "");
      inv.passed = ji.value("passed", false);
      inv.detail = ji.value("detail", "");
      const auto values = ji.value("values", nlohmann::json::object());
      for (const auto& item : values.items()) inv.values.emplace_back(item.key(), numberFrom(values, item.key().c_str()));
      c.invariants.push_back(std::move(inv));
    }
    for (const auto& jt : jc.value("timings", nlohmann::json::array()))
      c.timings.push_back({jt.value("pass", ""), jt.value("median_ms", 0.0), jt.value("p95_ms", 0.0)});
    r.cases.push_back(std::move(c));
  }
  return r;
}

}  // namespace taa::run
