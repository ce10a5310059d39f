#include "cli/bless_source.h"

#include <algorithm>

#include "cli/options.h"
#include "core/exr_codec.h"
#include "core/image_io.h"
#include "golden/signature.h"
#include "run/build_identity.h"
#include "run/golden_check.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {

// The SPIR-V digest a run's build identity names ("... | spirv HEX | ..."), or "".
std::string spirvOf(const std::string& build) {
  const std::string key = " | spirv ";
  const auto at = build.find(key);
  if (at == std::string::npos) return "";
  const auto start = at + key.size();
  return build.substr(start, build.find(" | ", start) - start);
}

bool isSha256Hex(const std::string& s) {
  return s.size() == 64 && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

}  // namespace

RunFolderSource::RunFolderSource(fs::path folder) : folder_(std::move(folder)) {
  std::error_code ec;
  if (!fs::is_directory(folder_.root(), ec))
    throw UsageError(
        "--from " + folder_.root().string() +
        ": not a folder; pass the --out folder of a run (holding results.json and its frames)");
  results_ = folder_.readResults("pass the --out folder of a `taa-harness run`");
  if (results_.environment.device.empty() ||
      results_.environment.fingerprint() != results_.fingerprint)
    throw UsageError(
        folder_.resultsFile().string() +
        ": its environment is missing or disagrees with its fingerprint; bless --from needs the "
        "results.json of a run of this version (run the cases there again)");
}

BlessSource RunFolderSource::source(const cases::LoadedCase& loaded) const {
  const std::string& name = loaded.spec.name;
  const std::string where = folder_.resultsFile().string() + ": case " + name;
  const auto it = std::find_if(results_.cases.begin(), results_.cases.end(),
                               [&](const run::CaseResult& c) { return c.name == name; });
  if (it == results_.cases.end())
    throw UsageError(folder_.resultsFile().string() + " holds no case " + name +
                     "; run it there (taa-harness run " + loaded.spec.file.string() + " --out " +
                     folder_.root().string() + ") or leave it out");
  const run::CaseResult& r = *it;
  if (r.caseSha256 != loaded.sha256)
    throw UsageError(where + " was rendered from other case, scene, track or shader bytes than " +
                     loaded.spec.file.string() + " has here (case_sha256 " +
                     r.caseSha256.substr(0, 12) + " != " + loaded.sha256.substr(0, 12) +
                     "); run it again from this tree");
  if (spirvOf(results_.build) != run::spirvIdentity())
    throw UsageError(
        folder_.resultsFile().string() +
        ": rendered with other built-in shaders (SPIR-V) than this build's; run it again with "
        "this tree's build");
  if (r.status == run::CaseStatus::Error)
    throw UsageError(where + " did not render (" + r.message + "); fix it and run it again");
  const auto& sha = r.frameSha256;
  const auto& sig = r.frameSignatures;
  if (sha.empty() || sig.size() != sha.size())
    throw UsageError(where + " lists " + std::to_string(sha.size()) + " frame hashes and " +
                     std::to_string(sig.size()) +
                     " signatures; bless --from needs both for every frame "
                     "(a run with --verdict-from copies no frames: run without it)");
  for (size_t f = 0; f < sha.size(); ++f)
    if (!isSha256Hex(sha[f]) || !golden::signatureDistance(sig[f], sig[f]).valid)
      throw UsageError(where + ": frame " + std::to_string(f) +
                       "'s hash or signature is malformed");
  BlessSource s;
  s.environment = results_.environment;
  s.commit = results_.commit;
  s.digests = {sha, sig};
  s.result = r;
  for (const int f : loaded.spec.output.frames) {
    if (size_t(f) >= sha.size())
      throw UsageError(where + " rendered " + std::to_string(sha.size()) +
                       " frames, not checked frame " + std::to_string(f));
    const fs::path rel = run::RunFolder::caseFile(name, f, run::FrameFile::Exr);
    const fs::path file = folder_.root() / rel;
    Image image;
    try {
      image = exr::decode(folder_.readFile(rel, "frame " + std::to_string(f) + " of " + name,
                                           "the run's frames are needed as it wrote them"),
                          kMaxImageSamples);
    } catch (const exr::ExrError& e) {
      throw UsageError(file.string() + ": " + e.what() +
                       "; the run's frames are needed as it wrote them");
    }
    if (pixelSha256(image) != sha[size_t(f)])
      throw UsageError(file.string() + " does not hash to what " + where +
                       " claims for frame " + std::to_string(f) +
                       "; the folder was altered: run it again");
    // The run signed the frame before its EXR rounded it to half floats: a cell may move by a
    // rounding step, never past the bounds two signatures are compared within.
    const auto d = golden::signatureDistance(golden::frameSignature(image), sig[size_t(f)]);
    if (d.cell > golden::kSignatureCellTolerance || d.mean > golden::kSignatureMeanTolerance)
      throw UsageError(file.string() + "'s signature is not what " + where +
                       " claims for frame " + std::to_string(f) +
                       "; the folder was altered: run it again");
    s.stored.emplace(f, std::move(image));
  }
  return s;
}

}  // namespace taa::cli
