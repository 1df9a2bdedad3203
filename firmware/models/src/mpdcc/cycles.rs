//! Structural clock-cycle model of the FPGA MPDCC core (paper 001, Sec.
//! VII-A, Table II).
//!
//! Not a formula: each unit's work is listed as operations with their data
//! dependencies, exactly the arithmetic of [`super::mpdcc_fixed`], and scheduled on
//! the hardware the paper describes:
//! - **Computational block** (Fig. 3): operand muxes, a multiplier, an adder,
//!   a 3-stage pipeline. One operation enters a block per cycle; its result
//!   is usable 3 cycles later. The scheduler and each explorer own 4 blocks
//!   (Sec. V-C: "four of the computational blocks").
//! - **Search lanes**: 7 Algorithm-2 lanes per explorer in parallel (one
//!   comparator and adder each), `M + 1` cycles worst case
//!   ([`super::binsearch`]); their first cycle also forms `J_dl`'s terms.
//! - **Compare trees**: `ceil(log2 7) = 3` levels for `min l_j` (and `max` of
//!   `J_dl` in parallel), 1 cycle per level; reciprocal ROM 1 cycle; handshake
//!   registers 1 cycle.
//!
//! A list scheduler (operations in program order, each starts when its
//! inputs are ready and a block issue slot is free) gives the latency of the
//! scheduler's pre-phase and of one explorer evaluation. Candidates are then
//! dispatched one per cycle, each to the explorer that is free first; the
//! scheduler compares results as they arrive (1 cycle after the last) and
//! registers the output (1 cycle).
//!
//! The paper's `47 + 2176/n` is exact only when `n` divides the candidate
//! count: its own Table II rounds `47 + 2176/3 = 772.3` to 772 and
//! `47 + 2176/6 = 409.7` to 410, so it is a fit, not a count. A structural
//! model gives `pre + ceil(|S|/n) T_cand + post` instead; see
//! docs/mpdcc-fpga.md for the comparison.

/// What an operation occupies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// One issue slot of a computational block, [`CycleModel::block_latency`] cycles.
    Block,
    /// The 7 Algorithm-2 lanes (duration given per evaluation).
    Lanes,
    /// A compare tree of the given depth (1 cycle per level).
    Tree(u32),
    /// A ROM read or a handshake/register stage: 1 cycle.
    Reg,
}

/// One operation of a unit's program.
///
/// Operations name their inputs by handle, not by position, so inserting an
/// operation cannot silently rewire the others: a dependency on a handle
/// that no earlier operation has is an error ([`check_program`], tested for
/// every program here). The `k`-th partial result of an accumulation is
/// `name#k`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Op {
    /// Handle: unique within its program.
    pub id: &'static str,
    /// What it computes (the names used in [`super::mpdcc_fixed`]).
    pub name: &'static str,
    /// Resource and latency class.
    pub kind: Kind,
    /// Handles of the operations whose results it needs.
    pub deps: &'static [&'static str],
}

const fn op(id: &'static str, name: &'static str, kind: Kind, deps: &'static [&'static str]) -> Op {
    Op {
        id,
        name,
        kind,
        deps,
    }
}

