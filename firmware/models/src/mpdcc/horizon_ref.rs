//! Longer switching horizons for MPDCC: the sequence search shared by the
//! `f64` reference ([`HorizonRef`], here) and the 16-bit FPGA model
//! (`super::horizon_fixed`).
//!
//! Paper 001 implements the switching horizon "SE" (switch, then extend)
//! and names longer horizons as the architecture's extension. The
//! vocabulary is T. Geyer's ("Model predictive direct current control",
//! IEEE Ind. Appl. Mag. 18(2), 2012, paper 001's ref. [12]; "Generalized
//! model predictive direct torque control: long prediction horizons and
//! minimization of switching losses", IEEE CDC 2009, ref. [11]): `S` = a
//! switching event (any admissible position), `E` = an extension step
//! (hold the position until the first step at which an output would leave
//! its bound, found by extrapolation/interpolation exactly as for "SE").
//!
//! # Horizons ([`Horizon`])
//! - **SE**: the paper's. Identical decisions to [`super::mpdcc_ref`] and
//!   to `mpdcc_fixed::decide` (tested).
//! - **SSE**: switch at `k` to `s1` (held one step, must keep every output
//!   inside at `k+1`), switch at `k+1` to `s2` (admissible from `s1`, `s2 =
//!   s1` allowed), then extend. Length `1 + L*(s2)`.
//! - **SESE**: switch to `s1` at `k`, extend it for `l1 = L*(s1)` steps
//!   (the last step inside), switch at `k + l1` to `s2` (admissible from
//!   `s1`), extend `l2 = L*(s2)` steps from the predicted state at `k + l1`.
//!   Length `l1 + l2`. If `l1 = N_bar` (no bound reached within the cap)
//!   the sequence ends there (length `N_bar`).
//! - **SESESE**: SESE with a third switching event at the end of the second
//!   extension. Below the first event at most `beam` (default 1) children
//!   of a node are expanded, so the budget splits between first events and
//!   their best continuation.
//!
//! "eSESE" (a leading optional extension of `s(k-1)`) is not a separate
//! horizon here: with paper 001's lazy evaluation (Algorithm 1, line 1) the
//! search only runs when `s(k-1)` leaves a bound at `k+1`, so the leading
//! extension always has length zero and eSESE decides as SESE.
//!
//! Each extension segment is capped at `N_bar` (`horizon_max_steps`), so a
//! sequence predicts at most `segments x N_bar` steps.
//!
//! # Cost and decision
//! A complete sequence with `f_s` device turn-ons in total (all switching
//! events) and length `l` costs `J = f_s / l + lambda_n v_n(k+l)^2` (eqs.
//! 10-12 with the sequence's own length and terminal neutral point). For SE
//! this is exactly the paper's cost. The decision applies the first
//! element `s1` of the cheapest sequence; ties go to the smaller sequence in
//! lexicographic order of the position codes (`64 s_a + 8 s_b + s_c`, a
//! shorter sequence padded with code 0), which for SE is the paper's "first
//! in enumeration order".
//!
//! # Deadlock handling
//! 1. A complete feasible sequence exists: the cheapest one decides.
//! 2. None does (every continuation of every `s1` leaves a bound, or the
//!    expansion budget ran out first) but some `s1` keeps all outputs inside
//!    at `k+1` (`L*(s1) > 0`): the SE decision among those (**fallback to
//!    SE**, counted in [`Search::fallback`]). So a longer horizon never
//!    picks a position that leaves a bound at `k+1` when one exists.
//! 3. No `s1` is feasible: eqs. (15)-(16) on the first step, as for SE.
//!
//! # Pruning (branch and bound) and the bound on the work
//! Every first event is evaluated (the SE search; its `L*`, cost and
//! `J_dl` are needed for the fallback and the deadlock anyway). The
//! continuations are searched by branch and bound on the switching effort
//! so far:
//! - **Lower bound** of every completion of a partial sequence with `f_s`
//!   turn-ons so far, length `l` so far and `r` extension segments still to
//!   come: `LB = f_s / (l + r N_bar)` (later events add turn-ons `>= 0`,
//!   each extension adds at most `N_bar` steps, the terminal term is `>= 0`).
//!   It is known before the candidate is extended, from its transition
//!   count alone.
//! - **Node order**: the expandable first events are visited in ascending
//!   `(J_SE, code)`, `J_SE` = the first event's own SE cost (what the
//!   explorers return anyway): the most promising first segments first. A
//!   node with `LB > J_best` is skipped; inside a node, a candidate with
//!   `LB > J_best` is skipped before it is extended (not issued to an
//!   explorer). Pruning only on strict `>` keeps every sequence that could
//!   tie, so with an unlimited budget the decision equals brute-force
//!   enumeration (tested).
//! - **Budget**: at most `max_expansions` nodes beyond the first event are
//!   expanded. This bounds the candidate evaluations to `|S| (1 +
//!   max_expansions)` per decision (`|S| <= 216`) and the core's cycles
//!   ([`super::horizon_fixed`]); when it binds ([`Search::budget_hit`]) the
//!   decision is the best sequence found so far.
//!
//! In hardware the order needs no sort: the scheduler keeps the
//! `max_expansions` smallest `(J_SE, code)` entries in a sorted register
//! list while the first-event results stream in.
#![allow(clippy::needless_range_loop)]

