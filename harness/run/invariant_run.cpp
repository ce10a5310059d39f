#include "run/invariant_run.h"

namespace taa::run {

InvariantRun::InvariantRun(const spec::CheckedCase& spec) : fromFrame_(spec.checks.from_frame) {
  for (const auto& name : spec.checks.invariants) {
    const auto& info = invariants::invariantInfo(name);
    needs_ |= info.needs;
    warmUp_ |= info.frames == invariants::Frames::All && fromFrame_ > 0;
    active_.push_back({&info, info.make(spec)});
  }
}

bool InvariantRun::readsImages(int frame) const {
  return !active_.empty() && frame >= fromFrame_;
}

bool InvariantRun::judges(const Active& a, int frame) const {
  return frame >= fromFrame_ || a.info->frames == invariants::Frames::All;
}

void InvariantRun::observe(const invariants::FrameView& frame) {
  for (auto& a : active_)
    if (judges(a, frame.frame)) a.invariant->observe(frame);
}

void InvariantRun::observeRepeat(const invariants::FrameView& frame) {
  for (auto& a : active_)
    if (judges(a, frame.frame)) a.invariant->observeRepeat(frame);
}

std::vector<invariants::Outcome> InvariantRun::finish() {
  std::vector<invariants::Outcome> out;
  for (auto& a : active_) {
    auto o = a.invariant->finish();
    o.name = a.info->name;
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace taa::run