/// Why a program is malformed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProgramError {
    /// Two operations share this handle.
    Duplicate(&'static str),
    /// This dependency names no earlier operation.
    Unresolved(&'static str),
    /// More operations than the scheduler's tables hold.
    TooLong,
}

/// Most operations in one program (size of [`CycleModel::makespan`]'s tables).
pub const MAX_OPS: usize = 128;

/// Index of the operation with handle `id` among `ops[..before]`.
fn find(ops: &[Op], before: usize, id: &str) -> Option<usize> {
    ops[..before.min(ops.len())].iter().position(|o| o.id == id)
}

/// Every handle unique, every dependency an earlier operation.
pub fn check_program(ops: &[Op]) -> Result<(), ProgramError> {
    if ops.len() > MAX_OPS {
        return Err(ProgramError::TooLong);
    }
    for (i, o) in ops.iter().enumerate() {
        if find(ops, i, o.id).is_some() {
            return Err(ProgramError::Duplicate(o.id));
        }
        if let Some(d) = o.deps.iter().find(|d| find(ops, i, d).is_none()) {
            return Err(ProgramError::Unresolved(d));
        }
    }
    Ok(())
}

use Kind::{Block as B, Lanes, Reg, Tree};

/// One explorer evaluation with the paper's structure (`Structure::PAPER`):
/// one chord, no accuracy options.
pub const EXPLORER_OPS_PAPER: &[Op] = &[
    op("load candidate, f_s", "load candidate, f_s", Reg, &[]),
    op(
        "v_a",
        "v_a = ph v_ph,a + mux(rail Vdc/2 | v_n)",
        B,
        &["load candidate, f_s"],
    ),
    op(
        "v_b",
        "v_b = ph v_ph,b + mux(rail Vdc/2 | v_n)",
        B,
        &["load candidate, f_s"],
    ),
    op(
        "v_c",
        "v_c = ph v_ph,c + mux(rail Vdc/2 | v_n)",
        B,
        &["load candidate, f_s"],
    ),
    op("sum", "sum = v_a + v_b", B, &["v_a", "v_b"]),
    op("sum#2", "sum += v_c", B, &["sum", "v_c"]),
    op("u_a", "u_a = 3 v_a - sum", B, &["v_a", "sum#2"]),
    op("u_b", "u_b = 3 v_b - sum", B, &["v_b", "sum#2"]),
    op("u_c", "u_c = 3 v_c - sum", B, &["v_c", "sum#2"]),
    op("D_a", "D_a = dn_a - g3 u_a", B, &["u_a"]),
    op("D_b", "D_b = dn_b - g3 u_b", B, &["u_b"]),
    op("D_c", "D_c = dn_c - g3 u_c", B, &["u_c"]),
    op("D_vn", "D_vn = np_a P_n,a", B, &["load candidate, f_s"]),
    op("D_vn#2", "D_vn += np_b P_n,b", B, &["D_vn"]),
    op("D_vn#3", "D_vn += np_c P_n,c", B, &["D_vn#2"]),
    op("D_ph,a", "D_ph,a = -c P_ph,a", B, &["load candidate, f_s"]),
    op("D_ph,b", "D_ph,b = -c P_ph,b", B, &["load candidate, f_s"]),
    op("D_ph,c", "D_ph,c = -c P_ph,c", B, &["load candidate, f_s"]),
    op(
        "Algorithm 2 x7",
        "Algorithm 2 x7 (J_dl terms in cycle 1)",
        Lanes,
        &["D_a", "D_b", "D_c", "D_vn#3", "D_ph,a", "D_ph,b", "D_ph,c"],
    ),
    op(
        "min l_j, max J_dl",
        "min l_j, max J_dl",
        Tree(3),
        &["Algorithm 2 x7"],
    ),
    op(
        "recip ROM [L*]",
        "recip ROM [L*]",
        Reg,
        &["min l_j, max J_dl"],
    ),
    op("J_sw", "J_sw = f_s recip", B, &["recip ROM [L*]"]),
    op(
        "e_vn",
        "e_vn = e_vn0 + L* D_vn / L",
        B,
        &["min l_j, max J_dl"],
    ),
    op("sq", "sq = e_vn^2", B, &["e_vn"]),
    op("J", "J = lambda sq + J_sw", B, &["sq", "J_sw"]),
    op("return result", "return result", Reg, &["J"]), // 25
];

/// One explorer evaluation of our default core ([`super::mpdcc_fixed::Structure::CORE`]):
/// four interpolation nodes, capacitor drift, stator damping, exact first step.
pub const EXPLORER_OPS: &[Op] = &[
    op("load candidate, f_s", "load candidate, f_s", Reg, &[]),
    op("D_vn", "D_vn = np_a P_n,a", B, &["load candidate, f_s"]),
    op("D_vn#2", "D_vn += np_b P_n,b", B, &["D_vn"]),
    op("D_vn#3", "D_vn += np_c P_n,c", B, &["D_vn#2"]),
    op("D_ph,a", "D_ph,a = -c P_ph,a", B, &["load candidate, f_s"]),
    op("D_ph,b", "D_ph,b = -c P_ph,b", B, &["load candidate, f_s"]),
    op("D_ph,c", "D_ph,c = -c P_ph,c", B, &["load candidate, f_s"]),
    op(
        "v_a",
        "v_a = ph v_ph,a + mux(rail Vdc/2 | v_n)",
        B,
        &["load candidate, f_s"],
    ),
    op(
        "v_b",
        "v_b = ph v_ph,b + mux(rail Vdc/2 | v_n)",
        B,
        &["load candidate, f_s"],
    ),
    op(
        "v_c",
        "v_c = ph v_ph,c + mux(rail Vdc/2 | v_n)",
        B,
        &["load candidate, f_s"],
    ),
    op("sum", "sum = v_a + v_b", B, &["v_a", "v_b"]),
    op("sum#2", "sum += v_c", B, &["sum", "v_c"]),
    op("u0_a", "u0_a = 3 v_a - sum", B, &["v_a", "sum#2"]),
    op("u0_b", "u0_b = 3 v_b - sum", B, &["v_b", "sum#2"]),
    op("u0_c", "u0_c = 3 v_c - sum", B, &["v_c", "sum#2"]),
    op(
        "vh_a",
        "vh_a = -(n D_vn + ph D_ph,a) / 2 (capacitor drift)",
        B,
        &["D_vn#3", "D_ph,a"],
    ),
    op("vh_b", "vh_b", B, &["D_vn#3", "D_ph,b"]),
    op("vh_c", "vh_c", B, &["D_vn#3", "D_ph,c"]),
    op("sum_h", "sum_h = vh_a + vh_b", B, &["vh_a", "vh_b"]),
    op("sum_h#2", "sum_h += vh_c", B, &["sum_h", "vh_c"]),
    op("uh_a", "uh_a = 3 vh_a - sum_h", B, &["vh_a", "sum_h#2"]),
    op("uh_b", "uh_b", B, &["vh_b", "sum_h#2"]),
    op("uh_c", "uh_c", B, &["vh_c", "sum_h#2"]),
    op("P0_a", "P0_a = g3 u0_a", B, &["u0_a"]),
    op("P0_b", "P0_b = g3 u0_b", B, &["u0_b"]),
    op("P0_c", "P0_c = g3 u0_c", B, &["u0_c"]),
    op("Q_a", "Q_a = -gd u0_a", B, &["u0_a"]),
    op("Q_b", "Q_b = -gd u0_b", B, &["u0_b"]),
    op("Q_c", "Q_c = -gd u0_c", B, &["u0_c"]),
    op("Q_a#2", "Q_a += g3 uh_a", B, &["Q_a", "uh_a"]),
    op("Q_b#2", "Q_b += g3 uh_b", B, &["Q_b", "uh_b"]),
    op("Q_c#2", "Q_c += g3 uh_c", B, &["Q_c", "uh_c"]),
    op(
        "t1L_a",
        "t = 1 P0_a + 1 Q_a (node 1L)",
        B,
        &["P0_a", "Q_a#2"],
    ),
    op("D1_a", "D1_a = dn1_a - t", B, &["t1L_a"]),
    op(
        "t2L_a",
        "t = 2 P0_a + 4 Q_a (node 2L)",
        B,
        &["P0_a", "Q_a#2"],
    ),
    op("D2_a", "D2_a = dn2_a - t", B, &["t2L_a"]),
    op(
        "t4L_a",
        "t = 4 P0_a + 16 Q_a (node 4L)",
        B,
        &["P0_a", "Q_a#2"],
    ),
    op("D4_a", "D4_a = dn4_a - t", B, &["t4L_a"]),
    op(
        "t8L_a",
        "t = 8 P0_a + 64 Q_a (node 8L)",
        B,
        &["P0_a", "Q_a#2"],
    ),
    op("D8_a", "D8_a = dn8_a - t", B, &["t8L_a"]),
    op(
        "t1L_b",
        "t = 1 P0_b + 1 Q_b (node 1L)",
        B,
        &["P0_b", "Q_b#2"],
    ),
    op("D1_b", "D1_b = dn1_b - t", B, &["t1L_b"]),
    op(
        "t2L_b",
        "t = 2 P0_b + 4 Q_b (node 2L)",
        B,
        &["P0_b", "Q_b#2"],
    ),
    op("D2_b", "D2_b = dn2_b - t", B, &["t2L_b"]),
    op(
        "t4L_b",
        "t = 4 P0_b + 16 Q_b (node 4L)",
        B,
        &["P0_b", "Q_b#2"],
    ),
    op("D4_b", "D4_b = dn4_b - t", B, &["t4L_b"]),
    op(
        "t8L_b",
        "t = 8 P0_b + 64 Q_b (node 8L)",
        B,
        &["P0_b", "Q_b#2"],
    ),
    op("D8_b", "D8_b = dn8_b - t", B, &["t8L_b"]),
    op(
        "t1L_c",
        "t = 1 P0_c + 1 Q_c (node 1L)",
        B,
        &["P0_c", "Q_c#2"],
    ),
    op("D1_c", "D1_c = dn1_c - t", B, &["t1L_c"]),
    op(
        "t2L_c",
        "t = 2 P0_c + 4 Q_c (node 2L)",
        B,
        &["P0_c", "Q_c#2"],
    ),
    op("D2_c", "D2_c = dn2_c - t", B, &["t2L_c"]),
    op(
        "t4L_c",
        "t = 4 P0_c + 16 Q_c (node 4L)",
        B,
        &["P0_c", "Q_c#2"],
    ),
    op("D4_c", "D4_c = dn4_c - t", B, &["t4L_c"]),
    op(
        "t8L_c",
        "t = 8 P0_c + 64 Q_c (node 8L)",
        B,
        &["P0_c", "Q_c#2"],
    ),
    op("D8_c", "D8_c = dn8_c - t", B, &["t8L_c"]),
    op(
        "D1step_a",
        "D1_a = dn1_a - g3_1 (u0_a + uh_a/L) (first step)",
        B,
        &["u0_a", "uh_a"],
    ),
    op("D1step_b", "D1_b", B, &["u0_b", "uh_b"]),
    op("D1step_c", "D1_c", B, &["u0_c", "uh_c"]),
    op(
        "Algorithm 2 x7, up to 4 pieces each",
        "Algorithm 2 x7, up to 4 pieces each (J_dl terms in cycle 1)",
        Lanes,
        &[
            "D1_a", "D1_b", "D1_c", "D2_a", "D2_b", "D2_c", "D4_a", "D4_b", "D4_c", "D8_a", "D8_b",
            "D8_c", "D_vn#3", "D_ph,a", "D_ph,b", "D_ph,c", "D1step_a", "D1step_b", "D1step_c",
        ],
    ),
    op(
        "min l_j, max J_dl",
        "min l_j, max J_dl",
        Tree(3),
        &["Algorithm 2 x7, up to 4 pieces each"],
    ),
    op(
        "recip ROM [L*]",
        "recip ROM [L*]",
        Reg,
        &["min l_j, max J_dl"],
    ),
    op("J_sw", "J_sw = f_s recip", B, &["recip ROM [L*]"]),
    op(
        "e_vn",
        "e_vn = e_vn0 + interpolated D_vn at L*",
        B,
        &["min l_j, max J_dl"],
    ),
    op("sq", "sq = e_vn^2", B, &["e_vn"]),
    op("J", "J = lambda sq + J_sw", B, &["sq", "J_sw"]),
    op("return result", "return result", Reg, &["J"]), // 66
];

/// The scheduler before dispatch ([`super::mpdcc_fixed::common_terms`] and
/// [`super::mpdcc_fixed::lazy_ok`]) of our default core (all accuracy options, four
/// nodes), worst case (the lazy check fails). [`SCHEDULER_OPS_PAPER`] is the
/// paper's structure.
pub const SCHEDULER_OPS: &[Op] = &[
    op("sample state registers", "sample state registers", Reg, &[]),
    op("kw", "kw = c_w omega_r", B, &["sample state registers"]),
    op("w2", "w2 = omega_r^2", B, &["sample state registers"]),
    op("ks", "ks = c_s omega_s", B, &["sample state registers"]),
    op("s2", "s2 = omega_s^2", B, &["sample state registers"]),
    op("kp", "kp = c_p w2", B, &["w2"]),
    op("k2", "k2 = ks^2 / 2 (2nd-order rotation)", B, &["ks"]),
    op("tr", "tr = c_3 w2 (3rd order)", B, &["w2"]),
    op("ts", "ts = c_3 s2 (3rd order)", B, &["s2"]),
    op("kw3", "kw3 = kw tr", B, &["kw", "tr"]),
    op("ks3", "ks3 = ks ts", B, &["ks", "ts"]),
    op(
        "nat_a",
        "nat_a = -c_tau i_a",
        B,
        &["sample state registers"],
    ),
    op("nat_a#2", "nat_a += c_r psi_a", B, &["nat_a"]),
    op("nat_a#3", "nat_a += kw psi_b", B, &["kw", "nat_a#2"]),
    op("rate_a", "rate_a = -ks i*_b - nat_a", B, &["ks", "nat_a#3"]),
    op(
        "nat_b",
        "nat_b = -c_tau i_b",
        B,
        &["sample state registers"],
    ),
    op("nat_b#2", "nat_b += c_r psi_b", B, &["nat_b"]),
    op("nat_b#3", "nat_b -= kw psi_a", B, &["kw", "nat_b#2"]),
    op("rate_b", "rate_b = ks i*_a - nat_b", B, &["ks", "nat_b#3"]),
    op(
        "dmp_a",
        "dmp_a = c_d nat_a (stator damping)",
        B,
        &["nat_a#3"],
    ),
    op("dmp_b", "dmp_b = c_d nat_b", B, &["nat_b#3"]),
    op(
        "kw1",
        "kw1 = c_w1 omega_r (one-step products)",
        B,
        &["sample state registers"],
    ),
    op("ks1", "ks1 = c_s1 omega_s", B, &["sample state registers"]),
    op(
        "nat1_a",
        "nat1_a = -c_tau1 i_a",
        B,
        &["sample state registers"],
    ),
    op("nat1_a#2", "nat1_a += c_r1 psi_a", B, &["nat1_a"]),
    op("nat1_a#3", "nat1_a += kw1 psi_b", B, &["kw1", "nat1_a#2"]),
    op(
        "rate1_a",
        "rate1_a = -ks1 i*_b - nat1_a",
        B,
        &["ks1", "nat1_a#3"],
    ),
    op(
        "nat1_b",
        "nat1_b = -c_tau1 i_b",
        B,
        &["sample state registers"],
    ),
    op("nat1_b#2", "nat1_b += c_r1 psi_b", B, &["nat1_b"]),
    op("nat1_b#3", "nat1_b -= kw1 psi_a", B, &["kw1", "nat1_b#2"]),
    op(
        "rate1_b",
        "rate1_b = ks1 i*_a - nat1_b",
        B,
        &["ks1", "nat1_b#3"],
    ),
    op("cor_a", "cor_a = kp psi_a", B, &["kp"]),
    op("cor_a#2", "cor_a += k2 i*_a", B, &["k2", "cor_a"]),
    op("cor_b", "cor_b = kp psi_b", B, &["kp"]),
    op("cor_b#2", "cor_b += k2 i*_b", B, &["k2", "cor_b"]),
    op("cub_a", "cub_a = ks3 i*_b", B, &["ks3"]),
    op("cub_a#2", "cub_a += kw3 psi_b", B, &["kw3", "cub_a"]),
    op("cub_b", "cub_b = -ks3 i*_a", B, &["ks3"]),
    op("cub_b#2", "cub_b -= kw3 psi_a", B, &["kw3", "cub_b"]),
    op(
        "dl_a",
        "dl_a = rate_a + dmp_a - cor_a + cub_a (node L)",
        B,
        &["rate_a", "dmp_a", "cor_a#2", "cub_a#2"],
    ),
    op(
        "dl_b",
        "dl_b = rate_b + dmp_b - cor_b + cub_b",
        B,
        &["rate_b", "dmp_b", "cor_b#2", "cub_b#2"],
    ),
    op(
        "d1_a",
        "d1_a = rate1_a - cor_a / L^2 + cub_a / L^3 (one step)",
        B,
        &["rate1_a", "cor_a#2", "cub_a#2"],
    ),
    op(
        "d1_b",
        "d1_b = rate1_b - cor_b / L^2 + cub_b / L^3",
        B,
        &["rate1_b", "cor_b#2", "cub_b#2"],
    ),
    op("s3h dl_b", "s3h dl_b", B, &["dl_b"]),
    op("s3h d1_b", "s3h d1_b", B, &["d1_b"]),
    op("dn_l,b", "dn_l,b", B, &["dl_a", "s3h dl_b"]),
    op("dn_l,c", "dn_l,c", B, &["dl_a", "s3h dl_b"]),
    op("dn_1,b", "dn_1,b", B, &["d1_a", "s3h d1_b"]),
    op("dn_1,c", "dn_1,c", B, &["d1_a", "s3h d1_b"]),
    op(
        "dn_2L,a",
        "dn_2L,a = 2 rate_a + 4 (dmp_a - cor_a) + 8 cub_a",
        B,
        &["rate_a", "dmp_a", "cor_a#2", "cub_a#2"],
    ),
    op(
        "dl_2L,b",
        "dl_2L,b = 2 rate_b + 4 (dmp_b - cor_b) + 8 cub_b",
        B,
        &["rate_b", "dmp_b", "cor_b#2", "cub_b#2"],
    ),
    op("s3h dl_2L,b", "s3h dl_2L,b", B, &["dl_2L,b"]),
    op("dn_2L,b", "dn_2L,b", B, &["dn_2L,a", "s3h dl_2L,b"]),
    op("dn_2L,c", "dn_2L,c", B, &["dn_2L,a", "s3h dl_2L,b"]),
    op(
        "dn_4L,a",
        "dn_4L,a = 4 rate_a + 16 (dmp_a - cor_a) + 64 cub_a",
        B,
        &["rate_a", "dmp_a", "cor_a#2", "cub_a#2"],
    ),
    op(
        "dl_4L,b",
        "dl_4L,b = 4 rate_b + 16 (dmp_b - cor_b) + 64 cub_b",
        B,
        &["rate_b", "dmp_b", "cor_b#2", "cub_b#2"],
    ),
    op("s3h dl_4L,b", "s3h dl_4L,b", B, &["dl_4L,b"]),
    op("dn_4L,b", "dn_4L,b", B, &["dn_4L,a", "s3h dl_4L,b"]),
    op("dn_4L,c", "dn_4L,c", B, &["dn_4L,a", "s3h dl_4L,b"]),
    op(
        "dn_8L,a",
        "dn_8L,a = 8 rate_a + 64 (dmp_a - cor_a) + 512 cub_a",
        B,
        &["rate_a", "dmp_a", "cor_a#2", "cub_a#2"],
    ),
    op(
        "dl_8L,b",
        "dl_8L,b = 8 rate_b + 64 (dmp_b - cor_b) + 512 cub_b",
        B,
        &["rate_b", "dmp_b", "cor_b#2", "cub_b#2"],
    ),
    op("s3h dl_8L,b", "s3h dl_8L,b", B, &["dl_8L,b"]),
    op("dn_8L,b", "dn_8L,b", B, &["dn_8L,a", "s3h dl_8L,b"]),
    op("dn_8L,c", "dn_8L,c", B, &["dn_8L,a", "s3h dl_8L,b"]),
    op("s3h i_b", "s3h i_b", B, &["sample state registers"]),
    op("i_b", "i_b", B, &["s3h i_b"]),
    op("i_c", "i_c", B, &["s3h i_b"]),
    op("e_a", "e_a = i*_a - i_a", B, &["sample state registers"]),
    op("e_b'", "e_b' = i*_b - i_b", B, &["sample state registers"]),
    op("s3h e_b'", "s3h e_b'", B, &["e_b'"]),
    op("e_b", "e_b", B, &["e_a", "s3h e_b'"]),
    op("e_c", "e_c", B, &["e_a", "s3h e_b'"]),
    op("e_vn", "e_vn = -v_n", B, &["sample state registers"]),
    op("e_ph,a", "e_ph,a", B, &["sample state registers"]),
    op("e_ph,b", "e_ph,b", B, &["sample state registers"]),
    op("e_ph,c", "e_ph,c", B, &["sample state registers"]),
    op("P_n,a", "P_n,a = c_n i_a", B, &["sample state registers"]),
    op("P_n,b", "P_n,b", B, &["i_b"]),
    op("P_n,c", "P_n,c", B, &["i_c"]),
    op(
        "P_ph,a",
        "P_ph,a = c_ph i_a",
        B,
        &["sample state registers"],
    ),
    op("P_ph,b", "P_ph,b", B, &["i_b"]),
    op("P_ph,c", "P_ph,c", B, &["i_c"]),
    op(
        "v_a(s_prev)",
        "v_a(s_prev) = ph v_ph,a + mux(rail Vdc/2 | v_n)",
        B,
        &["sample state registers"],
    ),
    op(
        "v_b(s_prev)",
        "v_b(s_prev) = ph v_ph,b + mux(rail Vdc/2 | v_n)",
        B,
        &["sample state registers"],
    ),
    op(
        "v_c(s_prev)",
        "v_c(s_prev) = ph v_ph,c + mux(rail Vdc/2 | v_n)",
        B,
        &["sample state registers"],
    ),
    op(
        "v_a(s_prev)#2",
        "v_a(s_prev) += (n D_vn + ph D_ph,a) / (2L) (capacitor drift)",
        B,
        &["P_n,a", "P_n,b", "P_n,c", "P_ph,a", "v_a(s_prev)"],
    ),
    op(
        "v_b(s_prev)#2",
        "v_b(s_prev) += drift",
        B,
        &["P_n,a", "P_n,b", "P_n,c", "P_ph,b", "v_b(s_prev)"],
    ),
    op(
        "v_c(s_prev)#2",
        "v_c(s_prev) += drift",
        B,
        &["P_n,a", "P_n,b", "P_n,c", "P_ph,c", "v_c(s_prev)"],
    ),
    op(
        "sum",
        "sum = v_a + v_b",
        B,
        &["v_a(s_prev)#2", "v_b(s_prev)#2"],
    ),
    op("sum#2", "sum += v_c", B, &["v_c(s_prev)#2", "sum"]),
    op("u_a", "u_a = 3 v_a - sum", B, &["v_a(s_prev)#2", "sum#2"]),
    op("u_b", "u_b", B, &["v_b(s_prev)#2", "sum#2"]),
    op("u_c", "u_c", B, &["v_c(s_prev)#2", "sum#2"]),
    op(
        "e1_a",
        "e1_a = e_a + dn_1,a - g3 u_a / L",
        B,
        &["d1_a", "e_a", "u_a"],
    ),
    op("e1_b", "e1_b", B, &["dn_1,b", "e_b", "u_b"]),
    op("e1_c", "e1_c", B, &["dn_1,c", "e_c", "u_c"]),
    op(
        "e1_vn",
        "e1_vn = e_vn + np_a P_n,a / L",
        B,
        &["e_vn", "P_n,a"],
    ),
    op("e1_vn#2", "e1_vn += np_b P_n,b / L", B, &["P_n,b", "e1_vn"]),
    op(
        "e1_vn#3",
        "e1_vn += np_c P_n,c / L",
        B,
        &["P_n,c", "e1_vn#2"],
    ),
    op(
        "e1_ph,a",
        "e1_ph,a = e_ph,a - c P_ph,a / L",
        B,
        &["e_ph,a", "P_ph,a"],
    ),
    op("e1_ph,b", "e1_ph,b", B, &["e_ph,b", "P_ph,b"]),
    op("e1_ph,c", "e1_ph,c", B, &["e_ph,c", "P_ph,c"]),
    op(
        "7 bound compares, AND (lazy check); all nodes ready",
        "7 bound compares, AND (lazy check); all nodes ready",
        Reg,
        &[
            "dn_l,b", "dn_l,c", "dn_2L,a", "dn_2L,b", "dn_2L,c", "dn_4L,a", "dn_4L,b", "dn_4L,c",
            "dn_8L,a", "dn_8L,b", "dn_8L,c", "e1_a", "e1_b", "e1_c", "e1_vn#3", "e1_ph,a",
            "e1_ph,b", "e1_ph,c",
        ],
    ), // 102
];

/// The scheduler before dispatch with the paper's structure
/// (`Structure::PAPER`: first-order rotations plus the `p`
/// correction, one node, no stator damping, no capacitor drift), worst case;
/// [`SCHEDULER_OPS`] without the operations of the accuracy options.
pub const SCHEDULER_OPS_PAPER: &[Op] = &[
    op("sample state registers", "sample state registers", Reg, &[]),
    op("kw", "kw = c_w omega_r", B, &["sample state registers"]),
    op("w2", "w2 = omega_r^2", B, &["sample state registers"]),
    op("ks", "ks = c_s omega_s", B, &["sample state registers"]),
    op("kp", "kp = c_p w2", B, &["w2"]),
    op(
        "nat_a",
        "nat_a = -c_tau i_a",
        B,
        &["sample state registers"],
    ),
    op("nat_a#2", "nat_a += c_r psi_a", B, &["nat_a"]),
    op("nat_a#3", "nat_a += kw psi_b", B, &["kw", "nat_a#2"]),
    op("rate_a", "rate_a = -ks i*_b - nat_a", B, &["ks", "nat_a#3"]),
    op(
        "nat_b",
        "nat_b = -c_tau i_b",
        B,
        &["sample state registers"],
    ),
    op("nat_b#2", "nat_b += c_r psi_b", B, &["nat_b"]),
    op("nat_b#3", "nat_b -= kw psi_a", B, &["kw", "nat_b#2"]),
    op("rate_b", "rate_b = ks i*_a - nat_b", B, &["ks", "nat_b#3"]),
    op(
        "kw1",
        "kw1 = c_w1 omega_r (one-step products)",
        B,
        &["sample state registers"],
    ),
    op("ks1", "ks1 = c_s1 omega_s", B, &["sample state registers"]),
    op(
        "nat1_a",
        "nat1_a = -c_tau1 i_a",
        B,
        &["sample state registers"],
    ),
    op("nat1_a#2", "nat1_a += c_r1 psi_a", B, &["nat1_a"]),
    op("nat1_a#3", "nat1_a += kw1 psi_b", B, &["kw1", "nat1_a#2"]),
    op(
        "rate1_a",
        "rate1_a = -ks1 i*_b - nat1_a",
        B,
        &["ks1", "nat1_a#3"],
    ),
    op(
        "nat1_b",
        "nat1_b = -c_tau1 i_b",
        B,
        &["sample state registers"],
    ),
    op("nat1_b#2", "nat1_b += c_r1 psi_b", B, &["nat1_b"]),
    op("nat1_b#3", "nat1_b -= kw1 psi_a", B, &["kw1", "nat1_b#2"]),
    op(
        "rate1_b",
        "rate1_b = ks1 i*_a - nat1_b",
        B,
        &["ks1", "nat1_b#3"],
    ),
    op("cor_a", "cor_a = kp psi_a", B, &["kp"]),
    op("cor_b", "cor_b = kp psi_b", B, &["kp"]),
    op(
        "dl_a",
        "dl_a = rate_a - cor_a (node L)",
        B,
        &[
            "sample state registers",
            "kw",
            "w2",
            "ks",
            "nat_a#3",
            "rate_a",
            "cor_a",
        ],
    ),
    op(
        "dl_b",
        "dl_b = rate_b - cor_b",
        B,
        &[
            "sample state registers",
            "kw",
            "w2",
            "ks",
            "nat_b#3",
            "rate_b",
            "cor_b",
        ],
    ),
    op(
        "d1_a",
        "d1_a = rate1_a - cor_a / L^2 (one step)",
        B,
        &[
            "sample state registers",
            "kw",
            "w2",
            "ks",
            "rate1_a",
            "cor_a",
        ],
    ),
    op(
        "d1_b",
        "d1_b = rate1_b - cor_b / L^2",
        B,
        &[
            "sample state registers",
            "kw",
            "w2",
            "ks",
            "rate1_b",
            "cor_b",
        ],
    ),
    op("s3h dl_b", "s3h dl_b", B, &["dl_b"]),
    op("s3h d1_b", "s3h d1_b", B, &["d1_b"]),
    op("dn_l,b", "dn_l,b", B, &["dl_a", "s3h dl_b"]),
    op("dn_l,c", "dn_l,c", B, &["dl_a", "s3h dl_b"]),
    op("dn_1,b", "dn_1,b", B, &["d1_a", "s3h d1_b"]),
    op("dn_1,c", "dn_1,c", B, &["d1_a", "s3h d1_b"]),
    op("s3h i_b", "s3h i_b", B, &["sample state registers"]),
    op("i_b", "i_b", B, &["s3h i_b"]),
    op("i_c", "i_c", B, &["s3h i_b"]),
    op("e_a", "e_a = i*_a - i_a", B, &["sample state registers"]),
    op("e_b'", "e_b' = i*_b - i_b", B, &["sample state registers"]),
    op("s3h e_b'", "s3h e_b'", B, &["e_b'"]),
    op("e_b", "e_b", B, &["e_a", "s3h e_b'"]),
    op("e_c", "e_c", B, &["e_a", "s3h e_b'"]),
    op("e_vn", "e_vn = -v_n", B, &["sample state registers"]),
    op("e_ph,a", "e_ph,a", B, &["sample state registers"]),
    op("e_ph,b", "e_ph,b", B, &["sample state registers"]),
    op("e_ph,c", "e_ph,c", B, &["sample state registers"]),
    op("P_n,a", "P_n,a = c_n i_a", B, &["sample state registers"]),
    op("P_n,b", "P_n,b", B, &["i_b"]),
    op("P_n,c", "P_n,c", B, &["i_c"]),
    op(
        "P_ph,a",
        "P_ph,a = c_ph i_a",
        B,
        &["sample state registers"],
    ),
    op("P_ph,b", "P_ph,b", B, &["i_b"]),
    op("P_ph,c", "P_ph,c", B, &["i_c"]),
    op(
        "v_a(s_prev)",
        "v_a(s_prev) = ph v_ph,a + mux(rail Vdc/2 | v_n)",
        B,
        &["sample state registers"],
    ),
    op(
        "v_b(s_prev)",
        "v_b(s_prev) = ph v_ph,b + mux(rail Vdc/2 | v_n)",
        B,
        &["sample state registers"],
    ),
    op(
        "v_c(s_prev)",
        "v_c(s_prev) = ph v_ph,c + mux(rail Vdc/2 | v_n)",
        B,
        &["sample state registers"],
    ),
    op(
        "sum",
        "sum = v_a + v_b",
        B,
        &[
            "P_n,a",
            "P_n,b",
            "P_n,c",
            "P_ph,a",
            "P_ph,b",
            "v_a(s_prev)",
            "v_b(s_prev)",
        ],
    ),
    op(
        "sum#2",
        "sum += v_c",
        B,
        &["P_n,a", "P_n,b", "P_n,c", "P_ph,c", "v_c(s_prev)", "sum"],
    ),
    op(
        "u_a",
        "u_a = 3 v_a - sum",
        B,
        &["P_n,a", "P_n,b", "P_n,c", "P_ph,a", "v_a(s_prev)", "sum#2"],
    ),
    op(
        "u_b",
        "u_b",
        B,
        &["P_n,a", "P_n,b", "P_n,c", "P_ph,b", "v_b(s_prev)", "sum#2"],
    ),
    op(
        "u_c",
        "u_c",
        B,
        &["P_n,a", "P_n,b", "P_n,c", "P_ph,c", "v_c(s_prev)", "sum#2"],
    ),
    op(
        "e1_a",
        "e1_a = e_a + dn_1,a - g3 u_a / L",
        B,
        &["d1_a", "e_a", "u_a"],
    ),
    op("e1_b", "e1_b", B, &["dn_1,b", "e_b", "u_b"]),
    op("e1_c", "e1_c", B, &["dn_1,c", "e_c", "u_c"]),
    op(
        "e1_vn",
        "e1_vn = e_vn + np_a P_n,a / L",
        B,
        &["e_vn", "P_n,a"],
    ),
    op("e1_vn#2", "e1_vn += np_b P_n,b / L", B, &["P_n,b", "e1_vn"]),
    op(
        "e1_vn#3",
        "e1_vn += np_c P_n,c / L",
        B,
        &["P_n,c", "e1_vn#2"],
    ),
    op(
        "e1_ph,a",
        "e1_ph,a = e_ph,a - c P_ph,a / L",
        B,
        &["e_ph,a", "P_ph,a"],
    ),
    op("e1_ph,b", "e1_ph,b", B, &["e_ph,b", "P_ph,b"]),
    op("e1_ph,c", "e1_ph,c", B, &["e_ph,c", "P_ph,c"]),
    op(
        "7 bound compares, AND",
        "7 bound compares, AND (lazy check)",
        Reg,
        &[
            "sample state registers",
            "kw",
            "w2",
            "ks",
            "nat_a#3",
            "rate_a",
            "nat_b#3",
            "rate_b",
            "cor_a",
            "cor_b",
            "dn_l,b",
            "dn_l,c",
            "e1_a",
            "e1_b",
            "e1_c",
            "e1_vn#3",
            "e1_ph,a",
            "e1_ph,b",
            "e1_ph,c",
        ],
    ), // 70
];

/// Hardware parameters of the cycle model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CycleModel {
    /// Computational blocks per explorer.
    pub explorer_blocks: u32,
    /// Computational blocks in the scheduler.
    pub scheduler_blocks: u32,
    /// Pipeline depth of a block (Fig. 3: 3 stages).
    pub block_latency: u32,
    /// The explorer's program ([`EXPLORER_OPS`] or [`EXPLORER_OPS_PAPER`]).
    pub explorer: &'static [Op],
    /// The scheduler's pre-phase ([`SCHEDULER_OPS`] or [`SCHEDULER_OPS_PAPER`]).
    pub scheduler: &'static [Op],
}

