#include "run/add_environment.h"

#include "compare/tolerance.h"
#include "golden/signature.h"

namespace taa::run {

namespace {

AddEnvironmentOutcome refused(std::string why) {
  AddEnvironmentOutcome out;
  out.detail = std::move(why);
  return out;
}

// The first stored frame outside the case's tolerances of the primary's EXR, as a sentence.
std::string storedFrameProblem(const spec::CheckedCase& spec, const golden::GoldenSet& set,
                               const std::map<int, Image>& stored) {
  for (const auto& gf : set.manifest.frames) {
    const auto it = stored.find(gf.frame);
    if (it == stored.end())
      return "frame " + std::to_string(gf.frame) + " (a stored golden) was not rendered";
    const Image& golden = set.load(gf);
    if (!golden.sameShape(it->second))
      return "frame " + std::to_string(gf.frame) + " has another size";
    const auto measured =
        compare::measureAgainstGolden(golden, it->second, spec.checks.tolerance.pixel_threshold);
    const auto violations = compare::toleranceViolations(measured.metrics, spec.checks.tolerance);
    if (!violations.empty()) {
      std::string why = "frame " + std::to_string(gf.frame) +
                        " is outside the case's tolerances of the primary positive:";
      for (const auto& v : violations) why += " " + v;
      return why;
    }
  }
  return "";
}

std::string signatureProblem(const golden::Positive& primary, const golden::Positive& candidate) {
  for (size_t f = 0; f < primary.signatures.size(); ++f) {
    const auto d = golden::signatureDistance(primary.signatures[f], candidate.signatures[f]);
    if (!d.valid) return "frame " + std::to_string(f) + "'s signature is malformed";
    if (d.cell > golden::kSignatureCellTolerance || d.mean > golden::kSignatureMeanTolerance)
      return "frame " + std::to_string(f) +
             "'s signature is outside the signature bounds of the primary's (cell " +
             std::to_string(d.cell) + "/255, channel mean " + std::to_string(d.mean) + ")";
  }
  return "";
}

}  // namespace

AddEnvironmentOutcome addEnvironment(const spec::CheckedCase& spec, const golden::GoldenSet& set,
                                     const std::string& caseSha,
                                     const PositiveCandidate& candidate) {
  const auto& m = set.manifest;
  const auto& p = candidate.positive;
  const std::string fingerprint = p.environment.fingerprint();
  if (m.caseSha256 != caseSha)
    return refused(
        "the case (or a file it references) changed since its goldens were blessed (" +
        m.bless.date +
        "): that is an image change; bless it with a reason first, then add environments");
  if (const auto own = m.positiveFor(fingerprint)) {
    if (own->sequence == p.sequence) {
      AddEnvironmentOutcome out;
      out.kind = AddEnvironmentOutcome::Kind::AlreadyThere;
      out.detail = "the goldens already hold this positive for " + fingerprint;
      return out;
    }
    return refused("the goldens hold another positive for " + fingerprint +
                   ": its frames changed, which is an image change; bless it with a reason");
  }
  if (m.sequence.empty() || m.signatures.size() != m.sequence.size())
    return refused(
        "its manifest predates per-frame hashes and signatures; bless it again with a reason "
        "first");
  if (p.sequence.size() != m.sequence.size() || p.signatures.size() != p.sequence.size())
    return refused("this run rendered " + std::to_string(p.sequence.size()) + " frames (" +
                   std::to_string(p.signatures.size()) + " signatures), the goldens hold " +
                   std::to_string(m.sequence.size()));
  const auto primary = m.positives().front();
  if (const auto why = storedFrameProblem(spec, set, *candidate.stored); !why.empty())
    return refused(why);
  if (const auto why = signatureProblem(primary, p); !why.empty()) return refused(why);
  AddEnvironmentOutcome out;
  out.kind = AddEnvironmentOutcome::Kind::Added;
  out.manifest = m;
  out.manifest.others.push_back(p);
  out.detail = p.sequence == m.sequence
                   ? "its frames hash as the primary's (" + m.environment.fingerprint() +
                         "): stored as the same frames"
                   : "its own frame hashes, within tolerance of the primary's";
  return out;
}

}  // namespace taa::run
