// results.json, declared once: every key of every object a run's results hold, walked by the
// writer and the reader alike (run/results_visitors.h), as the case file's fields() are. A key
// renamed here is renamed for both; a file of another format_version is refused as a whole.
// Keys are written in alphabetical order (nlohmann's objects), whatever the order here.
#pragma once

#include "run/results.h"
#include "run/results_visitors.h"

namespace taa::run {

// Raise it when a key is added, renamed, removed or changes meaning: a reader then names the
// version instead of misreading the file. 1: the first versioned format (no key of the
// unversioned files before it changed).
inline constexpr int kResultsFormatVersion = 1;

template <class V>
void fields(V& v, golden::Environment& e) {
  v.field("device", e.device);
  v.field("driver_name", e.driverName);
  v.field("driver_info", e.driverInfo);
  v.field("api_version", e.apiVersion);
  v.field("cpu_features", e.cpuFeatures);
  v.derived("fingerprint", e.fingerprint());
}

template <class V>
void fields(V& v, SuiteInfo& s) {
  v.field("cases", s.cases);
  v.field("sha256", s.sha256);
  v.ints("shard", {&s.shardIndex, &s.shardCount}, 1, 999999);  // as run --shard I/N takes it
  v.require(s.shardIndex <= s.shardCount, "shard", "expected [I, N] with I <= N");
}

template <class V>
void fields(V& v, FrameImages& i) {
  v.field("golden", i.golden);
  v.field("actual", i.actual);
  v.field("diff", i.diff);
  v.field("zoom_golden", i.zoomGolden);
  v.field("zoom_actual", i.zoomActual);
  v.field("zoom_diff", i.zoomDiff);
  v.ints("zoom", {&i.zoomX, &i.zoomY, &i.zoomW, &i.zoomH}, 0, 1 << 20);
  v.field("zoom_chosen", i.zoomChosen);
  v.field("ab", i.ab);
  v.field("zoom_ab", i.zoomAb);
  v.field("ab_label", i.abLabel);
}

template <class V>
void fields(V& v, FrameComparison& f) {
  v.field("frame", f.frame);
  v.field("status", f.status);
  v.field("actual_sha256", f.actualSha256);
  v.field("golden_sha256", f.goldenSha256);
  v.field("tolerance_mode", f.toleranceMode);
  v.metrics("metrics", f.metrics);  // one key per golden metric (compare/metric_table.h)
  v.field("failures", f.failures);
  v.object("images", f.images);
}

template <class V>
void fields(V& v, FirstDifference::Neighbour& n) {
  v.field("frame", n.frame);
  v.field("image", n.image);
}

template <class V>
void fields(V& v, FirstDifference& d) {
  v.field("frame", d.frame);
  v.field("detail", d.detail);
  v.field("actual_sha256", d.actualSha256);
  v.field("golden_sha256", d.goldenSha256);
  v.field("actual", d.actual);
  v.list("golden_neighbours", d.goldenNeighbours);
}

template <class V>
void fields(V& v, CaseResult::SequenceCheck& q) {
  v.field("mode", q.mode);
  v.field("frames", q.frames);
  v.field("worst_cell", q.worstCell);
  v.field("worst_cell_frame", q.worstCellFrame);
  v.field("worst_mean", q.worstMean);
  v.field("worst_mean_frame", q.worstMeanFrame);
}

template <class V>
void fields(V& v, InvariantResult& i) {
  v.field("name", i.name);
  v.field("passed", i.passed);
  v.field("detail", i.detail);
  v.namedNumbers("values", i.values);
}

template <class V>
void fields(V& v, PassTiming& t) {
  v.field("pass", t.pass);
  v.field("median_ms", t.medianMs);
  v.field("p95_ms", t.p95Ms);
}

template <class V>
void fields(V& v, CaseResult& c) {
  v.field("name", c.name);
  v.field("file", c.file);
  v.field("case_sha256", c.caseSha256);
  v.field("goldens_sha256", c.goldensSha256);
  v.field("description", c.description);
  v.field("status", c.status);
  v.field("resolve", c.resolve);
  v.field("golden_status", c.goldenStatus);
  v.field("message", c.message);
  v.field("bless_command", c.blessCommand);
  v.field("fingerprint", c.fingerprint);
  v.field("golden_fingerprint", c.goldenFingerprint);
  v.field("golden_mode", c.goldenMode);
  v.field("reference_rmse", c.referenceRmse);
  v.field("frame_ms", c.frameMs);
  v.field("frame_stats", c.frameStats);
  v.field("log", c.log);
  v.field("frame_sha256", c.frameSha256);
  v.field("frame_signatures", c.frameSignatures);
  v.field("seconds", c.seconds);
  // Only for the checks that ran: a sequence compared, a frame that differs, frames stored,
  // invariants judged, passes timed.
  v.optionalObject("sequence_check", c.sequenceCheck, !c.sequenceCheck.mode.empty());
  v.optionalObject("first_difference", c.firstDifference, c.firstDifference.frame >= 0);
  v.optionalList("frames", c.frames);
  v.optionalList("invariants", c.invariants);
  v.optionalList("timings", c.timings);
}

template <class V>
void fields(V& v, RunResults& r) {
  v.version("format_version", kResultsFormatVersion);
  v.field("device", r.device);
  v.field("fingerprint", r.fingerprint);
  v.object("environment", r.environment);
  v.field("commit", r.commit);
  v.field("build", r.build);
  v.object("suite", r.suite);
  v.field("not_run", r.notRun);
  v.list("cases", r.cases);
}

}  // namespace taa::run