use super::anpc;
use super::controller::{candidates, Controller, CtrlState, Decision, DecisionKind, StateError};
use super::mpdcc_ref::MpdccRef;
use super::params::{DriveParams, ParamError};

/// Longest sequence (switching events) supported.
pub const MAX_EVENTS: usize = 3;

/// Default budget of expanded nodes beyond the first switching event.
pub const DEFAULT_MAX_EXPANSIONS: u32 = 8;

/// A switching horizon (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Horizon {
    /// Switch, extend (paper 001).
    Se,
    /// Switch, switch one step later, extend.
    Sse,
    /// Switch, extend, switch, extend.
    Sese,
    /// Three switching events, each extended.
    Sesese,
}

/// How long the position of a switching event is held.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hold {
    /// One step (the event is followed by another `S`).
    OneStep,
    /// Until the first step outside a bound (`E`), at most `N_bar`.
    Extend,
}

impl Horizon {
    /// All implemented horizons, shortest first.
    pub const ALL: [Horizon; 4] = [Horizon::Se, Horizon::Sse, Horizon::Sese, Horizon::Sesese];

    /// The horizon's name in Geyer's notation.
    pub fn name(self) -> &'static str {
        match self {
            Horizon::Se => "SE",
            Horizon::Sse => "SSE",
            Horizon::Sese => "SESE",
            Horizon::Sesese => "SESESE",
        }
    }

    /// Parses "SE", "SSE", "SESE", "SESESE" (any case) and "eSESE" (=
    /// SESE under lazy evaluation, see the module documentation).
    pub fn parse(s: &str) -> Option<Horizon> {
        let t = s.trim();
        if t == "eSESE" {
            return Some(Horizon::Sese);
        }
        Horizon::ALL
            .into_iter()
            .find(|h| h.name().eq_ignore_ascii_case(t))
    }

    /// The hold of each switching event, in order.
    pub fn events(self) -> &'static [Hold] {
        match self {
            Horizon::Se => &[Hold::Extend],
            Horizon::Sse => &[Hold::OneStep, Hold::Extend],
            Horizon::Sese => &[Hold::Extend, Hold::Extend],
            Horizon::Sesese => &[Hold::Extend, Hold::Extend, Hold::Extend],
        }
    }
}

/// One candidate's extension from a node, as a [`SequenceModel`] computes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ext<D, T> {
    /// `L*`, steps (0: leaves a bound at the first step), `<= N_bar`.
    pub l: u32,
    /// The deadlock key `J_dl` of eq. (15) at the first step (smaller is better).
    pub dl: D,
    /// What the cost needs from the end of the extension (`v_n(k+L*)`).
    pub end: T,
}

/// The prediction model behind the search: the reference or the FPGA model.
pub trait SequenceModel {
    /// A predicted state at a switching instant (holds the position in force).
    type Node;
    /// A cost (`f64` pu or the FPGA's UQ15.17).
    type Cost: Copy + PartialOrd;
    /// The deadlock key.
    type Dl: Copy + PartialOrd;
    /// The terminal value the cost needs.
    type End: Copy;
    /// `N_bar`, steps.
    fn n_bar(&self) -> u32;
    /// The position in force at the node.
    fn held(&self, node: &Self::Node) -> [u8; 3];
    /// Extends `s` from `node` (`L*`, capped at `N_bar`, and `J_dl`).
    fn extend(&mut self, node: &Self::Node, s: [u8; 3]) -> Ext<Self::Dl, Self::End>;
    /// `J` of a sequence with `fs` turn-ons in total and length `len >= 1`
    /// whose last extension ended with `end`.
    fn cost(&self, end: Self::End, fs: u32, len: u32) -> Self::Cost;
    /// A lower bound of the cost of any sequence with at least `fs`
    /// turn-ons and length at most `len_max`.
    fn lower_bound(&self, fs: u32, len_max: u32) -> Self::Cost;
    /// The node `l` steps after `node` with `s` held.
    fn advance(&mut self, node: &Self::Node, s: [u8; 3], l: u32) -> Self::Node;
}

/// Options of the search.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SearchOptions {
    /// Nodes expanded beyond the first event at most (all levels).
    pub max_expansions: u32,
    /// Children expanded per node below the first event at most (SESESE).
    pub beam: u32,
    /// Branch and bound on (off: every sequence is evaluated; tests).
    pub prune: bool,
}