impl Default for CycleModel {
    fn default() -> Self {
        Self {
            explorer_blocks: 4,
            scheduler_blocks: 4,
            block_latency: 3,
            explorer: EXPLORER_OPS,
            scheduler: SCHEDULER_OPS,
        }
    }
}

impl CycleModel {
    /// The explorer and scheduler with the paper's structure (one chord, no
    /// options).
    pub fn paper() -> Self {
        Self {
            explorer: EXPLORER_OPS_PAPER,
            scheduler: SCHEDULER_OPS_PAPER,
            ..Self::default()
        }
    }
}

/// Worst-case cycles of one search lane: `M + 1` for the single chord; for
/// `K` nodes (as many as fit below `N_bar`) the sum over the pieces of
/// `bits(cap) + 1`, pieces of `L`, `L`, `2L`, ... and the last one up to
/// `N_bar`.
pub fn worst_lane_cycles(nodes: u32, lambda: u32, m_bits: u32) -> u32 {
    let n_bar = 1u32 << m_bits;
    let big_l = 1u32 << lambda;
    let mut k = nodes.max(1);
    while k > 1 && (big_l << (k - 1)) > n_bar {
        k -= 1;
    }
    if k == 1 {
        return m_bits + 1;
    }
    let bits = |n: u32| (32 - (n.max(2) - 1).leading_zeros()).max(1);
    let mut total = 0;
    for i in 0..k {
        let (start, len) = if i == 0 {
            (0, big_l)
        } else {
            (big_l << (i - 1), big_l << (i - 1))
        };
        let cap = if i + 1 == k { n_bar - start } else { len };
        total += bits(cap) + 1;
    }
    total
}

