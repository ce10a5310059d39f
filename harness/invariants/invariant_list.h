// The table of invariants: one row each, in the order `techniques --json` and error messages
// list them. TAA_INVARIANT(id) names the InvariantInfo `id_invariant` that
// harness/invariants/<id>.cpp defines; that row carries the name, needs, frames and factory.
// Adding an invariant is adding its file and one line here. No include guard: the includer
// defines TAA_INVARIANT.
TAA_INVARIANT(history_bounded)
TAA_INVARIANT(no_ghosting)
TAA_INVARIANT(converges)
TAA_INVARIANT(temporal_stability)
TAA_INVARIANT(finite)
TAA_INVARIANT(energy)
TAA_INVARIANT(determinism)
TAA_INVARIANT(bit_stable)
TAA_INVARIANT(matches_input)
TAA_INVARIANT(adaptive_unmarked)
TAA_INVARIANT(tscmaa_non_edge)
