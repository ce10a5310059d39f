// `bless --add-environment`: a golden set gains the positive of one more environment (another
// CPU level, driver or GPU) without a new image. Only frames that are the blessed images as
// that environment renders them may become its positive; anything else is an image change,
// which a plain bless with a reason makes.
#pragma once

#include <map>
#include <string>

#include "core/image.h"
#include "golden/golden_store.h"
#include "golden/manifest.h"
#include "spec/checked_case.h"

namespace taa::run {

struct PositiveCandidate {
  golden::Positive positive;  // its environment, bless record, hashes and signatures
  const std::map<int, Image>* stored = nullptr;  // the case's checked frames, as rendered there
};

struct AddEnvironmentOutcome {
  enum class Kind { Added, AlreadyThere, Refused } kind = Kind::Refused;
  std::string detail;         // why it was refused, or what was added
  golden::Manifest manifest;  // the set's manifest with the positive (Added)
};

// Checks `candidate` against `set` (the case's goldens, verified) and returns the manifest with
// it added. Refused when the case's inputs changed since the set's bless (`caseSha`), when the
// environment already has another positive, when its frame count differs, or when a stored
// frame lies outside the case's tolerances of the primary's EXR or any frame's signature outside
// the signature bounds of the primary's. AlreadyThere when the same hashes are blessed for it.
AddEnvironmentOutcome addEnvironment(const spec::CheckedCase& spec, const golden::GoldenSet& set,
                                     const std::string& caseSha,
                                     const PositiveCandidate& candidate);

}  // namespace taa::run