/// Per-phase breakdown of one worst-case decision.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "std", derive(serde::Serialize))]
pub struct Breakdown {
    /// Scheduler before the first dispatch (sample, common terms, lazy check), cycles.
    pub pre: u32,
    /// One explorer evaluation, cycles.
    pub per_candidate: u32,
    /// Candidates evaluated.
    pub candidates: u32,
    /// Explorers.
    pub explorers: u32,
    /// Total, cycles.
    pub total: u32,
}

impl CycleModel {
    /// Makespan of a program with the given lane duration, on `blocks` blocks.
    pub fn makespan(&self, ops: &[Op], blocks: u32, lane_cycles: u32) -> u32 {
        // Issue slots used per cycle; programs are short (< 100 ops, < 200 cycles).
        // Dependencies resolve by handle; [`check_program`] holds for every
        // program here (tested), so an unresolved one cannot occur.
        let mut used = [0u32; 512];
        let mut fin = [0u32; MAX_OPS];
        let mut end = 0;
        for (i, o) in ops.iter().enumerate().take(fin.len()) {
            let ready = o
                .deps
                .iter()
                .filter_map(|d| find(ops, i, d))
                .map(|d| fin[d])
                .max()
                .unwrap_or(0);
            let (start, lat) = match o.kind {
                Kind::Block => {
                    let mut t = ready as usize;
                    while t + 1 < used.len() && used[t] >= blocks.max(1) {
                        t += 1;
                    }
                    used[t] += 1;
                    (t as u32, self.block_latency)
                }
                Kind::Lanes => (ready, lane_cycles),
                Kind::Tree(d) => (ready, d),
                Kind::Reg => (ready, 1),
            };
            fin[i] = start + lat;
            end = end.max(fin[i]);
        }
        end
    }

