//! Longer switching horizons on the 16-bit FPGA model: the sequence search
//! of [`super::horizon_ref`] over the frozen core's datapath (common terms,
//! explorer, cost of [`super::mpdcc_fixed`]), plus the one new unit a longer
//! horizon needs: the **state advance** that turns a candidate's predicted
//! output errors at `k + l` into the core's inputs at `k + l` (the next
//! switching instant), from which the common terms are computed again.
//! For SE this is `mpdcc_fixed::decide` exactly (tested bit for bit); the frozen
//! core is not changed.
//!
//! # State advance (fixed point; formats of docs/mpdcc-fpga.md)
//! From a node's inputs `x` and common terms `c`, candidate `s` held `l` steps:
//! - output errors `e_j(k+l) = e_j(k) + Delta_j(l)`, Q2.13, saturated:
//!   `Delta_j` from the one-step prediction for `l = 1` (the core's
//!   `exact_first_step`), else from the search lanes' node polyline
//!   ([`mpdcc_fixed::lane_change`]), the same interpolation that found `L*`;
//! - rotation angle `theta = l T omega_s`: `T omega_s` is the core's
//!   one-step register (f17), times `l` exactly, rounded to f14 (an 18-bit
//!   word, `|theta| < 4` rad);
//! - `sin theta = theta (1 - theta^2/6 (1 - theta^2/20))`, `cos theta = 1 -
//!   theta^2/2 (1 - theta^2/12 (1 - theta^2/30))` (Horner, every product
//!   rounded to f14; truncation error < 2e-4 for `|theta| <= 1` rad, i.e.
//!   128 steps at 1 pu);
//! - current reference `i*(k+l) = R(theta) i*(k)` and rotor flux `psi(k+l)
//!   = R(theta) psi(k)` (the flux turns with the stator frequency in steady
//!   state; its magnitude changes with the rotor time constant, ~1e-3 per
//!   100 steps, which the advance neglects), Q2.13 / Q1.14, rounded;
//! - stator current `i(k+l) = i*(k+l) - e_ab(k+l)` with `e_alpha = e_a`,
//!   `e_beta = (e_b - e_c)/sqrt(3)` (`1/sqrt(3)` Q1.14), saturated;
//! - `v_n = -e_vn`, `v_ph = V_dc/4 - e_ph`; `omega_r`, `omega_s` unchanged;
//!   `s(k-1) = s`.
//!
//! # Cycles ([`horizon_cycles`])
//! The frozen core's count ([`cycles::pipelined_core_cycles`]) for the
//! first event, plus per expanded node the advance ([`ADVANCE_CYCLES`]) and
//! one more pass of the core with the candidates issued at that node (the
//! same common-terms unit, explorers and arg-min tree, reused). A model for
//! a later RTL step, not a measured count.
#![allow(clippy::needless_range_loop)]

use super::controller::{Controller, CtrlState, Decision, DecisionKind, StateError};
use super::cycles;
use super::formats::{sat16, F_C, F_SMALL};
use super::horizon_ref::{
    self, Ext, Horizon, HorizonStats, Search, SearchOptions, SequenceModel, STATS_EXPLORERS,
};
use super::mpdcc_fixed::{self, Coeffs, Common, FpgaConfig, FpgaError, Inputs, MpdccFixed, Nodes};
use super::params::DriveParams;
use crate::fixedpoint::rshift_round;

/// Cycles of one state advance: re-issue of the node's candidate to an
/// explorer for its node changes ([`cycles::PIPELINED_EXPLORER_LATENCY`]),
/// then the rotation polynomial on the common-terms multipliers: `theta`,
/// `theta^2`, three Horner products for sine and cosine in parallel, the
/// eight rotation products (two issue cycles on four multipliers), each
/// product 3 cycles (Fig. 3 block latency): `41 + 3 + 3 + 9 + 2 + 3 + 2`
/// (the final subtraction and the register).
pub const ADVANCE_CYCLES: u32 = cycles::PIPELINED_EXPLORER_LATENCY + 3 + 3 + 9 + 2 + 3 + 2;

