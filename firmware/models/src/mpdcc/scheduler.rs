//! The central scheduler's control flow, Algorithm 1 of paper 001 (Sec. V-D),
//! over `n` explorer units, for the switching horizon "SE".
//!
//! ```text
//! 1  if |y*(k+1) - y(k+1)| <= y_bnd with s(k) = s(k-1): keep s(k-1)
//! 4  else: common terms (Sec. V-A), candidate set S(s(k-1)),
//! 6-7     each candidate to the next free explorer (J and J_dl),
//! 9-13    argmin J over L* > 0, else argmin J_dl (deadlock, eqs. 15-16)
//! ```
//!
//! Interpretations (written down because the paper leaves them open):
//! - **Dispatch order and ties**: candidates are issued in the order of
//!   [`controller::candidates`] (ascending code). Results may come back in any
//!   order from `n` explorers; the scheduler compares `(J, index)`
//!   lexicographically, so the first candidate in enumeration order wins a
//!   tie whatever `n` is. The decision therefore does not depend on `n`; only
//!   the cycle count does ([`super::cycles`]).
//! - **`J_dl` always computed**: the paper lets the scheduler tell explorers
//!   to skip `J_dl` once a feasible candidate is known. In our explorer `J_dl`
//!   comes out of the search lanes' first cycle at no extra cost, so the skip
//!   saves nothing; the decision is the same either way.
//! - **`s(k-1)` is a candidate** (as in the reference): after a failed lazy
//!   check it normally has `L* = 0`, but it can win a deadlock.

use super::controller::{self, Decision, DecisionKind, MAX_CANDIDATES};
use super::cycles;

/// What one explorer returns for one candidate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ExplorerResult {
    /// The candidate `s`.
    pub s: [u8; 3],
    /// `L* = min_j l_j`, steps (0: infeasible at `k+1`).
    pub l_star: u32,
    /// `f_s(s(k-1), s)`, device turn-ons.
    pub fs: u32,
    /// `J`, UQ15.17 transitions/step; `u32::MAX` = `+inf`.
    pub cost: u32,
    /// `J_dl` of eq. (15), Q2.13 pu (may be negative).
    pub j_dl: i32,
    /// Clock cycles of the slowest search lane (Algorithm 2).
    pub lane_cycles: u32,
    /// `Delta_j` over `L` steps, Q2.13 (for tests and traces).
    pub deltas: [i16; 7],
}

/// An explorer unit: evaluates one candidate (same result on every unit).
pub trait Explorer {
    /// `J`, `J_dl`, `L*` of candidate `s`.
    fn evaluate(&mut self, s: [u8; 3]) -> ExplorerResult;
}

/// Everything the scheduler produced for one time step.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The decision in the shared controller vocabulary.
    pub decision: Decision,
    /// Per-candidate results, in enumeration order (empty when kept).
    pub results: heapless::Vec<ExplorerResult, MAX_CANDIDATES>,
    /// Clock cycles of this decision (structural model, [`cycles`]).
    pub cycles: u32,
}

/// Index of the winner: min `J` among `L* > 0`, else min `J_dl`; first wins ties.
pub fn select(results: &[ExplorerResult]) -> Option<(usize, DecisionKind)> {
    let mut best: Option<usize> = None;
    for (i, r) in results.iter().enumerate() {
        if r.l_star == 0 {
            continue;
        }
        if best.is_none_or(|b| r.cost < results[b].cost) {
            best = Some(i);
        }
    }
    if let Some(b) = best {
        return Some((b, DecisionKind::Optimal));
    }
    let mut best: Option<usize> = None;
    for (i, r) in results.iter().enumerate() {
        if best.is_none_or(|b| r.j_dl < results[b].j_dl) {
            best = Some(i);
        }
    }
    best.map(|b| (b, DecisionKind::Deadlock))
}