impl Default for SearchOptions {
    fn default() -> Self {
        Self {
            max_expansions: DEFAULT_MAX_EXPANSIONS,
            beam: 1,
            prune: true,
        }
    }
}

/// The first events' results and the expanded nodes' issue counts.
pub const MAX_PASSES: usize = 1 + 512;

/// Result of one search.
#[derive(Debug, Clone, PartialEq)]
pub struct Search {
    /// The decision (`horizon_steps`: length of the chosen sequence;
    /// `candidates`: extensions evaluated in all).
    pub decision: Decision,
    /// Extensions evaluated per explorer pass: the first event, then one
    /// entry per expanded node (`MAX_PASSES` at most; the budget is capped).
    pub passes: heapless::Vec<u32, MAX_PASSES>,
    /// The expansion budget stopped the search.
    pub budget_hit: bool,
    /// No complete sequence: the SE decision was taken (deadlock rule 2).
    pub fallback: bool,
    /// The applied position differs from the SE decision on the same state.
    pub differs_from_se: bool,
}

/// Observer of the complete feasible sequences a search evaluates: the
/// positions, the length (steps) and the cost.
pub type Visit<'a, C> = dyn FnMut(&[[u8; 3]], u32, C) + 'a;

/// A sequence's position codes (padded with 0) for the tie-break.
type Path = [u16; MAX_EVENTS];

fn code(s: [u8; 3]) -> u16 {
    64 * s[0] as u16 + 8 * s[1] as u16 + s[2] as u16
}

struct Best<C> {
    cost: C,
    path: Path,
    s1: [u8; 3],
    len: u32,
}

fn offer<C: PartialOrd + Copy>(
    best: &mut Option<Best<C>>,
    cost: C,
    path: Path,
    s1: [u8; 3],
    len: u32,
) {
    let better = match best {
        None => true,
        Some(b) => cost < b.cost || (cost == b.cost && path < b.path),
    };
    if better {
        *best = Some(Best {
            cost,
            path,
            s1,
            len,
        });
    }
}

/// Expandable children of a node: (partial cost `J` so far, code,
/// position, length so far, turn-ons so far, `LB`).
type OpenList<C> = heapless::Vec<(C, u16, [u8; 3], u32, u32, C), 216>;

/// The search's running state.
struct State<C> {
    best: Option<Best<C>>,
    passes: heapless::Vec<u32, MAX_PASSES>,
    evaluations: u32,
    expanded: u32,
    budget_hit: bool,
}

fn path_codes(path: &[[u8; 3]; MAX_EVENTS], depth: usize) -> Path {
    core::array::from_fn(|i| if i <= depth { code(path[i]) } else { 0 })
}

/// Expands the children in `open` (events at index `depth`) of `node`, in
/// ascending `(J so far, code)`, at most `cap` of them and `budget` nodes
/// in all, skipping those with `LB > J_best`.
#[allow(clippy::too_many_arguments)]
fn expand_open<M: SequenceModel>(
    m: &mut M,
    st: &mut State<M::Cost>,
    opt: &SearchOptions,
    budget: u32,
    events: &[Hold],
    node: &M::Node,
    path: &mut [[u8; 3]; MAX_EVENTS],
    depth: usize,
    mut open: OpenList<M::Cost>,
    len_parent: u32,
    cap: u32,
    visit: &mut Visit<'_, M::Cost>,
) {
    open.sort_unstable_by(|a, b| {
        a.0.partial_cmp(&b.0)
            .unwrap_or(core::cmp::Ordering::Equal)
            .then(a.1.cmp(&b.1))
    });
    let mut n = 0u32;
    for &(_, _, s, len, fs, lb) in open.iter() {
        if opt.prune && st.best.as_ref().is_some_and(|b| lb > b.cost) {
            continue;
        }
        if opt.prune && (st.expanded >= budget || n >= cap) {
            st.budget_hit = true;
            break;
        }
        st.expanded += 1;
        n += 1;
        path[depth] = s;
        let child = m.advance(node, s, len - len_parent);
        children(
            m,
            st,
            opt,
            budget,
            events,
            &child,
            path,
            depth + 1,
            fs,
            len,
            visit,
        );
    }
}