/// `1/sqrt(3)`, Q1.14.
const INV_SQRT3: i64 = 9459;
/// Horner constants, f14: 1/6, 1/20, 1/12, 1/30.
const C6: i64 = 2731;
const C20: i64 = 819;
const C12: i64 = 1365;
const C30: i64 = 546;
const ONE: i64 = 1 << F_C;

/// `(sin, cos)` of `theta` (f14), f14 (see the module documentation).
pub fn sin_cos_q14(theta: i64) -> (i64, i64) {
    let m = |a: i64, b: i64| rshift_round(a * b, F_C);
    let t2 = m(theta, theta);
    let s_in = ONE - m(t2, C20);
    let s = theta - m(theta, m(m(t2, s_in), C6));
    let c_in = ONE - m(t2, C30);
    let c_mid = ONE - m(m(t2, c_in), C12);
    let c = ONE - rshift_round(m(t2, c_mid), 1);
    (s, c)
}

/// The node polyline of candidate `s` (the explorer's node changes).
fn nodes_of(k: &Coeffs, c: &Common, s: [u8; 3]) -> Nodes {
    core::array::from_fn(|i| {
        if i < k.nodes as usize {
            mpdcc_fixed::node_deltas(k, c, s, i)
        } else {
            [0; 7]
        }
    })
}

/// The core's inputs `l >= 1` steps after the node `(x, c)` with `s` held.
pub fn advance(k: &Coeffs, x: &Inputs, c: &Common, s: [u8; 3], l: u32) -> Inputs {
    let e: [i16; 7] = if l == 1 && k.exact_first_step {
        let d1 = mpdcc_fixed::deltas(k, c, s, true);
        core::array::from_fn(|j| sat16(c.e0[j] as i64 + d1[j] as i64))
    } else {
        let nodes = nodes_of(k, c, s);
        core::array::from_fn(|j| sat16(c.e0[j] as i64 + mpdcc_fixed::lane_change(k, &nodes, l, j)))
    };
    // theta = l T omega_s: f17 register times l, rounded to f14.
    let ks1 = fpga_one_step_theta(k, x);
    let theta = rshift_round(l as i64 * ks1 as i64, F_SMALL - F_C);
    let (sn, cs) = sin_cos_q14(theta);
    let rot = |v: [i16; 2]| -> [i16; 2] {
        let (a, b) = (v[0] as i64, v[1] as i64);
        [
            sat16(rshift_round(cs * a - sn * b, F_C)),
            sat16(rshift_round(sn * a + cs * b, F_C)),
        ]
    };
    let i_ref_ab = rot(x.i_ref_ab);
    let psi_ab = rot(x.psi_ab);
    let e_alpha = e[0] as i64;
    let e_beta = rshift_round((e[1] as i64 - e[2] as i64) * INV_SQRT3, F_C);
    let i_ab = [
        sat16(i_ref_ab[0] as i64 - e_alpha),
        sat16(i_ref_ab[1] as i64 - e_beta),
    ];
    Inputs {
        i_ab,
        psi_ab,
        v_n: sat16(-(e[3] as i64)),
        v_ph: core::array::from_fn(|ph| sat16(k.v_ph_ref as i64 - e[4 + ph] as i64)),
        i_ref_ab,
        omega_r: x.omega_r,
        omega_s: x.omega_s,
        s_prev: s,
        saturated: x.saturated,
    }
}

/// `T omega_s`, f17 (the one-step rotation register of the common terms).
fn fpga_one_step_theta(k: &Coeffs, x: &Inputs) -> i16 {
    super::formats::mul(k.c_s1, F_SMALL, x.omega_s, super::formats::F_I, F_SMALL)
}

/// A node of the fixed-point search: the core's inputs and common terms.
pub struct FixedNode {
    /// Inputs at the switching instant.
    pub x: Inputs,
    /// Common terms of `x`.
    pub c: Common,
}

struct FixedModel<'a> {
    k: &'a Coeffs,
}