/// Algorithm 1 for one step: `lazy` is the outcome of line 1 (computed by the
/// datapath), `n` the number of explorers, `model` the cycle model.
pub fn run<E: Explorer>(
    s_prev: [u8; 3],
    lazy: bool,
    n: u32,
    model: &cycles::CycleModel,
    explorer: &mut E,
) -> Outcome {
    if lazy {
        return Outcome {
            decision: Decision {
                s: s_prev,
                kind: DecisionKind::Kept,
                horizon_steps: 0,
                candidates: 0,
            },
            results: heapless::Vec::new(),
            cycles: model.kept_cycles(),
        };
    }
    let cands = controller::candidates(s_prev);
    let mut results: heapless::Vec<ExplorerResult, MAX_CANDIDATES> = heapless::Vec::new();
    let mut lanes: heapless::Vec<u32, MAX_CANDIDATES> = heapless::Vec::new();
    for &s in cands.iter() {
        let r = explorer.evaluate(s);
        // Capacities equal MAX_CANDIDATES, the size of any candidate set.
        let _ = lanes.push(r.lane_cycles);
        let _ = results.push(r);
    }
    let cycles = model.search_cycles(n, &lanes);
    let decision = match select(&results) {
        Some((i, kind)) => Decision {
            s: results[i].s,
            kind,
            horizon_steps: if kind == DecisionKind::Optimal {
                results[i].l_star
            } else {
                0
            },
            candidates: results.len() as u32,
        },
        // Unreachable: s(k-1) itself is always a candidate.
        None => Decision {
            s: s_prev,
            kind: DecisionKind::Deadlock,
            horizon_steps: 0,
            candidates: 0,
        },
    };
    Outcome {
        decision,
        results,
        cycles,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(s: u8, l_star: u32, cost: u32, j_dl: i32) -> ExplorerResult {
        ExplorerResult {
            s: [s, 0, 0],
            l_star,
            fs: 1,
            cost,
            j_dl,
            lane_cycles: 8,
            deltas: [0; 7],
        }
    }

    #[test]
    fn select_min_cost_first_on_ties() {
        let v = [
            r(0, 0, u32::MAX, -5),
            r(1, 10, 300, 0),
            r(2, 12, 200, 0),
            r(3, 20, 200, 0),
        ];
        assert_eq!(select(&v), Some((2, DecisionKind::Optimal)));
    }

    /// Constructed deadlock (eqs. 15-16): no candidate has L* > 0, the one
    /// with the smallest worst excess at k+1 wins, first on ties.
    #[test]
    fn deadlock_picks_min_excess() {
        let v = [
            r(0, 0, u32::MAX, 40),
            r(1, 0, u32::MAX, 7),
            r(2, 0, u32::MAX, 12),
            r(3, 0, u32::MAX, 7),
        ];
        assert_eq!(select(&v), Some((1, DecisionKind::Deadlock)));
        assert_eq!(select(&[]), None);
    }

    struct Fixed(heapless::Vec<ExplorerResult, 8>);
    impl Explorer for Fixed {
        fn evaluate(&mut self, s: [u8; 3]) -> ExplorerResult {
            // L* = 5 only for s = [1, 1, 1], cost by code otherwise infeasible.
            let feasible = s == [1, 1, 1];
            let out = ExplorerResult {
                s,
                l_star: if feasible { 5 } else { 0 },
                fs: 3,
                cost: if feasible { 1000 } else { u32::MAX },
                j_dl: 0,
                lane_cycles: 8,
                deltas: [0; 7],
            };
            let _ = self.0.push(out);
            out
        }
    }

    #[test]
    fn run_kept_and_search_paths() {
        let mut e = Fixed(heapless::Vec::new());
        let m = cycles::CycleModel::paper();
        let kept = run([0, 0, 0], true, 2, &m, &mut e);
        assert_eq!(kept.decision.kind, DecisionKind::Kept);
        assert_eq!(kept.decision.s, [0, 0, 0]);
        assert!(e.0.is_empty());
        let out = run([0, 0, 0], false, 2, &m, &mut e);
        // From [0,0,0]: 3 positions per phase (0, 1, 2) -> 27 candidates.
        assert_eq!(out.results.len(), 27);
        assert_eq!(out.decision.s, [1, 1, 1]);
        assert_eq!(out.decision.kind, DecisionKind::Optimal);
        assert_eq!(out.decision.horizon_steps, 5);
        // More explorers never take more cycles.
        let c1 = run([0, 0, 0], false, 1, &m, &mut e).cycles;
        let c4 = run([0, 0, 0], false, 4, &m, &mut e).cycles;
        assert!(c4 < c1 && out.cycles < c1 && c4 < out.cycles);
    }
}
