#include "invariants/invariant.h"
#include "invariants/invariant_support.h"

namespace taa::invariants {

using spec::InvariantKind;

Needs needsOf(InvariantKind kind) {
  Needs n;
  switch (kind) {
    case InvariantKind::HistoryBounded:
      n.current = true;
      break;
    case InvariantKind::NoGhosting:
      n.reference = n.ids = true;
      break;
    case InvariantKind::Converges:
      n.reference = true;
      break;
    case InvariantKind::TemporalStability:
      n.reference = n.ids = n.velocity = true;
      break;
    case InvariantKind::Finite:
      break;
    case InvariantKind::Energy:
      n.reference = true;
      break;
    case InvariantKind::Determinism:
      n.secondRun = true;
      break;
    case InvariantKind::BitStable:
      break;
    case InvariantKind::MatchesInput:
      n.current = true;
      break;
    case InvariantKind::AdaptiveUnmarked:
      n.adaptive = true;
      break;
    case InvariantKind::TscmaaNonEdge:
      n.current = n.tscmaa = true;
      break;
  }
  return n;
}

std::string inapplicable(InvariantKind kind, const spec::CaseSpec& spec) {
  switch (kind) {
    case InvariantKind::HistoryBounded:
      return historyBoundedInapplicable(spec);
    case InvariantKind::NoGhosting:
      return noGhostingInapplicable(spec);
    case InvariantKind::Converges:
      return convergesInapplicable(spec);
    case InvariantKind::TemporalStability:
      return temporalStabilityInapplicable(spec);
    case InvariantKind::Energy:
      return energyInapplicable(spec);
    case InvariantKind::BitStable:
      return bitStableInapplicable(spec);
    case InvariantKind::MatchesInput:
      return matchesInputInapplicable(spec);
    case InvariantKind::AdaptiveUnmarked:
      return adaptiveUnmarkedInapplicable(spec);
    case InvariantKind::TscmaaNonEdge:
      return tscmaaNonEdgeInapplicable(spec);
    case InvariantKind::Finite:       // meaningful for any output
    case InvariantKind::Determinism:  // likewise
      return "";
  }
  return "";
}

std::unique_ptr<Invariant> makeInvariant(InvariantKind kind, const spec::CaseSpec& spec) {
  switch (kind) {
    case InvariantKind::HistoryBounded:
      return makeHistoryBounded(spec);
    case InvariantKind::NoGhosting:
      return makeNoGhosting(spec);
    case InvariantKind::Converges:
      return makeConverges(spec);
    case InvariantKind::TemporalStability:
      return makeTemporalStability(spec);
    case InvariantKind::Finite:
      return makeFinite(spec);
    case InvariantKind::Energy:
      return makeEnergy(spec);
    case InvariantKind::Determinism:
      return makeDeterminism(spec);
    case InvariantKind::BitStable:
      return makeBitStable(spec);
    case InvariantKind::MatchesInput:
      return makeMatchesInput(spec);
    case InvariantKind::AdaptiveUnmarked:
      return makeAdaptiveUnmarked(spec);
    case InvariantKind::TscmaaNonEdge:
      return makeTscmaaNonEdge(spec);
  }
  return nullptr;
}

}  // namespace taa::invariants