impl SequenceModel for FixedModel<'_> {
    type Node = FixedNode;
    type Cost = u32;
    type Dl = i32;
    type End = i16;

    fn n_bar(&self) -> u32 {
        self.k.n_bar
    }

    fn held(&self, node: &FixedNode) -> [u8; 3] {
        node.x.s_prev
    }

    fn extend(&mut self, node: &FixedNode, s: [u8; 3]) -> Ext<i32, i16> {
        let r = mpdcc_fixed::explore(self.k, &node.c, node.x.s_prev, s);
        let evn = if r.l_star == 0 {
            0
        } else {
            let nodes = nodes_of(self.k, &node.c, s);
            sat16(node.c.e0[3] as i64 + mpdcc_fixed::lane_change(self.k, &nodes, r.l_star, 3))
        };
        Ext {
            l: r.l_star,
            dl: r.j_dl,
            end: evn,
        }
    }

    fn cost(&self, evn: i16, fs: u32, len: u32) -> u32 {
        mpdcc_fixed::sequence_cost(self.k, fs, len, evn)
    }

    fn lower_bound(&self, fs: u32, len_max: u32) -> u32 {
        // recip is non-increasing in l and the terminal term is >= 0.
        mpdcc_fixed::sequence_cost(self.k, fs, len_max.max(1), 0)
    }

    fn advance(&mut self, node: &FixedNode, s: [u8; 3], l: u32) -> FixedNode {
        let x = advance(self.k, &node.x, &node.c, s, l);
        FixedNode {
            c: mpdcc_fixed::common_terms(self.k, &x),
            x,
        }
    }
}

/// Core cycles of one decision with `n` explorers: the frozen core's count
/// for the first pass (also for a kept decision, as in the RTL), then
/// [`ADVANCE_CYCLES`] plus one core pass per expanded node.
pub fn horizon_cycles(n: u32, first: u32, expanded: &[u32]) -> u32 {
    cycles::pipelined_core_cycles(n, first)
        + expanded
            .iter()
            .map(|&c| ADVANCE_CYCLES + cycles::pipelined_core_cycles(n, c))
            .sum::<u32>()
}

/// Worst case over all decisions: every node expanded up to the budget
/// with the largest candidate set (no pruning).
pub fn worst_case_cycles(horizon: Horizon, n: u32, max_expansions: u32) -> u32 {
    let s = cycles::max_candidates();
    let e = if horizon == Horizon::Se {
        0
    } else {
        max_expansions
    };
    cycles::pipelined_core_cycles(n, s) + e * (ADVANCE_CYCLES + cycles::pipelined_core_cycles(n, s))
}

/// One fixed-point search (lazy check included): the decision, the search
/// (`None` when kept) and the core cycles for `n` explorers.
pub fn decide(
    k: &Coeffs,
    x: &Inputs,
    horizon: Horizon,
    opt: SearchOptions,
    n: u32,
    visit: &mut horizon_ref::Visit<'_, u32>,
) -> (Decision, Option<Search>, u32) {
    let c = mpdcc_fixed::common_terms(k, x);
    let s_prev = x.s_prev;
    let first = super::controller::candidates(s_prev).len() as u32;
    if mpdcc_fixed::lazy_ok(k, &c, s_prev) {
        let d = Decision {
            s: s_prev,
            kind: DecisionKind::Kept,
            horizon_steps: 0,
            candidates: 0,
        };
        return (d, None, cycles::pipelined_core_cycles(n, first));
    }
    let root = FixedNode { x: *x, c };
    let mut m = FixedModel { k };
    let s = horizon_ref::search(&mut m, &root, horizon, opt, visit);
    let cyc = horizon_cycles(n, s.passes[0], &s.passes[1..]);
    (s.decision, Some(s), cyc)
}

/// The FPGA model with a longer switching horizon.
pub struct HorizonFixed {
    core: MpdccFixed,
    horizon: Horizon,
    opt: SearchOptions,
    stats: HorizonStats,
}