    /// Cycles of one explorer evaluation whose slowest lane took `lane_cycles`.
    pub fn candidate_cycles(&self, lane_cycles: u32) -> u32 {
        self.makespan(self.explorer, self.explorer_blocks, lane_cycles)
    }

    /// Cycles of the scheduler's pre-phase (common terms and lazy check).
    pub fn pre_cycles(&self) -> u32 {
        self.makespan(self.scheduler, self.scheduler_blocks, 0)
    }

    /// A decision that keeps `s(k-1)`: pre-phase plus the output register.
    pub fn kept_cycles(&self) -> u32 {
        self.pre_cycles() + 1
    }

    /// A decision with a search: dispatch one candidate per cycle to the
    /// explorer that is free first, compare as results arrive, register the
    /// output. `lanes[i]` = slowest lane of candidate `i`.
    pub fn search_cycles(&self, n: u32, lanes: &[u32]) -> u32 {
        let n = n.clamp(1, 64) as usize;
        let pre = self.pre_cycles() + 1; // + candidate generator start
        let mut free = [pre; 64];
        let mut next_dispatch = pre;
        let mut last = pre;
        // Lane durations take few values: one makespan per distinct value.
        let mut memo: [(u32, u32); 16] = [(u32::MAX, 0); 16];
        let mut per_candidate = |lc: u32| -> u32 {
            if let Some(&(_, c)) = memo.iter().find(|m| m.0 == lc) {
                return c;
            }
            let c = self.candidate_cycles(lc);
            if let Some(m) = memo.iter_mut().find(|m| m.0 == u32::MAX) {
                *m = (lc, c);
            }
            c
        };
        for &lc in lanes {
            // Explorer free first (lowest index on ties).
            let (e, &t_free) = free[..n]
                .iter()
                .enumerate()
                .min_by_key(|&(i, &t)| (t, i))
                .unwrap_or((0, &pre));
            let start = t_free.max(next_dispatch);
            next_dispatch = start + 1;
            free[e] = start + per_candidate(lc);
            last = last.max(free[e]);
        }
        last + 1 + 1 // last compare, output register
    }