/// Evaluates the switching event `depth >= 1` at `node` (every candidate
/// whose `LB` does not exceed `J_best`), records complete sequences and
/// expands the rest (at most `opt.beam` of them).
#[allow(clippy::too_many_arguments)]
fn children<M: SequenceModel>(
    m: &mut M,
    st: &mut State<M::Cost>,
    opt: &SearchOptions,
    budget: u32,
    events: &[Hold],
    node: &M::Node,
    path: &mut [[u8; 3]; MAX_EVENTS],
    depth: usize,
    fs_so_far: u32,
    len_so_far: u32,
    visit: &mut Visit<'_, M::Cost>,
) {
    let n_bar = m.n_bar();
    let held = path[depth - 1];
    let rem_after = events[depth + 1..]
        .iter()
        .filter(|h| **h == Hold::Extend)
        .count() as u32;
    let last = depth + 1 == events.len();
    let mut open: OpenList<M::Cost> = heapless::Vec::new();
    let mut issued = 0u32;
    for &s in candidates(held).iter() {
        let fs = fs_so_far + anpc::switch_transitions(held, s);
        if opt.prune
            && st
                .best
                .as_ref()
                .is_some_and(|b| m.lower_bound(fs, len_so_far + (1 + rem_after) * n_bar) > b.cost)
        {
            continue;
        }
        issued += 1;
        let e = m.extend(node, s);
        if e.l == 0 {
            continue;
        }
        let len = len_so_far + e.l;
        let j = m.cost(e.end, fs, len);
        path[depth] = s;
        if last || e.l == n_bar {
            visit(&path[..=depth], len, j);
            offer(&mut st.best, j, path_codes(path, depth), path[0], len);
        } else {
            let lb = m.lower_bound(fs, len + rem_after * n_bar);
            // Capacity 216 = the largest candidate set.
            let _ = open.push((j, code(s), s, len, fs, lb));
        }
    }
    st.evaluations += issued;
    let _ = st.passes.push(issued);
    if !open.is_empty() {
        expand_open(
            m, st, opt, budget, events, node, path, depth, open, len_so_far, opt.beam, visit,
        );
    }
}

/// Searches the sequences of `horizon` from `root` (the state at `k`, held
/// position `s(k-1)`; the lazy check is the caller's). `visit` sees every
/// complete feasible sequence evaluated (its codes, length and cost).
pub fn search<M: SequenceModel>(
    m: &mut M,
    root: &M::Node,
    horizon: Horizon,
    opt: SearchOptions,
    visit: &mut Visit<'_, M::Cost>,
) -> Search {
    let events = horizon.events();
    let n_bar = m.n_bar();
    let s_prev = m.held(root);
    let cands = candidates(s_prev);
    let mut st = State {
        best: None,
        passes: heapless::Vec::new(),
        evaluations: cands.len() as u32,
        expanded: 0,
        budget_hit: false,
    };
    let _ = st.passes.push(st.evaluations);
    // First events: SE cost (fallback), J_dl (deadlock), expansion order.
    let mut se: Option<Best<M::Cost>> = None;
    let mut dl: Option<([u8; 3], M::Dl)> = None;
    let mut open: OpenList<M::Cost> = heapless::Vec::new();
    let remaining_ext = events[1..].iter().filter(|h| **h == Hold::Extend).count() as u32;
    let mut path = [[0u8; 3]; MAX_EVENTS];
    for &s1 in cands.iter() {
        let e = m.extend(root, s1);
        if e.l == 0 {
            if dl.is_none_or(|d| e.dl < d.1) {
                dl = Some((s1, e.dl));
            }
            continue;
        }
        let fs = anpc::switch_transitions(s_prev, s1);
        let j = m.cost(e.end, fs, e.l);
        path[0] = s1;
        let codes = path_codes(&path, 0);
        offer(&mut se, j, codes, s1, e.l);
        let complete = events.len() == 1 || (events[0] == Hold::Extend && e.l == n_bar);
        if complete {
            visit(&path[..1], e.l, j);
            offer(&mut st.best, j, codes, s1, e.l);
            continue;
        }
        let used = if events[0] == Hold::OneStep { 1 } else { e.l };
        let lb = m.lower_bound(fs, used + remaining_ext * n_bar);
        // Capacity 216 = the largest candidate set.
        let _ = open.push((j, code(s1), s1, used, fs, lb));
    }
    let budget = opt.max_expansions.min(MAX_PASSES as u32 - 1);
    expand_open(
        m,
        &mut st,
        &opt,
        budget,
        events,
        root,
        &mut path,
        0,
        open,
        0,
        u32::MAX,
        visit,
    );
    let State {
        best,
        passes,
        evaluations,
        budget_hit,
        ..
    } = st;
    let se_s1 = se.as_ref().map(|b| b.s1);
    let (decision, fallback) = match (best, se, dl) {
        (Some(b), _, _) => (
            Decision {
                s: b.s1,
                kind: DecisionKind::Optimal,
                horizon_steps: b.len,
                candidates: evaluations,
            },
            false,
        ),
        (None, Some(b), _) => (
            Decision {
                s: b.s1,
                kind: DecisionKind::Optimal,
                horizon_steps: b.len,
                candidates: evaluations,
            },
            true,
        ),
        (None, None, Some((s, _))) => (
            Decision {
                s,
                kind: DecisionKind::Deadlock,
                horizon_steps: 0,
                candidates: evaluations,
            },
            false,
        ),
        // Unreachable: s(k-1) is a candidate, so either some L* > 0 or a J_dl exists.
        (None, None, None) => (
            Decision {
                s: s_prev,
                kind: DecisionKind::Deadlock,
                horizon_steps: 0,
                candidates: evaluations,
            },
            false,
        ),
    };
    Search {
        differs_from_se: se_s1.is_some_and(|s| s != decision.s),
        decision,
        passes,
        budget_hit,
        fallback,
    }
}

