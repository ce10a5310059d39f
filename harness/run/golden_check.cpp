#include "run/golden_check.h"

#include <algorithm>
#include <cstdio>

#include "compare/heatmap.h"
#include "compare/tolerance.h"
#include "core/image_io.h"
#include "golden/case_owner.h"
#include "golden/signature.h"

namespace taa::run {

namespace fs = std::filesystem;

namespace {

std::string blessCommandFor(const spec::CaseSpec& spec) {
  return "taa-harness bless " + spec.file.string() + " --reason \"<why the image changed>\"";
}

std::string shortSha(const std::string& sha) {
  return sha.substr(0, 12);
}

// Magnification of a crop: about 256 px wide, whole pixels.
int zoomFactor(int width) {
  return std::max(1, 256 / std::max(1, width));
}

}  // namespace

namespace {

// One frame's files in a case's folder of the run: where each is written, and the name
// results.json and the report give it.
struct FrameFiles {
  RunFolder out;
  std::string caseName;
  int frame;
  fs::path path(FrameFile kind) const { return out.caseFolder(caseName) / frameFileName(frame, kind); }
  std::string rel(FrameFile kind) const { return RunFolder::caseFile(caseName, frame, kind); }
  std::string png(FrameFile kind, const Image& image) const {
    writePng(path(kind), image);
    return rel(kind);
  }
};

}  // namespace

void writeFrameImages(const RunFolder& out, const std::string& caseName, FrameComparison& fc,
                      const Image& actual, const Image* golden, const Image* errorMap,
                      const spec::ZoomSpec& zoom) {
  const FrameFiles files{out, caseName, fc.frame};
  writeExr(files.path(FrameFile::Exr), actual);
  fc.images.actual = files.png(FrameFile::Png, actual);
  if (golden) fc.images.golden = files.png(FrameFile::GoldenPng, *golden);
  if (golden && errorMap) {
    writePngLinear8(files.path(FrameFile::DiffPng), compare::heatmap(*errorMap));
    fc.images.diff = files.rel(FrameFile::DiffPng);
  }
  // The region the case chose (report.zoom), or else the worst tenth of the frame, magnified
  // so single pixels are visible.
  compare::Region region;
  if (zoom.width > 0 && zoom.height > 0) {
    region.x = std::min(zoom.x, actual.width - 1);
    region.y = std::min(zoom.y, actual.height - 1);
    region.width = std::min(zoom.width, actual.width - region.x);
    region.height = std::min(zoom.height, actual.height - region.y);
    fc.images.zoomChosen = true;
  } else if (golden && errorMap &&
             std::any_of(errorMap->data.begin(), errorMap->data.end(),
                         [](float e) { return e != 0.0f; })) {
    // (An exact match has no worst region: the crop would show an arbitrary corner.)
    const int w = std::max(1, std::min(actual.width, std::max(8, actual.width / 10)));
    const int h = std::max(1, std::min(actual.height, std::max(8, actual.height / 10)));
    region = compare::worstRegion(*errorMap, w, h);
  } else {
    return;
  }
  const int factor = zoomFactor(region.width);
  auto zoomed = [&](const Image& img) {
    return compare::upscaleNearest(
        compare::crop(img, region.x, region.y, region.width, region.height), factor);
  };
  fc.images.zoomActual = files.png(FrameFile::ZoomActualPng, zoomed(actual));
  if (golden) fc.images.zoomGolden = files.png(FrameFile::ZoomGoldenPng, zoomed(*golden));
  if (golden && errorMap) {
    writePngLinear8(files.path(FrameFile::ZoomDiffPng), zoomed(compare::heatmap(*errorMap)));
    fc.images.zoomDiff = files.rel(FrameFile::ZoomDiffPng);
  }
  fc.images.zoomX = region.x;
  fc.images.zoomY = region.y;
  fc.images.zoomW = region.width;
  fc.images.zoomH = region.height;
}

void writeAbImages(const RunFolder& out, const std::string& caseName, FrameComparison& fc,
                   const Image& b, const std::string& label) {
  const FrameFiles files{out, caseName, fc.frame};
  fc.images.ab = files.png(FrameFile::AbPng, b);
  fc.images.abLabel = label;
  const auto& im = fc.images;
  if (im.zoomW <= 0 || im.zoomH <= 0) return;
  const Image crop = compare::crop(b, im.zoomX, im.zoomY, im.zoomW, im.zoomH);
  fc.images.zoomAb =
      files.png(FrameFile::ZoomAbPng, compare::upscaleNearest(crop, zoomFactor(im.zoomW)));
}

namespace {

// Of the positives, the one whose environment shares the most with `env` (device, driver, Vulkan
// version, CPU level, in that order of weight); the primary on a tie, since its EXRs are the
// ones the stored frames are compared with anyway.
const golden::Positive& nearestPositive(const std::vector<golden::Positive>& all,
                                        const golden::Environment& env) {
  auto score = [&](const golden::Environment& e) {
    return (e.device == env.device) * 8 + (e.driverInfo == env.driverInfo) * 4 +
           (e.apiVersion == env.apiVersion) * 2 + (e.cpuFeatures == env.cpuFeatures);
  };
  const golden::Positive* best = &all.front();
  for (const auto& p : all)
    if (score(p.environment) > score(best->environment)) best = &p;
  return *best;
}

}  // namespace

GoldenCheck::GoldenCheck(const spec::CheckedCase& spec, const golden::Environment& env,
                         const RunOptions& options)
    : spec_(spec), options_(options), environment_(env.fingerprint()) {
  const fs::path root =
      options.goldensRoot.empty() ? defaultGoldensRoot(spec.file) : options.goldensRoot;
  dir_ = root / spec.name;
  try {
    goldens_ = golden::loadGoldens(root, spec.name);
    if (goldens_) problem_ = golden::otherCaseProblem(goldens_->manifest, root, spec.file);
  } catch (const golden::GoldenError& e) {
    problem_ = e.what();
  }
  // Hashes are comparable only where lavapipe reproduces a positive's bytes; elsewhere every
  // frame's signature is compared within tolerances.
  if (!goldens_ || !problem_.empty()) return;
  const auto all = goldens_->manifest.positives();
  if (const auto own = goldens_->manifest.positiveFor(environment_)) {
    positive_ = *own;
    ownPositive_ = true;
    mode_ = positive_.sequence.empty() ? Mode::None : Mode::Exact;
  } else {
    positive_ = nearestPositive(all, env);
    mode_ = positive_.signatures.empty() ? Mode::None : Mode::Signature;
  }
}

void GoldenCheck::observe(const FrameRecord& r) {
  sequence_.push_back(r.colorSha256);
  signatures_.push_back(golden::frameSignature(r.color));
  if (mode_ == Mode::None) return;
  const auto f = size_t(r.frame);
  std::string why;
  if (mode_ == Mode::Exact) {
    const auto& golden = positive_.sequence;
    if (f < golden.size() && golden[f] != r.colorSha256) why = "pixels";
  } else if (const auto& golden = positive_.signatures; f < golden.size()) {
    const auto d = golden::signatureDistance(golden[f], signatures_.back());
    auto& q = worst_;
    if (d.cell > q.cell) {
      q.cell = d.cell;
      q.cellFrame = r.frame;
    }
    if (d.mean > q.mean) {
      q.mean = d.mean;
      q.meanFrame = r.frame;
    }
    if (!d.valid) why = "its golden signature is malformed";
    if (d.cell > golden::kSignatureCellTolerance)
      why = "the mean luma of cell (row " + std::to_string(d.cellIndex / golden::kSignatureGrid) +
            ", column " + std::to_string(d.cellIndex % golden::kSignatureGrid) + " of " +
            std::to_string(golden::kSignatureGrid) + "x" + std::to_string(golden::kSignatureGrid) +
            ") differs by " + std::to_string(d.cell) + "/255 > " +
            std::to_string(golden::kSignatureCellTolerance) + "/255";
    if (d.mean > golden::kSignatureMeanTolerance)
      why += (why.empty() ? "" : "; ") + std::string("a channel's frame mean differs by ") +
             std::to_string(d.mean) + " > " + std::to_string(golden::kSignatureMeanTolerance);
  }
  if (!why.empty() && firstDiff_ < 0) {
    firstDiff_ = r.frame;
    firstDiffWhy_ = why;
    firstDiffImage_ = r.color;
  }
}

bool GoldenCheck::compareSequence(CaseResult& result) {
  const bool exact = mode_ == Mode::Exact;
  const auto& golden = exact ? positive_.sequence : positive_.signatures;
  auto& q = result.sequenceCheck;
  q.mode = exact ? "exact" : "signature";
  q.frames = int(std::min(golden.size(), sequence_.size()));
  q.worstCell = worst_.cell;
  q.worstCellFrame = worst_.cellFrame;
  q.worstMean = worst_.mean;
  q.worstMeanFrame = worst_.meanFrame;
  auto& d = result.firstDifference;
  if (firstDiff_ < 0) {
    if (golden.size() == sequence_.size()) return false;
    const size_t common = std::min(golden.size(), sequence_.size());
    d.frame = int(common);
    d.detail = "the golden sequence has " + std::to_string(golden.size()) + " frames, this run " +
               std::to_string(sequence_.size()) + "; the first " + std::to_string(common) +
               (exact ? " are identical" : " are within tolerance");
    return true;
  }
  const int f = firstDiff_;
  d.frame = f;
  if (exact) {
    d.actualSha256 = sequence_.at(size_t(f));
    d.goldenSha256 = golden.at(size_t(f));
    d.detail = "frame " + std::to_string(f) +
               " is the first whose pixels differ from the golden sequence (sha256 " +
               shortSha(d.actualSha256) + " != " + shortSha(d.goldenSha256) + ")" +
               (f > 0 ? "; frames 0-" + std::to_string(f - 1) + " are identical" : "");
  } else {
    d.detail =
        "frame " + std::to_string(f) +
        " is the first whose signature is out of tolerance against the nearest positive's (" +
        positive_.environment.fingerprint() + "): " + firstDiffWhy_ +
        (f > 0 ? "; frames 0-" + std::to_string(f - 1) + " are within tolerance" : "");
  }
  return true;
}

void GoldenCheck::writeFirstDifference(FirstDifference& d) const {
  const FrameFiles files{RunFolder(options_.outDir), spec_.name, d.frame};
  writeExr(files.path(FrameFile::Exr), firstDiffImage_);
  d.actual = files.png(FrameFile::Png, firstDiffImage_);
  // The stored golden frames around it: what the sequence looked like where it was right.
  const golden::GoldenFrame* before = nullptr;
  const golden::GoldenFrame* after = nullptr;
  for (const auto& gf : goldens_->manifest.frames) {
    if (gf.frame <= d.frame && (!before || gf.frame > before->frame)) before = &gf;
    if (gf.frame >= d.frame && (!after || gf.frame < after->frame)) after = &gf;
  }
  for (const auto* gf : {before, after}) {
    if (!gf || (gf == after && after == before)) continue;
    const FrameFiles neighbour{files.out, spec_.name, gf->frame};
    d.goldenNeighbours.push_back(
        {gf->frame, neighbour.png(FrameFile::GoldenPng, goldens_->load(*gf))});
  }
}

CaseStatus GoldenCheck::finish(const std::map<int, Image>& outputs, const std::string& caseSha,
                               CaseResult& result) {
  result.blessCommand = blessCommandFor(spec_);
  result.frameSha256 = sequence_;
  result.frameSignatures = signatures_;
  // Unusable goldens are never compared with: every stored frame is then a missing golden.
  const bool usable = problem_.empty() && goldens_;
  for (const auto& [frame, image] : outputs) {
    StoredFrame stored = usable ? judgeStoredFrame(frame, image) : StoredFrame{missingGolden(frame)};
    if (options_.writeImages && stored.drawn)
      writeFrameImages(RunFolder(options_.outDir), spec_.name, stored.comparison, image,
                       stored.golden, stored.golden ? &stored.errorMap : nullptr,
                       spec_.report.zoom);
    result.frames.push_back(std::move(stored.comparison));
  }
  if (!usable) return verdictWithoutGoldens(result);
  const CaseStatus status = verdictWithGoldens(caseSha, result);
  if (options_.writeImages && firstDiff_ >= 0) writeFirstDifference(result.firstDifference);
  return status;
}

CaseStatus GoldenCheck::verdictWithoutGoldens(CaseResult& result) const {
  if (!problem_.empty()) {
    result.message = "goldens cannot be used: " + problem_;
    return CaseStatus::Fail;
  }
  // Missing goldens are a skip outside CI.
  result.message = "no goldens in " + dir_.string() + "; look at the frames, then bless them";
  if (!options_.missingGoldenFails) return CaseStatus::NoGolden;
  result.message += " (CI=true: a case without goldens fails in CI)";
  return CaseStatus::Fail;
}

CaseStatus GoldenCheck::verdictWithGoldens(const std::string& caseSha, CaseResult& result) {
  const auto& m = goldens_->manifest;
  result.goldenFingerprint = positive_.environment.fingerprint();
  result.goldenMode = ownPositive_ ? "exact" : "tolerance";
  bool anyFailed = std::any_of(result.frames.begin(), result.frames.end(), [](const auto& f) {
    return f.status == FrameStatus::Failed || f.status == FrameStatus::MissingGolden;
  });
  std::vector<std::string> notes;
  const bool missingPositive = !ownPositive_ && options_.requireExact;
  if (ownPositive_ && positive_.sequence.empty()) {
    notes.push_back(
        (dir_ / "manifest.json").string() +
        " has no frame_sha256 (blessed before every frame was hashed), so only the stored frames "
        "were checked; re-bless it");
    anyFailed = true;
  }
  if (!ownPositive_ && positive_.signatures.empty()) {
    notes.push_back((dir_ / "manifest.json").string() +
                    " has no frame_signatures (blessed before frames had signatures), so only the "
                    "stored frames were checked in this environment; re-bless it");
    anyFailed = true;
  }
  if (mode_ != Mode::None) anyFailed |= compareSequence(result);
  const bool stale = m.caseSha256 != caseSha;
  if (stale) {
    // An edit that changed no frame (a description, a comment's worth of JSON) keeps its pass;
    // one whose frames match no positive is stale on every path, the tolerance path too.
    const auto all = m.positives();
    const bool asBlessed = std::any_of(all.begin(), all.end(), [&](const golden::Positive& p) {
      return !p.sequence.empty() && p.sequence == sequence_;
    });
    notes.push_back(
        "the case file (or a file it references) changed since its goldens were blessed (" +
        m.bless.date + ", \"" + m.bless.reason + "\")" +
        (asBlessed ? "; its frames are still those of a positive"
                   : "; its frames match no positive"));
    anyFailed |= !asBlessed;
  }
  // Last: what failed or went stale reads first where a summary cuts the message short.
  if (!ownPositive_) notes.push_back(toleranceNote());
  if (missingPositive) notes.push_back(requireExactNote());
  for (const auto& n : notes) result.message += (result.message.empty() ? "" : "; ") + n;
  // Frames within tolerance on a machine without its positive: what is missing is the positive,
  // not a new image, so the hint adds this environment; a plain bless here would replace the set
  // and drop the machine that blessed it. (A stale case needs the plain bless: --add-environment
  // refuses a case changed since its bless.)
  if (!ownPositive_ && !anyFailed && !stale)
    result.blessCommand = "taa-harness bless --add-environment " + spec_.file.string() +
                          " --reason \"<which machine this is>\"";
  if (!anyFailed && !missingPositive) return CaseStatus::Pass;
  return stale && anyFailed ? CaseStatus::Stale : CaseStatus::Fail;
}

std::string GoldenCheck::toleranceNote() const {
  return "tolerance: no positive for " + environment_ + " (compared with the positive of " +
         positive_.environment.fingerprint() + ")";
}

std::string GoldenCheck::requireExactNote() const {
  return "--require-exact: no positive for this environment; add one from a run here with "
         "`taa-harness bless --add-environment " +
         spec_.file.string() +
         " --reason \"<which machine>\"` or `taa-harness bless --from OUT --add-environment " +
         spec_.file.string() + " --reason \"...\"`";
}

FrameComparison GoldenCheck::missingGolden(int frame) const {
  FrameComparison fc;
  fc.frame = frame;
  fc.status = FrameStatus::MissingGolden;
  fc.actualSha256 = sequence_.at(size_t(frame));
  return fc;
}

GoldenCheck::StoredFrame GoldenCheck::judgeStoredFrame(int frame, const Image& image) const {
  StoredFrame stored{missingGolden(frame)};
  FrameComparison& fc = stored.comparison;
  fc.toleranceMode = !ownPositive_;
  const golden::GoldenFrame* gf = goldens_->manifest.find(frame);
  if (!gf) {
    fc.failures.push_back("frame " + std::to_string(frame) + " is checked but was never blessed");
    return stored;
  }
  // The stored EXR is the primary positive's; another environment's positive has only its hash.
  const auto& own = positive_.sequence;
  fc.goldenSha256 = ownPositive_ && size_t(frame) < own.size() ? own[size_t(frame)] : gf->sha256;
  const Image& goldenImage = goldens_->load(*gf);
  if (!goldenImage.sameShape(image)) {
    fc.status = FrameStatus::Failed;
    fc.failures.push_back("size " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + " differs from the golden's " +
                          std::to_string(goldenImage.width) + "x" +
                          std::to_string(goldenImage.height));
    stored.drawn = false;  // no heatmap of images of two sizes
    return stored;
  }
  auto measured =
      compare::measureAgainstGolden(goldenImage, image, spec_.checks.tolerance.pixel_threshold);
  fc.metrics = measured.metrics;
  if (fc.actualSha256 == fc.goldenSha256) {
    fc.status = FrameStatus::Exact;
  } else if (ownPositive_) {
    // This environment has a positive: lavapipe reproduces bytes, so any change is real.
    fc.status = FrameStatus::Failed;
    fc.failures.push_back("pixels differ from this environment's positive (sha256 " +
                          shortSha(fc.actualSha256) + " != " + shortSha(fc.goldenSha256) + ")");
  } else {
    fc.failures = compare::toleranceViolations(fc.metrics, spec_.checks.tolerance);
    fc.status = fc.failures.empty() ? FrameStatus::WithinTolerance : FrameStatus::Failed;
  }
  stored.golden = &goldenImage;
  stored.errorMap = std::move(measured.errorMap);
  return stored;
}

}  // namespace taa::run