impl HorizonFixed {
    /// The frozen core's arithmetic ([`MpdccFixed::new`]) with `horizon`.
    pub fn new(
        p: &DriveParams,
        cfg: FpgaConfig,
        horizon: Horizon,
        opt: SearchOptions,
    ) -> Result<Self, FpgaError> {
        Ok(Self {
            core: MpdccFixed::new(p, cfg)?,
            horizon,
            opt,
            stats: HorizonStats::default(),
        })
    }

    /// Statistics since construction (cycles for the configured explorers).
    pub fn stats(&self) -> &HorizonStats {
        &self.stats
    }

    /// The coefficients in use.
    pub fn coeffs(&self) -> &Coeffs {
        self.core.coeffs()
    }

    /// One decision on quantized inputs (no statistics).
    pub fn decide_raw(&self, x: &Inputs) -> (Decision, Option<Search>, u32) {
        decide(
            self.core.coeffs(),
            x,
            self.horizon,
            self.opt,
            self.core.config().explorers,
            &mut |_, _, _| {},
        )
    }
}

impl Controller for HorizonFixed {
    fn name(&self) -> &'static str {
        self.horizon.name()
    }

    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let x = Inputs::quantize(st)?;
        let (d, s, _) = self.decide_raw(&x);
        self.stats.decisions += 1;
        let first = super::controller::candidates(st.s_prev).len() as u32;
        for (i, &n) in STATS_EXPLORERS.iter().enumerate() {
            let cyc = match &s {
                Some(s) => horizon_cycles(n, s.passes[0], &s.passes[1..]),
                None => cycles::pipelined_core_cycles(n, first),
            };
            self.stats.cycles[i] += cyc as u64;
            self.stats.max_cycles[i] = self.stats.max_cycles[i].max(cyc);
        }
        if let Some(s) = s {
            self.stats.record(&s);
        }
        Ok(d)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::mpdcc::closed_loop::{self, LoopConfig};
    use crate::mpdcc::formats::{to_f64, F_I};
    use crate::mpdcc::horizon_ref::tests::random_state;
    use crate::mpdcc::horizon_ref::HorizonRef;
    use crate::mpdcc::mpdcc_ref::MpdccRef;
    use crate::testrng::Rng;

    fn cfg(p: &DriveParams) -> FpgaConfig {
        FpgaConfig::core(&p.machine)
    }

    /// SE through the sequence search is the frozen core: the same decision
    /// (position, kind, L*, candidate count) and the same cycle count as
    /// `mpdcc_fixed::decide`, on random states.
    #[test]
    fn se_horizon_is_the_frozen_core_bit_for_bit() {
        let p = DriveParams::default();
        let f = MpdccFixed::new(&p, cfg(&p)).unwrap();
        let mut rng = Rng(31);
        let mut searched = 0;
        for _ in 0..400 {
            let st = random_state(&p, &mut rng);
            let x = Inputs::quantize(&st).unwrap();
            let want = mpdcc_fixed::decide(f.coeffs(), &x, 2);
            let (d, s, _) = decide(
                f.coeffs(),
                &x,
                Horizon::Se,
                SearchOptions::default(),
                2,
                &mut |_, _, _| {},
            );
            assert_eq!(d, want.decision);
            searched += s.is_some() as u32;
        }
        assert!(searched > 50, "{searched}");
    }

    /// The rotation polynomial against libm over the angles a horizon
    /// reaches (up to 256 steps at 1 pu): within 3e-4.
    #[test]
    fn sin_cos_polynomial_is_accurate() {
        for i in -300..=300 {
            let th = i as f64 / 200.0; // -1.5..1.5 rad
            let (s, c) = sin_cos_q14(libm::round(th * 16384.0) as i64);
            let tol = if th.abs() <= 1.0 { 2.5e-4 } else { 4e-3 };
            assert!((s as f64 / 16384.0 - libm::sin(th)).abs() < tol, "sin {th}");
            assert!((c as f64 / 16384.0 - libm::cos(th)).abs() < tol, "cos {th}");
        }
    }

    /// The fixed-point state advance against the reference's prediction of
    /// the same candidate over the same steps (at most its `L*`): currents
    /// and capacitor voltages within the extrapolation error.
    #[test]
    fn state_advance_matches_reference_prediction() {
        let p = DriveParams::default();
        let f = MpdccFixed::new(&p, cfg(&p)).unwrap();
        let k = f.coeffs();
        let mut r = MpdccRef::new(&p).unwrap();
        let mut rng = Rng(5);
        let mut worst = [0.0f64; 3];
        for n in 0..400 {
            let st = random_state(&p, &mut rng);
            let s = st.s_prev;
            // Along a sequence a position is held at most until it leaves a
            // bound (the current stays near its reference, as eq. 18b assumes).
            let l_star = r.evaluate(&st, s).unwrap().l_star;
            if l_star == 0 {
                continue;
            }
            let l = [1, 5, 17, 40][n % 4].min(l_star);
            let x = Inputs::quantize(&st).unwrap();
            let c = mpdcc_fixed::common_terms(k, &x);
            let a = advance(k, &x, &c, s, l);
            let b = r.predict(&st, s, l).unwrap();
            let di = (to_f64(a.i_ab[0], F_I) - b.x_m[0])
                .abs()
                .max((to_f64(a.i_ab[1], F_I) - b.x_m[1]).abs());
            let dr = (to_f64(a.i_ref_ab[0], F_I) - b.i_ref_ab_pu[0])
                .abs()
                .max((to_f64(a.i_ref_ab[1], F_I) - b.i_ref_ab_pu[1]).abs());
            let dv = (to_f64(a.v_n, F_I) - b.v_n_pu)
                .abs()
                .max((to_f64(a.v_ph[0], F_I) - b.v_ph_pu[0]).abs());
            worst = [worst[0].max(di), worst[1].max(dr), worst[2].max(dv)];
        }
        std::println!(
            "advance errors: current {:.4}, reference {:.5}, voltages {:.5} pu",
            worst[0],
            worst[1],
            worst[2]
        );
        assert!(worst[1] < 4e-4, "{worst:?}");
        // Eq. (18b) holds the phase currents over the interval: the
        // capacitor voltages drift by up to ~0.1 x delta_i x l T / C.
        assert!(worst[0] < 0.03, "{worst:?}");
        assert!(worst[2] < 8e-3, "{worst:?}");
    }

    /// Per horizon: the 16-bit model shadowing the horizon reference in the
    /// closed loop (the reference drives) decides differently in at most
    /// 1 % of the steps, and the reference-driven loop stays inside its
    /// bounds (up to the model-vs-plant error).
    #[test]
    fn closed_loop_mismatch_per_horizon() {
        let p = DriveParams::default();
        let lc = LoopConfig {
            warmup_periods: 1,
            measure_periods: 2,
        };
        for h in Horizon::ALL {
            let mut r = HorizonRef::new(&p, h).unwrap();
            let mut f = HorizonFixed::new(&p, cfg(&p), h, SearchOptions::default()).unwrap();
            let res = closed_loop::run(&p, &lc, &mut r, Some(&mut f), &mut |_| {}).unwrap();
            let fs = f.stats();
            std::println!(
                "{}: mismatch {:.2} % ({} of {} steps), fsw {:.1} Hz, THD {:.2} %, candidates mean {:.0} max {}, cycles N=2 mean {:.0} max {}",
                h.name(),
                res.mismatch_percent(),
                res.shadow_mismatches,
                res.steps,
                res.fsw_hz,
                res.thd_percent,
                fs.mean_evaluations(),
                fs.max_evaluations,
                fs.mean_cycles(1),
                fs.max_cycles[1]
            );
            assert!(res.mismatch_percent() <= 1.0, "{}: {res:?}", h.name());
            // The reference's model differs from the plant by ~1e-7 pu per
            // step: a loop riding a bound may leave it by that, rarely.
            assert!(
                res.steps_outside_bounds * 500 <= res.steps,
                "{}: {res:?}",
                h.name()
            );
        }
    }
}