/// Running statistics of a horizon controller (searches only; kept steps
/// count in `decisions`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HorizonStats {
    /// Decisions (kept included).
    pub decisions: u64,
    /// Decisions with a search.
    pub searches: u64,
    /// Candidate extensions evaluated, summed over searches.
    pub evaluations: u64,
    /// Most extensions in one search.
    pub max_evaluations: u32,
    /// Searches stopped by the expansion budget.
    pub budget_hits: u64,
    /// Searches that fell back to the SE decision.
    pub fallbacks: u64,
    /// Deadlock decisions.
    pub deadlocks: u64,
    /// Searches whose applied position differs from SE's on the same state.
    pub differs_from_se: u64,
    /// Core cycles summed over all decisions, for [`STATS_EXPLORERS`]
    /// explorers (FPGA model only).
    pub cycles: [u64; 3],
    /// Most core cycles of one decision, same order (FPGA model only).
    pub max_cycles: [u32; 3],
}

/// Explorer counts `N` the statistics report cycles for.
pub const STATS_EXPLORERS: [u32; 3] = [1, 2, 4];

impl HorizonStats {
    /// Records one search.
    pub fn record(&mut self, s: &Search) {
        self.searches += 1;
        self.evaluations += s.decision.candidates as u64;
        self.max_evaluations = self.max_evaluations.max(s.decision.candidates);
        self.budget_hits += s.budget_hit as u64;
        self.fallbacks += s.fallback as u64;
        self.differs_from_se += s.differs_from_se as u64;
        self.deadlocks += (s.decision.kind == DecisionKind::Deadlock) as u64;
    }

    /// Mean core cycles per decision for `STATS_EXPLORERS[i]` explorers.
    pub fn mean_cycles(&self, i: usize) -> f64 {
        if self.decisions == 0 {
            0.0
        } else {
            self.cycles[i] as f64 / self.decisions as f64
        }
    }

    /// Mean extensions per search.
    pub fn mean_evaluations(&self) -> f64 {
        if self.searches == 0 {
            0.0
        } else {
            self.evaluations as f64 / self.searches as f64
        }
    }
}

/// The reference as a [`SequenceModel`]: nodes are predicted [`CtrlState`]s.
struct RefModel<'a> {
    r: &'a mut MpdccRef,
    lambda_n: f64,
    n_bar: u32,
}

impl SequenceModel for RefModel<'_> {
    type Node = CtrlState;
    type Cost = f64;
    type Dl = f64;
    type End = f64;

    fn n_bar(&self) -> u32 {
        self.n_bar
    }

    fn held(&self, node: &CtrlState) -> [u8; 3] {
        node.s_prev
    }

    fn extend(&mut self, node: &CtrlState, s: [u8; 3]) -> Ext<f64, f64> {
        // Nodes come from checked states and the model; a failure (not
        // expected) counts as infeasible with the worst deadlock key.
        match self.r.evaluate(node, s) {
            Ok(e) => Ext {
                l: e.l_star,
                dl: e.excess_k1,
                end: e.v_n_end,
            },
            Err(_) => Ext {
                l: 0,
                dl: f64::INFINITY,
                end: 0.0,
            },
        }
    }

    fn cost(&self, v_n: f64, fs: u32, len: u32) -> f64 {
        // Same expression as `MpdccRef::cost` (bit-identical for SE).
        fs as f64 / len as f64 + self.lambda_n * v_n * v_n
    }

    fn lower_bound(&self, fs: u32, len_max: u32) -> f64 {
        fs as f64 / len_max.max(1) as f64
    }

    fn advance(&mut self, node: &CtrlState, s: [u8; 3], l: u32) -> CtrlState {
        self.r
            .predict(node, s, l)
            .unwrap_or(CtrlState { s_prev: s, ..*node })
    }
}

/// The idealized reference with a longer switching horizon.
pub struct HorizonRef {
    r: MpdccRef,
    p: DriveParams,
    horizon: Horizon,
    opt: SearchOptions,
    stats: HorizonStats,
}

impl HorizonRef {
    /// The reference for `horizon` with the default search options.
    pub fn new(p: &DriveParams, horizon: Horizon) -> Result<Self, ParamError> {
        Self::with_options(p, horizon, SearchOptions::default())
    }