    /// Worst case for `n` explorers and `candidates` candidates, every lane
    /// taking `lane_worst` cycles ([`worst_lane_cycles`], no early exit).
    pub fn worst_case(&self, n: u32, candidates: u32, lane_worst: u32) -> Breakdown {
        let lanes = [lane_worst; super::controller::MAX_CANDIDATES];
        let c = (candidates as usize).min(lanes.len());
        Breakdown {
            pre: self.pre_cycles() + 1,
            per_candidate: self.candidate_cycles(lane_worst),
            candidates: c as u32,
            explorers: n,
            total: self.search_cycles(n, &lanes[..c]),
        }
    }

    /// Initiation interval of a pipelined explorer (a what-if, not the
    /// paper's FSM design): a new candidate every `II` cycles, limited by
    /// the block issue slots (`ceil(block ops / blocks)`) and by the search
    /// lanes (busy `lane_worst` cycles per candidate unless duplicated).
    pub fn pipelined_ii(&self, lane_worst: u32) -> u32 {
        let ops = self
            .explorer
            .iter()
            .filter(|o| o.kind == Kind::Block)
            .count() as u32;
        ops.div_ceil(self.explorer_blocks.max(1))
            .max(lane_worst)
            .max(1)
    }

    /// Worst case with pipelined explorers: each explorer takes
    /// `ceil(|S|/n)` candidates, one every [`Self::pipelined_ii`] cycles,
    /// the last one finishing one latency after it starts.
    pub fn pipelined_worst_case(&self, n: u32, candidates: u32, lane_worst: u32) -> u32 {
        let per = candidates.div_ceil(n.max(1));
        let lat = self.candidate_cycles(lane_worst);
        let ii = self.pipelined_ii(lane_worst);
        self.pre_cycles() + 1 + (n.max(1) - 1) + per.saturating_sub(1) * ii + lat + 2
    }
}

/// Latency of the pipelined explorer `mpdcc_explorer` (Verilog), cycles
/// from a candidate's strobe to its result (one candidate per clock).
pub const PIPELINED_EXPLORER_LATENCY: u32 = 41;

/// Shared 16 x 16 multipliers (DSP48E1) of the common terms `mpdcc_common`
/// (Verilog parameter `MULS` of `mpdcc_core`).
pub const PIPELINED_COMMON_MULTIPLIERS: u32 = 4;

/// Products of the common terms per group of `mpdcc_common`'s schedule: a
/// group needs only values of the groups before it (the products of the
/// straight pipeline's stages 1, 3, 5-6, 7 and 14).
pub const PIPELINED_COMMON_GROUPS: [u32; 5] = [15, 13, 14, 4, 5];

/// Group starts of `mpdcc_common`'s schedule with `muls` shared
/// multipliers, cycles after the start strobe: group `g` issues
/// `ceil(n_g / muls)` cycles of products (one per multiplier and cycle,
/// final two cycles after issue); the next group starts when its operands
/// are final (the pipeline stages between the groups: 1, 2, 1, 6).
const fn common_group_starts(muls: u32) -> [u32; 5] {
    let m = if muls == 0 { 1 } else { muls };
    let g = PIPELINED_COMMON_GROUPS;
    let s1 = 1;
    let s3 = s1 + g[0].div_ceil(m) + 2;
    let s5 = s3 + g[1].div_ceil(m) + 3;
    let s7 = s5 + g[2].div_ceil(m) + 2;
    let s14 = s7 + g[3].div_ceil(m) + 7;
    [s1, s3, s5, s7, s14]
}

/// Latency of `mpdcc_common` with `muls` shared multipliers, cycles from
/// the start strobe until the last outputs (the node changes `dn`, `dn1`)
/// are final: two stages after the last product.
pub const fn pipelined_common_latency(muls: u32) -> u32 {
    let m = if muls == 0 { 1 } else { muls };
    common_group_starts(m)[4] + PIPELINED_COMMON_GROUPS[4].div_ceil(m) - 1 + 4
}

