// What a run found, case by case: the data behind the console lines, results.json,
// the JUnit file and the HTML report.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "golden/environment.h"
#include "spec/fields.h"

namespace taa::run {

struct ImageMetrics {
  double maxAbs = 0.0;
  double rmse = 0.0;
  double psnr = 0.0;
  double shareOver = 0.0;
  double flipMean = 0.0;
  double flipP99 = 0.0;
};

// Paths are relative to the run's output folder (where report.html lives).
struct FrameImages {
  std::string golden;       // PNG of the golden frame (tonemapped)
  std::string actual;       // PNG of this run's frame
  std::string diff;         // heatmap PNG of the per-pixel error
  std::string zoomGolden;   // magnified crop of the worst region
  std::string zoomActual;
  std::string zoomDiff;
  int zoomX = 0, zoomY = 0, zoomW = 0, zoomH = 0;  // the crop in frame pixels
  bool zoomChosen = false;                         // the case's report.zoom, not the worst region
  std::string ab;       // report.ab: PNG of the B side's output of this frame
  std::string zoomAb;   // and its crop
  std::string abLabel;  // what B is ("preset variance_ycocg")
};

enum class FrameStatus { Exact, WithinTolerance, Failed, MissingGolden };
// Their names in results.json, the console and the report: one list (toString reads it).
TAA_ENUM_NAMES(FrameStatus, {FrameStatus::Exact, "exact"},
               {FrameStatus::WithinTolerance, "within_tolerance"}, {FrameStatus::Failed, "failed"},
               {FrameStatus::MissingGolden, "missing_golden"})

struct FrameComparison {
  int frame = 0;
  FrameStatus status = FrameStatus::Failed;
  std::string actualSha256;
  std::string goldenSha256;
  bool toleranceMode = false;  // environment differs from the golden's: thresholds apply
  ImageMetrics metrics;
  std::vector<std::string> failures;  // "rmse 0.021 > 0.01", one per violated threshold
  FrameImages images;
};

struct InvariantResult {
  std::string name;
  bool passed = false;
  std::string detail;
  std::vector<std::pair<std::string, double>> values;
};

// In order of severity: a case's status is the worst of its checks (worse()). NoGolden is a
// skip: a case without goldens whose other checks pass (outside CI; under CI=true it is Fail).
enum class CaseStatus { Pass, NoGolden, Stale, Fail, Error };
TAA_ENUM_NAMES(CaseStatus, {CaseStatus::Pass, "pass"}, {CaseStatus::NoGolden, "no_golden"},
               {CaseStatus::Stale, "stale"}, {CaseStatus::Fail, "fail"},
               {CaseStatus::Error, "error"})

CaseStatus worse(CaseStatus a, CaseStatus b);

// The first frame whose pixels differ from the golden's frame_sha256, in the golden's own
// environment (where any changed bit is a regression). frame -1: none differs or the
// sequence was not compared.
struct FirstDifference {
  int frame = -1;
  std::string detail;  // one sentence: which frame, which hashes, what matched before it
  std::string actualSha256;
  std::string goldenSha256;
  std::string actual;  // PNG of this run's frame (relative to the report)
  struct Neighbour {
    int frame = 0;
    std::string image;  // PNG of the stored golden frame
  };
  std::vector<Neighbour> goldenNeighbours;  // the stored golden frames nearest before and after
};

struct PassTiming {
  std::string pass;
  double medianMs = 0.0;
  double p95Ms = 0.0;
};

struct CaseResult {
  std::string name;
  std::string file;
  std::string caseSha256;     // of the case's inputs (cases::LoadedCase::sha256)
  std::string description;
  std::string resolve;  // the user's shader and its parameters; "" for the built-in resolve
  CaseStatus status = CaseStatus::Error;
  // The golden comparison's own verdict (Pass without goldens to check), so the console can
  // tell a missing golden that is a skip from one that fails (CI=true) when an invariant
  // fails the case either way.
  CaseStatus goldenStatus = CaseStatus::Pass;
  std::string message;        // error text, or the stale/no-golden explanation
  std::string blessCommand;   // what to run when the change is intended
  std::string fingerprint;    // this run's environment
  std::string goldenFingerprint;  // the positive compared with (this environment's, or the nearest)
  // "exact": this environment has a positive, any changed byte fails; "tolerance": it has none,
  // frames were compared within tolerances with goldenFingerprint's; "": no goldens compared.
  std::string goldenMode;
  std::string goldensSha256;  // the case's golden folder as this run read it (run::folderDigest)
  std::vector<FrameComparison> frames;
  FirstDifference firstDifference;
  std::vector<std::string> frameSha256;  // every rendered frame's pixel hash, when goldens apply
  std::vector<std::string> frameSignatures;  // and golden::frameSignature (bless, bless --from)
  // How every frame compared with the golden sequence: "exact" (hashes, this environment's positive),
  // "signature" (within tolerances, elsewhere) or "" (not compared); with the largest signature
  // distances seen, so the tolerances can be judged against real runs.
  struct SequenceCheck {
    std::string mode;
    int frames = 0;
    int worstCell = 0;  // 8-bit steps of a cell's mean luma
    int worstCellFrame = -1;
    double worstMean = 0.0;  // a channel's frame mean, in [0, 1]
    int worstMeanFrame = -1;
  } sequenceCheck;
  std::vector<InvariantResult> invariants;
  std::vector<double> referenceRmse;  // per frame against the reference; empty without one
  std::vector<double> frameMs;        // per frame, all passes together
  // Per-frame figures the renderer reports by name (adaptive: traced_share, fxaa_share).
  std::map<std::string, std::vector<double>> frameStats;
  std::vector<PassTiming> timings;
  std::vector<std::string> log;       // passes and buffers the renderer allocated
  double seconds = 0.0;               // wall time of the case (not a result, for scheduling)
  int framesRendered = 0;             // every replay's frames (repeat, report.ab); not in JSON
};

// The cases a run was asked for before --shard kept its share: what `merge` checks shards
// against (the same suite, every shard present once).
struct SuiteInfo {
  std::vector<std::string> cases;  // every case name, in case order
  std::string sha256;              // of every case's name and inputs (files, scenes, tracks)
  int shardIndex = 1;              // --shard I/N; 1/1 without
  int shardCount = 1;
};

struct RunResults {
  std::string device;
  std::string fingerprint;
  golden::Environment environment;  // the same, field by field: what `bless --from` adds
  std::string commit;               // the harness's source commit (golden::rendererCommit)
  std::string build;  // the executable, SPIR-V, CPU level and device asked for (build_identity.h)
  SuiteInfo suite;
  size_t notRun = 0;   // cases --fail-fast left out after the first failure
  std::vector<CaseResult> cases;
};

const char* toString(FrameStatus s);
const char* toString(CaseStatus s);
// results.json through its one declaration (run/results_format.h). The reader throws
// ResultsFormatError (run/results_visitors.h) naming the key path of a missing, unknown or
// mistyped key, or the format_version when it is not this build's; RunFolder::readResults
// adds the file's name and the fix.
nlohmann::json toJson(const RunResults& r);
RunResults runResultsFromJson(const nlohmann::json& j);

}  // namespace taa::run