    /// The same with explicit search options.
    pub fn with_options(
        p: &DriveParams,
        horizon: Horizon,
        opt: SearchOptions,
    ) -> Result<Self, ParamError> {
        Ok(Self {
            r: MpdccRef::new(p)?,
            p: *p,
            horizon,
            opt,
            stats: HorizonStats::default(),
        })
    }

    /// Statistics since construction.
    pub fn stats(&self) -> &HorizonStats {
        &self.stats
    }

    /// One search without the lazy check (tests and experiments); `visit`
    /// as in [`search`].
    pub fn search(
        &mut self,
        st: &CtrlState,
        visit: &mut Visit<'_, f64>,
    ) -> Result<Search, StateError> {
        st.check()?;
        let mut m = RefModel {
            r: &mut self.r,
            lambda_n: self.p.controller.lambda_n,
            n_bar: self.p.controller.horizon_max_steps,
        };
        Ok(search(&mut m, st, self.horizon, self.opt, visit))
    }

    /// The underlying SE reference (its model for tests).
    pub fn reference(&mut self) -> &mut MpdccRef {
        &mut self.r
    }
}

impl Controller for HorizonRef {
    fn name(&self) -> &'static str {
        self.horizon.name()
    }

    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        st.check()?;
        self.stats.decisions += 1;
        // Lazy evaluation (Algorithm 1, line 1), as for SE.
        if self.r.evaluate(st, st.s_prev)?.excess_k1 <= 0.0 {
            return Ok(Decision {
                s: st.s_prev,
                kind: DecisionKind::Kept,
                horizon_steps: 0,
                candidates: 0,
            });
        }
        let s = self.search(st, &mut |_, _, _| {})?;
        self.stats.record(&s);
        Ok(s.decision)
    }
}

#[cfg(test)]
pub(crate) mod tests {
    extern crate std;
    use super::*;
    use crate::mpdcc::machine;
    use crate::testrng::Rng;
    use std::vec::Vec;

    /// A toy model with pseudo-random extension lengths (small `N_bar`,
    /// many zero lengths and ties) for the enumeration and pruning tests.
    struct Toy {
        seed: u64,
        n_bar: u32,
    }