/// Cycles from the start strobe to the first candidate's issue, less one
/// (`mpdcc_common` `ISSUE_DELAY`): the explorers read `P_n`, `P_ph` (the
/// first six products of the third group, from their hold registers) in the issue
/// cycle and `dn` 12 cycles after it, so the first candidate issues when
/// both are final when read, before the common terms are complete.
pub const fn pipelined_issue_delay(muls: u32) -> u32 {
    let m = if muls == 0 { 1 } else { muls };
    let pn_final = common_group_starts(m)[2] + 5 / m + 2;
    let dn_read = pipelined_common_latency(m) - 12;
    let first = if pn_final > dn_read {
        pn_final
    } else {
        dn_read
    };
    first - 1
}

/// Cycles from the start strobe until the explorers start (less one),
/// [`pipelined_issue_delay`] of [`PIPELINED_COMMON_MULTIPLIERS`].
pub const PIPELINED_COMMON_LATENCY: u32 = pipelined_issue_delay(PIPELINED_COMMON_MULTIPLIERS);

/// Registered levels of `mpdcc_core`'s arg-min tree (up to eight results
/// of one clock, one comparison per level), cycles.
pub const PIPELINED_ARGMIN_LEVELS: u32 = 3;

/// Clock cycles of one decision of the Verilog `mpdcc_core`, from the
/// start strobe to the decision strobe: the common terms until the first
/// issue ([`PIPELINED_COMMON_LATENCY`]), `ceil(|S| / n)` cycles issuing `n`
/// candidates per clock, the explorers' latency for the last group, the
/// arg-min tree ([`PIPELINED_ARGMIN_LEVELS`]), one cycle for the fold into
/// the decision's minimum. Data-independent apart from `|S|`; a decision
/// that keeps `s(k-1)` takes as long (the lazy check is the result of
/// `s(k-1)` itself). Checked against the RTL's own count on every vector
/// of `scripts/rtl-check mpdcc`.
pub fn pipelined_core_cycles(n: u32, candidates: u32) -> u32 {
    pipelined_core_cycles_ii(n, 1, candidates)
}

/// Latency of `mpdcc_explorer` that takes one candidate every `ii` clocks
/// (`II` = 1..7, clamped): [`PIPELINED_EXPLORER_LATENCY`] at `ii <= 3`
/// (the running minimum of `ceil(7 / ii)` shared search lanes ends no later
/// than the full-rate min tree), `ii - 3` cycles more above.
pub const fn pipelined_explorer_latency(ii: u32) -> u32 {
    let ii = if ii < 1 {
        1
    } else if ii > 7 {
        7
    } else {
        ii
    };
    PIPELINED_EXPLORER_LATENCY + ii.saturating_sub(3)
}

/// [`pipelined_core_cycles`] of a core whose explorers take one candidate
/// every `ii` clocks (`mpdcc_core` parameter `II`, 1..7): the `G =
/// ceil(|S| / n)` issue clocks are `ii` clocks apart, so the last group
/// issues `ii (G - 1)` clocks after the first, then the explorers' latency
/// ([`pipelined_explorer_latency`]), the arg-min tree and the fold. `ii =
/// 1` is [`pipelined_core_cycles`].
pub fn pipelined_core_cycles_ii(n: u32, ii: u32, candidates: u32) -> u32 {
    let groups = candidates.div_ceil(n.max(1));
    let issue = match groups {
        0 => 0,
        g => ii.clamp(1, 7) * (g - 1) + 1,
    };
    PIPELINED_COMMON_LATENCY + issue + pipelined_explorer_latency(ii) + PIPELINED_ARGMIN_LEVELS + 1
}

/// The paper's Table II, worst-case cycles for `n = 1..6` explorers.
pub const PAPER_TABLE2: [u32; 6] = [2223, 1135, 772, 591, 482, 410];

/// `47 + 2176/n`, the paper's fit (Sec. VII-A), rounded to nearest.
pub fn paper_formula(n: u32) -> f64 {
    47.0 + 2176.0 / n.max(1) as f64
}

/// One row of our Table II.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "std", derive(serde::Serialize))]
pub struct Table2Row {
    /// Number of explorers `n`.
    pub explorers: u32,
    /// Paper, Table II, cycles.
    pub paper_cycles: u32,
    /// Paper formula `47 + 2176/n` (unrounded), cycles.
    pub paper_formula_cycles: f64,
    /// Our default core ([`EXPLORER_OPS`], 4 nodes), worst case over our
    /// candidate sets (216 candidates), cycles.
    pub model_cycles: u32,
    /// The paper's explorer structure ([`EXPLORER_OPS_PAPER`]) on our 216
    /// candidates, cycles.
    pub model_cycles_paper_core: u32,
    /// The paper's explorer structure on the paper's apparent tree of 64
    /// candidates (2176 = 64 x 34): the like-for-like comparison, cycles.
    pub model_cycles_64: u32,
    /// Per-candidate explorer latency, our default core, cycles.
    pub model_per_candidate: u32,
    /// Per-candidate explorer latency, paper structure, cycles.
    pub model_per_candidate_paper_core: u32,
    /// Scheduler pre-phase (sample, common terms, lazy check), our default
    /// core, cycles.
    pub model_pre: u32,
    /// Scheduler pre-phase, paper structure ([`SCHEDULER_OPS_PAPER`]), cycles.
    pub model_pre_paper_core: u32,
    /// What-if: our default core with pipelined explorers
    /// ([`CycleModel::pipelined_worst_case`]), 216 candidates, cycles.
    pub model_cycles_pipelined: u32,
}

/// Largest candidate set of the controllers (over all `s(k-1)`).
pub fn max_candidates() -> u32 {
    let mut m = 0;
    for code in 0..512u32 {
        let s = [(code >> 6) as u8, ((code >> 3) & 7) as u8, (code & 7) as u8];
        m = m.max(super::controller::candidates(s).len() as u32);
    }
    m
}

/// Table II for `n = 1..6`, search width `m_bits` (`log2 N_bar`), the
/// default extrapolation point `L` of [`super::params::ControllerParams`].
pub fn table2(m_bits: u32) -> [Table2Row; 6] {
    let lambda = super::params::ControllerParams::default()
        .extrapolation_steps
        .trailing_zeros();
    table2_for(m_bits, lambda)
}

