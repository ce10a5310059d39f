// The invariants of one case as the runner drives them: built from checks.invariants through
// the invariant table, told what to read back, and fed the frames each should judge. The
// frame rules (checks.from_frame, a row's Frames::All) live here and nowhere else; tests feed
// synthetic frames through this same class.
#pragma once

#include <memory>
#include <vector>

#include "invariants/invariant.h"
#include "invariants/registry.h"
#include "spec/checked_case.h"

namespace taa::run {

class InvariantRun {
 public:
  // Throws std::invalid_argument for a name the table lacks (validation rejects those first).
  explicit InvariantRun(const spec::CheckedCase& spec);

  bool empty() const { return active_.empty(); }
  // Union of the listed invariants' needs.
  const invariants::Needs& needs() const { return needs_; }
  // Whether frame `frame`'s images must be read back (with the reference and captures):
  // every frame from checks.from_frame on while an invariant is listed.
  bool readsImages(int frame) const;
  // Whether some invariant judges frames before checks.from_frame; they get the output
  // only (its hash and colour, read back for every frame).
  bool judgesWarmUp() const { return warmUp_; }

  // A frame of the (first or repeat) render; handed to the invariants that judge it.
  void observe(const invariants::FrameView& frame);
  void observeRepeat(const invariants::FrameView& frame);
  // One outcome per listed invariant, in the listed order, named after its table row.
  std::vector<invariants::Outcome> finish();

 private:
  struct Active {
    const invariants::InvariantInfo* info;
    std::unique_ptr<invariants::Invariant> invariant;
  };
  bool judges(const Active& a, int frame) const;

  std::vector<Active> active_;
  invariants::Needs needs_;
  int fromFrame_ = 0;
  bool warmUp_ = false;
};

}  // namespace taa::run