    fn mix(mut z: u64) -> u64 {
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    impl SequenceModel for Toy {
        type Node = ([u8; 3], u64);
        type Cost = f64;
        type Dl = i64;
        type End = f64;
        fn n_bar(&self) -> u32 {
            self.n_bar
        }
        fn held(&self, n: &Self::Node) -> [u8; 3] {
            n.0
        }
        fn extend(&mut self, n: &Self::Node, s: [u8; 3]) -> Ext<i64, f64> {
            let h = mix(self.seed ^ n.1.wrapping_mul(1_000_003) ^ code(s) as u64);
            Ext {
                l: ((h % 7) as u32).min(self.n_bar),
                dl: ((h >> 8) % 5) as i64,
                end: ((h >> 16) % 3) as f64 * 0.05,
            }
        }
        fn cost(&self, end: f64, fs: u32, len: u32) -> f64 {
            fs as f64 / len as f64 + end * end
        }
        fn lower_bound(&self, fs: u32, len_max: u32) -> f64 {
            fs as f64 / len_max.max(1) as f64
        }
        fn advance(&mut self, n: &Self::Node, s: [u8; 3], l: u32) -> Self::Node {
            (s, mix(n.1 ^ (l as u64) << 20 ^ code(s) as u64))
        }
    }

    type Seq = (Vec<[u8; 3]>, u32, f64);

    /// Independent enumeration of every admissible, feasible sequence
    /// (all 512 positions tried at each event).
    fn brute_force(m: &mut Toy, root: &([u8; 3], u64), h: Horizon) -> Vec<Seq> {
        let mut out = Vec::new();
        let mut prefix = Vec::new();
        brute_rec(m, root, h.events(), 0, 0, 0, &mut prefix, &mut out);
        out
    }

    #[allow(clippy::too_many_arguments)]
    fn brute_rec(
        m: &mut Toy,
        node: &([u8; 3], u64),
        ev: &[Hold],
        depth: usize,
        fs0: u32,
        len0: u32,
        prefix: &mut Vec<[u8; 3]>,
        out: &mut Vec<Seq>,
    ) {
        let held = node.0;
        for a in 0..512u32 {
            let s = [(a >> 6) as u8, ((a >> 3) & 7) as u8, (a & 7) as u8];
            if !anpc::admissible(held, s) {
                continue;
            }
            let e = m.extend(node, s);
            if e.l == 0 {
                continue;
            }
            let fs = fs0 + anpc::switch_transitions(held, s);
            prefix.push(s);
            let capped = ev[depth] == Hold::Extend && e.l == m.n_bar;
            if depth + 1 == ev.len() || capped {
                let len = len0 + e.l;
                out.push((prefix.clone(), len, m.cost(e.end, fs, len)));
            } else {
                let used = if ev[depth] == Hold::OneStep { 1 } else { e.l };
                let next = m.advance(node, s, used);
                brute_rec(m, &next, ev, depth + 1, fs, len0 + used, prefix, out);
            }
            prefix.pop();
        }
    }

    fn key(s: &Seq) -> [u16; MAX_EVENTS] {
        core::array::from_fn(|i| s.0.get(i).map_or(0, |&x| code(x)))
    }

    #[test]
    fn names_parse() {
        for h in Horizon::ALL {
            assert_eq!(Horizon::parse(h.name()), Some(h));
        }
        assert_eq!(Horizon::parse("sese"), Some(Horizon::Sese));
        assert_eq!(Horizon::parse("eSESE"), Some(Horizon::Sese));
        assert_eq!(Horizon::parse("SEE"), None);
        assert_eq!(Horizon::parse(""), None);
    }

    /// Without pruning the search visits every admissible feasible sequence
    /// exactly once (the same set as an independent enumeration over all
    /// 512 x 512 position pairs); with branch and bound and an unlimited
    /// budget it decides as the brute-force arg-min with the documented
    /// tie-break.
    #[test]
    fn enumeration_is_complete_once_and_pruning_is_exact() {
        let mut rng = Rng(0x5eed_1234_abcd_0001);
        let mut pruned_sum = 0usize;
        let mut total_sum = 0usize;
        for case in 0..24 {
            let h = Horizon::ALL[case % 4];
            // Three events: a short cap ends most sequences early (small tree).
            let n_bar = if h == Horizon::Sesese { 2 } else { 4 };
            let mut toy = Toy {
                seed: rng.next_u64(),
                n_bar,
            };
            let sp = (rng.next_u64() % 512) as u32;
            let root = (
                [(sp >> 6) as u8, ((sp >> 3) & 7) as u8, (sp & 7) as u8],
                rng.next_u64(),
            );
            let mut want = brute_force(&mut toy, &root, h);
            let mut seen: Vec<Seq> = Vec::new();
            let all = SearchOptions {
                max_expansions: 512,
                beam: 216,
                prune: false,
            };
            let full = search(&mut toy, &root, h, all, &mut |p, l, j| {
                seen.push((Vec::from(p), l, j))
            });
            let n_seen = seen.len();
            seen.sort_by_key(key);
            seen.dedup_by_key(|s| key(s));
            assert_eq!(seen.len(), n_seen, "case {case}: a sequence visited twice");
            want.sort_by_key(key);
            // Without pruning there is no budget: everything is visited. The
            // budget-bound search below is exact only if its budget (512
            // nodes) covers the tree: skip the rare larger trees.
            assert!(!full.budget_hit);
            if full.passes.len() >= MAX_PASSES {
                continue;
            }
            assert_eq!(seen, want, "case {case} {h:?}");
            total_sum += want.len();
            // Brute-force arg-min, ties to the smaller code path.
            let best = want
                .iter()
                .min_by(|a, b| a.2.partial_cmp(&b.2).unwrap().then(key(a).cmp(&key(b))));
            let bb = SearchOptions {
                max_expansions: 512,
                beam: 216,
                prune: true,
            };
            let mut n_bb = 0usize;
            let d = search(&mut toy, &root, h, bb, &mut |_, _, _| n_bb += 1);
            pruned_sum += n_bb;
            match best {
                Some(b) => {
                    assert_eq!(d.decision.s, b.0[0], "case {case} {h:?}");
                    assert_eq!(d.decision.horizon_steps, b.1);
                    assert_eq!(d.decision.kind, DecisionKind::Optimal);
                    assert!(!d.fallback);
                }
                None => assert!(d.fallback || d.decision.kind == DecisionKind::Deadlock),
            }
        }
        // Branch and bound visits fewer complete sequences than enumeration.
        assert!(pruned_sum * 2 < total_sum, "{pruned_sum} vs {total_sum}");
    }

    /// A state near the operating point's steady state (errors within
    /// 0.95 `delta_i`, capacitors within 0.045 pu), random `s(k-1)`.
    pub(crate) fn random_state(p: &DriveParams, rng: &mut Rng) -> CtrlState {
        let op = p.operating_point;
        let th = rng.uniform(0.0, 2.0 * core::f64::consts::PI);
        let i_ref = [libm::cos(th), libm::sin(th)];
        let psi = machine::steady_state_flux(&p.machine, i_ref, op.omega_s_pu, op.omega_r_pu);
        let d = 0.95 * p.controller.delta_i_pu;
        CtrlState {
            x_m: [
                i_ref[0] + rng.uniform(-d, d),
                i_ref[1] + rng.uniform(-d, d),
                psi[0],
                psi[1],
            ],
            v_n_pu: rng.uniform(-0.045, 0.045),
            v_ph_pu: core::array::from_fn(|_| {
                p.inverter.v_ph_ref_pu() + rng.uniform(-0.045, 0.045)
            }),
            omega_r_pu: op.omega_r_pu,
            omega_s_pu: op.omega_s_pu,
            i_ref_ab_pu: i_ref,
            s_prev: core::array::from_fn(|_| (rng.next_u64() % 8) as u8),
        }
    }

    /// SE through the sequence search is the paper's reference, decision
    /// for decision.
    #[test]
    fn se_horizon_is_the_reference() {
        let p = DriveParams::default();
        let mut r = MpdccRef::new(&p).unwrap();
        let mut h = HorizonRef::new(&p, Horizon::Se).unwrap();
        let mut rng = Rng(77);
        for _ in 0..150 {
            let st = random_state(&p, &mut rng);
            let a = r.step(&st).unwrap();
            let mut b = h.step(&st).unwrap();
            b.candidates = a.candidates;
            assert_eq!(a, b, "{st:?}");
        }
    }

    /// Deadlock handling: whenever some first position keeps every output
    /// inside at k+1 (checked with the reference model), no horizon
    /// answers with a deadlock, and the position it applies is one of
    /// those (so the bounds are not left when they need not be).
    #[test]
    fn deadlock_handling_never_leaves_bounds_needlessly() {
        let mut p = DriveParams::default();
        // Narrow bounds make deadlocks and dead ends frequent.
        p.controller.delta_i_pu = 0.04;
        p.controller.horizon_max_steps = 32;
        let mut rng = Rng(4242);
        let (mut searched, mut deadlocks, mut fallbacks) = (0, 0, 0);
        for h in [Horizon::Sse, Horizon::Sese, Horizon::Sesese] {
            let mut c = HorizonRef::new(&p, h).unwrap();
            for _ in 0..60 {
                let mut st = random_state(&p, &mut rng);
                st.x_m[0] += rng.uniform(-0.03, 0.03);
                let cands = candidates(st.s_prev);
                let ok: Vec<[u8; 3]> = cands
                    .iter()
                    .copied()
                    .filter(|&s| c.reference().evaluate(&st, s).unwrap().l_star > 0)
                    .collect();
                let d = c.step(&st).unwrap();
                if d.kind == DecisionKind::Kept {
                    continue;
                }
                searched += 1;
                if ok.is_empty() {
                    assert_eq!(d.kind, DecisionKind::Deadlock);
                    deadlocks += 1;
                } else {
                    assert_eq!(d.kind, DecisionKind::Optimal, "{h:?} {st:?}");
                    assert!(ok.contains(&d.s), "{h:?}: {:?} leaves a bound", d.s);
                }
            }
            fallbacks += c.stats().fallbacks;
        }
        std::println!("searched {searched}, deadlocks {deadlocks}, SE fallbacks {fallbacks}");
        assert!(searched > 40 && deadlocks > 0 && fallbacks > 0);
    }

    /// On the reference model, branch and bound with an unlimited budget
    /// decides as exhaustive enumeration (SESE and SSE, a few states).
    #[test]
    fn pruning_is_exact_on_the_reference_model() {
        let mut p = DriveParams::default();
        p.controller.horizon_max_steps = 64;
        let mut rng = Rng(9);
        for h in [Horizon::Sse, Horizon::Sese] {
            let exact = SearchOptions {
                max_expansions: 512,
                beam: 216,
                prune: false,
            };
            let bb = SearchOptions {
                max_expansions: 512,
                beam: 216,
                prune: true,
            };
            let mut a = HorizonRef::with_options(&p, h, exact).unwrap();
            let mut b = HorizonRef::with_options(&p, h, bb).unwrap();
            let mut n = 0;
            while n < 3 {
                let st = random_state(&p, &mut rng);
                if a.reference().evaluate(&st, st.s_prev).unwrap().excess_k1 <= 0.0 {
                    continue;
                }
                let mut all: Vec<Seq> = Vec::new();
                let sa = a
                    .search(&st, &mut |q, l, j| all.push((Vec::from(q), l, j)))
                    .unwrap();
                if sa.passes.len() == MAX_PASSES {
                    continue;
                }
                let sb = b.search(&st, &mut |_, _, _| {}).unwrap();
                let best = all
                    .iter()
                    .min_by(|x, y| x.2.partial_cmp(&y.2).unwrap().then(key(x).cmp(&key(y))));
                if let Some(bst) = best {
                    assert_eq!(sb.decision.s, bst.0[0]);
                    assert_eq!(sb.decision.horizon_steps, bst.1);
                }
                assert_eq!(sa.decision.s, sb.decision.s);
                assert!(sb.decision.candidates <= sa.decision.candidates);
                n += 1;
            }
        }
    }
}
