// A case's golden verdict: the goldens verified before use, every frame's hash against the
// positive of this run's environment where the set has one, the checked frames' images against
// the stored EXRs (bit-exact there, with tolerances where it has none), and staleness.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "api/frame_record.h"
#include "core/image.h"
#include "golden/environment.h"
#include "golden/golden_store.h"
#include "run/case_runner.h"
#include "run/results.h"
#include "run/run_folder.h"
#include "spec/checked_case.h"

namespace taa::run {

// The images of checked frame `fc.frame` in the case's folder of the run (actual; golden, diff
// heatmap and magnified worst region when there is a golden; the region `zoom` names instead
// when it has a size, with or without a golden), with their paths recorded in `fc`.
void writeFrameImages(const RunFolder& out, const std::string& caseName, FrameComparison& fc,
                      const Image& actual, const Image* golden, const Image* errorMap,
                      const spec::ZoomSpec& zoom = {});

// report.ab: the B side's output of the same frame, and its crop of the region writeFrameImages
// magnified, recorded in `fc` under `label`.
void writeAbImages(const RunFolder& out, const std::string& caseName, FrameComparison& fc,
                   const Image& b, const std::string& label);

class GoldenCheck {
 public:
  // Loads and verifies the case's goldens; a set that fails verification is remembered and
  // reported by finish(), so the case still renders and runs its invariants.
  GoldenCheck(const spec::CheckedCase& spec, const golden::Environment& env,
              const RunOptions& options);

  // Every rendered frame, in order, with its colour and hash: keeps the first frame whose
  // hash differs from the golden sequence (only where this environment has a positive).
  void observe(const FrameRecord& r);

  // The verdict, with result.frames, message, blessCommand, goldenFingerprint and
  // firstDifference filled in: Pass, NoGolden (or Fail when options.missingGoldenFails),
  // Stale (changed pixels of a case edited since its bless) or Fail. Then, with
  // options.writeImages, the frames' images: the verdict never depends on them.
  CaseStatus finish(const std::map<int, Image>& outputs, const std::string& caseSha,
                    CaseResult& result);

 private:
  // A stored frame's verdict and what its images are drawn from.
  struct StoredFrame {
    FrameComparison comparison;
    const Image* golden = nullptr;  // the stored EXR compared with, if any
    Image errorMap;                 // per pixel, when compared
    bool drawn = true;              // false: no image of it (sizes differ)
  };
  CaseStatus verdictWithoutGoldens(CaseResult& result) const;
  CaseStatus verdictWithGoldens(const std::string& caseSha, CaseResult& result);
  // Fills result.firstDifference when the sequence differs from the golden's; returns whether
  // it does.
  bool compareSequence(CaseResult& result);
  // The first differing frame's image and the golden frames around it, named in `d`.
  void writeFirstDifference(FirstDifference& d) const;
  FrameComparison missingGolden(int frame) const;
  // A stored (output) frame against its golden: by hash where this environment has a positive,
  // by the case's tolerances against the primary's EXR elsewhere.
  StoredFrame judgeStoredFrame(int frame, const Image& image) const;
  std::string toleranceNote() const;
  std::string requireExactNote() const;

  const spec::CheckedCase& spec_;
  const RunOptions& options_;
  std::filesystem::path dir_;  // goldens/NAME
  std::string environment_;    // this run's fingerprint
  std::optional<golden::GoldenSet> goldens_;
  std::string problem_;  // why the goldens cannot be used (GoldenError), empty when fine
  // How every frame is compared: by hash against this environment's positive where the set has
  // one, else by signature against the nearest positive (and the stored EXRs by tolerance).
  enum class Mode { None, Exact, Signature } mode_ = Mode::None;
  golden::Positive positive_;  // the positive compared with: this environment's, or the nearest
  bool ownPositive_ = false;   // positive_ is this environment's
  std::vector<std::string> sequence_;    // this run's hashes, frame by frame
  std::vector<std::string> signatures_;  // and signatures
  struct {
    int cell = 0, cellFrame = -1;
    double mean = 0.0;
    int meanFrame = -1;
  } worst_;
  int firstDiff_ = -1;
  std::string firstDiffWhy_;
  Image firstDiffImage_;
};

}  // namespace taa::run