/// Table II for search width `m_bits` and `L = 2^lambda`.
pub fn table2_for(m_bits: u32, lambda: u32) -> [Table2Row; 6] {
    let ours = CycleModel::default();
    let paper = CycleModel::paper();
    let cmax = max_candidates();
    let lw = worst_lane_cycles(4, lambda, m_bits);
    let lp = worst_lane_cycles(1, lambda, m_bits);
    core::array::from_fn(|i| {
        let n = i as u32 + 1;
        let w = ours.worst_case(n, cmax, lw);
        let wp = paper.worst_case(n, cmax, lp);
        Table2Row {
            explorers: n,
            paper_cycles: PAPER_TABLE2[i],
            paper_formula_cycles: paper_formula(n),
            model_cycles: w.total,
            model_cycles_paper_core: wp.total,
            model_cycles_64: paper.worst_case(n, 64, lp).total,
            model_per_candidate: w.per_candidate,
            model_per_candidate_paper_core: wp.per_candidate,
            model_pre: w.pre,
            model_pre_paper_core: wp.pre,
            model_cycles_pipelined: ours.pipelined_worst_case(n, cmax, lw),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The explorer forms `v_x` in one block operation because no position
    /// uses both a dc rail and the neutral point: `rail != 0 => n_coef = 0`.
    #[test]
    fn voltage_needs_one_operation() {
        for p in super::super::anpc::TABLE {
            assert!(p.rail == 0 || p.n_coef == 0, "{p:?}");
        }
    }

    #[test]
    fn programs_are_in_dependency_order() {
        for ops in [
            EXPLORER_OPS,
            EXPLORER_OPS_PAPER,
            SCHEDULER_OPS,
            SCHEDULER_OPS_PAPER,
        ] {
            assert_eq!(check_program(ops), Ok(()));
        }
        // A misspelt or forward handle is caught.
        const BAD: &[Op] = &[op("a", "a", B, &["b"]), op("b", "b", B, &[])];
        assert_eq!(check_program(BAD), Err(ProgramError::Unresolved("b")));
        const DUP: &[Op] = &[op("a", "a", B, &[]), op("a", "a", B, &["a"])];
        assert_eq!(check_program(DUP), Err(ProgramError::Duplicate("a")));
    }

    /// The Verilog core's count by hand: the common terms' 51 products on
    /// four multipliers are 4 + 4 + 4 + 1 + 2 issue cycles in five groups,
    /// groups starting at cycles 1, 7, 14, 20 and 28 (the stages between
    /// them), the last products final at 31, the node changes at 33, read
    /// by the explorers 12 cycles after issue: the first candidate issues
    /// at 21 (P_n, P_ph are final at 14 + 1 + 2 = 17); then 216 candidates
    /// at N = 2 are 108 issue cycles, the last group's results 41 cycles
    /// later, three tree levels and one fold; fewer candidates than
    /// explorers take one issue cycle.
    #[test]
    fn pipelined_core_cycles_by_hand() {
        assert_eq!(PIPELINED_COMMON_GROUPS.iter().sum::<u32>(), 51);
        assert_eq!(common_group_starts(4), [1, 7, 14, 20, 28]);
        assert_eq!(pipelined_common_latency(4), 28 + 2 - 1 + 4);
        assert_eq!(pipelined_issue_delay(4), 33 - 12 - 1);
        assert_eq!(PIPELINED_COMMON_LATENCY, 20);
        // one multiplier: 15 + 13 + 14 + 4 + 5 issue cycles
        assert_eq!(
            pipelined_common_latency(1),
            1 + 15 + 2 + 13 + 3 + 14 + 2 + 4 + 7 + 5 - 1 + 4
        );
        assert_eq!(pipelined_core_cycles(2, 216), 20 + 108 + 41 + 3 + 1);
        assert_eq!(pipelined_core_cycles(4, 216), 20 + 54 + 41 + 3 + 1);
        assert_eq!(pipelined_core_cycles(5, 216), 20 + 44 + 41 + 3 + 1);
        assert_eq!(pipelined_core_cycles(6, 5), 20 + 1 + 41 + 3 + 1);
        // shared lanes: issue clocks II apart, latency 41 + max(II - 3, 0)
        assert_eq!(
            pipelined_core_cycles_ii(1, 4, 216),
            20 + 4 * 215 + 1 + 42 + 3 + 1
        );
        assert_eq!(pipelined_core_cycles_ii(1, 4, 216), 927);
        assert_eq!(
            pipelined_core_cycles_ii(2, 3, 216),
            20 + 3 * 107 + 1 + 41 + 3 + 1
        );
        for n in 1..=6 {
            assert_eq!(
                pipelined_core_cycles_ii(n, 1, 216),
                pipelined_core_cycles(n, 216)
            );
        }
        // Against the structural model of the iterative explorers: more
        // than 20 times fewer cycles at every N for the full set (24x at
        // N = 6, 42x at N = 2).
        let m = CycleModel::default();
        let lw = worst_lane_cycles(4, 3, 7);
        for n in 1..=6 {
            assert!(20 * pipelined_core_cycles(n, 216) < m.worst_case(n, 216, lw).total);
        }
    }

    #[test]
    fn paper_table_is_its_formula_rounded() {
        for n in 1..=6u32 {
            let f = paper_formula(n);
            assert_eq!(libm::round(f) as u32, PAPER_TABLE2[n as usize - 1], "n={n}");
        }
        // ... and not a count: 2176/3 and 2176/6 are not integers.
        assert!(paper_formula(3).fract() > 0.0 && paper_formula(6).fract() > 0.0);
    }

    /// Hand count of a chain: three dependent block ops take 9 cycles, four
    /// independent ones on one block take 3 + 3 (issue-limited).
    #[test]
    fn list_scheduler_by_hand() {
        let m = CycleModel::default();
        const CHAIN: &[Op] = &[
            op("a", "a", B, &[]),
            op("b", "b", B, &["a"]),
            op("c", "c", B, &["b"]),
        ];
        assert_eq!(m.makespan(CHAIN, 4, 0), 9);
        const PAR: &[Op] = &[
            op("a", "a", B, &[]),
            op("b", "b", B, &[]),
            op("c", "c", B, &[]),
            op("d", "d", B, &[]),
        ];
        assert_eq!(m.makespan(PAR, 1, 0), 6);
        assert_eq!(m.makespan(PAR, 4, 0), 3);
        const LANE: &[Op] = &[
            op("a", "a", B, &[]),
            op("l", "l", Lanes, &["a"]),
            op("t", "t", Tree(3), &["l"]),
        ];
        assert_eq!(m.makespan(LANE, 4, 8), 3 + 8 + 3);
    }

    #[test]
    fn worst_case_structure() {
        let m = CycleModel::paper();
        let t = m.candidate_cycles(8);
        let pre = m.pre_cycles() + 1;
        // One explorer: strictly sequential candidates.
        let w1 = m.worst_case(1, 64, 8);
        assert_eq!(w1.total, pre + 64 * t + 2);
        // n dividing the count: exact split (dispatch skew hidden by the latency).
        let w4 = m.worst_case(4, 64, 8);
        assert_eq!(w4.total, pre + 16 * t + 3 + 2);
        // Otherwise the ceiling shows.
        let w3 = m.worst_case(3, 64, 8);
        assert_eq!(w3.total, pre + 22 * t + 2);
        // Monotone in n.
        for n in 1..6 {
            assert!(m.worst_case(n + 1, 216, 8).total < m.worst_case(n, 216, 8).total);
        }
        // Pipelining never takes longer than the sequential explorer, and an
        // interval equal to the latency gives the sequential count back
        // (up to the one-cycle dispatch skew per explorer).
        for n in 1..=6 {
            assert!(m.pipelined_worst_case(n, 216, 8) <= m.worst_case(n, 216, 8).total + n);
        }
        let seq = CycleModel {
            explorer_blocks: 1,
            ..CycleModel::paper()
        };
        let ii = seq.pipelined_ii(8);
        assert_eq!(
            ii,
            EXPLORER_OPS_PAPER
                .iter()
                .filter(|o| o.kind == Kind::Block)
                .count() as u32
        );
        // Lane worst cases: M + 1 for one chord; L = 16, N_bar = 128, three
        // pieces of 16, 16 and 96 steps: 5 + 5 + 8; L = 8, four pieces of 8,
        // 8, 16 and 96: 4 + 4 + 5 + 8; L = 64: room for two nodes only
        // (64, 128), pieces of 64 and 64: 7 + 7.
        assert_eq!(worst_lane_cycles(1, 4, 7), 8);
        assert_eq!(worst_lane_cycles(3, 4, 7), 18);
        assert_eq!(worst_lane_cycles(4, 3, 7), 21);
        assert_eq!(worst_lane_cycles(3, 6, 7), 14);
        assert_eq!(worst_lane_cycles(3, 7, 7), 8);
    }
}

#[cfg(test)]
mod print {
    extern crate std;
    /// Prints Table II as our model computes it (quoted in docs/mpdcc-fpga.md).
    #[test]
    fn print_table2() {
        let m = super::CycleModel::default();
        std::println!(
            "pre {} per-candidate {} kept {} max candidates {}",
            m.pre_cycles() + 1,
            m.candidate_cycles(super::worst_lane_cycles(4, 3, 7)),
            m.kept_cycles(),
            super::max_candidates()
        );
        let p = super::CycleModel::paper();
        std::println!(
            "paper core: pre {} per-candidate {}",
            p.pre_cycles() + 1,
            p.candidate_cycles(8)
        );
        let lw = super::worst_lane_cycles(4, 3, 7);
        std::println!(
            "pipelined II: ours {}, paper core {}",
            m.pipelined_ii(lw),
            p.pipelined_ii(8)
        );
        for r in super::table2(7) {
            std::println!("{r:?}");
        }
    }
}
