//! Structural clock-cycle model of the FPGA MPDCC core (paper 001, Sec.
//! VII-A, Table II).
//!
//! Not a formula: each unit's work is listed as operations with their data
//! dependencies, exactly the arithmetic of [`super::fpga`], and scheduled on
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
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Op {
    /// What it computes (the name used in [`super::fpga`]).
    pub name: &'static str,
    /// Resource and latency class.
    pub kind: Kind,
    /// Indices of the operations whose results it needs.
    pub deps: &'static [usize],
}

const fn op(name: &'static str, kind: Kind, deps: &'static [usize]) -> Op {
    Op { name, kind, deps }
}

use Kind::{Block as B, Lanes, Reg, Tree};

/// One explorer evaluation ([`super::fpga::explore`]).
pub const EXPLORER_OPS: &[Op] = &[
    op("load candidate, f_s", Reg, &[]),                        // 0
    op("v_a = rail Vdc/2 + ph v_ph,a", B, &[0]),                // 1
    op("v_b = rail Vdc/2 + ph v_ph,b", B, &[0]),                // 2
    op("v_c = rail Vdc/2 + ph v_ph,c", B, &[0]),                // 3
    op("v_a += n v_n", B, &[1]),                                // 4
    op("v_b += n v_n", B, &[2]),                                // 5
    op("v_c += n v_n", B, &[3]),                                // 6
    op("sum = v_a + v_b", B, &[4, 5]),                          // 7
    op("sum += v_c", B, &[7, 6]),                               // 8
    op("u_a = 3 v_a - sum", B, &[4, 8]),                        // 9
    op("u_b = 3 v_b - sum", B, &[5, 8]),                        // 10
    op("u_c = 3 v_c - sum", B, &[6, 8]),                        // 11
    op("D_a = dn_a - g3 u_a", B, &[9]),                         // 12
    op("D_b = dn_b - g3 u_b", B, &[10]),                        // 13
    op("D_c = dn_c - g3 u_c", B, &[11]),                        // 14
    op("D_vn = np_a P_n,a", B, &[0]),                           // 15
    op("D_vn += np_b P_n,b", B, &[15]),                         // 16
    op("D_vn += np_c P_n,c", B, &[16]),                         // 17
    op("D_ph,a = -c P_ph,a", B, &[0]),                          // 18
    op("D_ph,b = -c P_ph,b", B, &[0]),                          // 19
    op("D_ph,c = -c P_ph,c", B, &[0]),                          // 20
    op("Algorithm 2 x7", Lanes, &[12, 13, 14, 17, 18, 19, 20]), // 21
    op("min l_j, max J_dl", Tree(3), &[21]),                    // 22
    op("recip ROM [L*]", Reg, &[22]),                           // 23
    op("J_sw = f_s recip", B, &[23]),                           // 24
    op("e_vn = e_vn0 + L* D_vn / L", B, &[22]),                 // 25
    op("sq = e_vn^2", B, &[25]),                                // 26
    op("J = lambda sq + J_sw", B, &[26, 24]),                   // 27
    op("return result", Reg, &[27]),                            // 28
];

/// The scheduler before dispatch ([`super::fpga::common_terms`] and
/// [`super::fpga::lazy_ok`]), worst case (the lazy check fails).
pub const SCHEDULER_OPS: &[Op] = &[
    op("sample state registers", Reg, &[]),        // 0
    op("kw = c_w omega_r", B, &[0]),               // 1
    op("w2 = omega_r^2", B, &[0]),                 // 2
    op("ks = c_s omega_s", B, &[0]),               // 3
    op("kp = c_p w2", B, &[2]),                    // 4
    op("nat_a = -c_tau i_a", B, &[0]),             // 5
    op("nat_a += c_r psi_a", B, &[5]),             // 6
    op("nat_a += kw psi_b", B, &[6, 1]),           // 7
    op("rate_a = -ks i*_b - nat_a", B, &[7, 3]),   // 8
    op("nat_b = -c_tau i_b", B, &[0]),             // 9
    op("nat_b += c_r psi_b", B, &[9]),             // 10
    op("nat_b -= kw psi_a", B, &[10, 1]),          // 11
    op("rate_b = ks i*_a - nat_b", B, &[11, 3]),   // 12
    op("dl_a = rate_a - kp psi_a", B, &[8, 4]),    // 13
    op("dl_b = rate_b - kp psi_b", B, &[12, 4]),   // 14
    op("d1_a = rate_a L - kp psi_a", B, &[8, 4]),  // 15
    op("d1_b = rate_b L - kp psi_b", B, &[12, 4]), // 16
    op("s3h dl_b", B, &[14]),                      // 17
    op("s3h d1_b", B, &[16]),                      // 18
    op("dn_l,b/c", B, &[13, 17]),                  // 19
    op("dn_l,c", B, &[13, 17]),                    // 20
    op("dn_1,b", B, &[15, 18]),                    // 21
    op("dn_1,c", B, &[15, 18]),                    // 22
    op("s3h i_b", B, &[0]),                        // 23
    op("i_b", B, &[23]),                           // 24
    op("i_c", B, &[23]),                           // 25
    op("e_a = i*_a - i_a", B, &[0]),               // 26
    op("e_b' = i*_b - i_b", B, &[0]),              // 27
    op("s3h e_b'", B, &[27]),                      // 28
    op("e_b", B, &[26, 28]),                       // 29
    op("e_c", B, &[26, 28]),                       // 30
    op("e_vn = -v_n", B, &[0]),                    // 31
    op("e_ph,a", B, &[0]),                         // 32
    op("e_ph,b", B, &[0]),                         // 33
    op("e_ph,c", B, &[0]),                         // 34
    op("P_n,a = c_n i_a", B, &[0]),                // 35
    op("P_n,b", B, &[24]),                         // 36
    op("P_n,c", B, &[25]),                         // 37
    op("P_ph,a = c_ph i_a", B, &[0]),              // 38
    op("P_ph,b", B, &[24]),                        // 39
    op("P_ph,c", B, &[25]),                        // 40
    // Lazy check: the explorer's voltage/inverter path for s(k-1), one step.
    op("v_a(s_prev)", B, &[0]),                                      // 41
    op("v_b(s_prev)", B, &[0]),                                      // 42
    op("v_c(s_prev)", B, &[0]),                                      // 43
    op("v_a += n v_n", B, &[41]),                                    // 44
    op("v_b += n v_n", B, &[42]),                                    // 45
    op("v_c += n v_n", B, &[43]),                                    // 46
    op("sum = v_a + v_b", B, &[44, 45]),                             // 47
    op("sum += v_c", B, &[47, 46]),                                  // 48
    op("u_a", B, &[44, 48]),                                         // 49
    op("u_b", B, &[45, 48]),                                         // 50
    op("u_c", B, &[46, 48]),                                         // 51
    op("e1_a = e_a + dn_1,a - g3 u_a / L", B, &[49, 15, 26]),        // 52
    op("e1_b", B, &[50, 21, 29]),                                    // 53
    op("e1_c", B, &[51, 22, 30]),                                    // 54
    op("e1_vn = e_vn + sum np P_n / L", B, &[31, 35, 36, 37]),       // 55
    op("e1_vn += ...", B, &[55]),                                    // 56
    op("e1_vn += ...", B, &[56]),                                    // 57
    op("e1_ph,a", B, &[32, 38]),                                     // 58
    op("e1_ph,b", B, &[33, 39]),                                     // 59
    op("e1_ph,c", B, &[34, 40]),                                     // 60
    op("7 bound compares, AND", Reg, &[52, 53, 54, 57, 58, 59, 60]), // 61
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
}

impl Default for CycleModel {
    fn default() -> Self {
        Self {
            explorer_blocks: 4,
            scheduler_blocks: 4,
            block_latency: 3,
        }
    }
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
        let mut used = [0u32; 512];
        let mut fin = [0u32; 128];
        let mut end = 0;
        for (i, o) in ops.iter().enumerate().take(fin.len()) {
            let ready = o.deps.iter().map(|&d| fin[d]).max().unwrap_or(0);
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
        self.makespan(EXPLORER_OPS, self.explorer_blocks, lane_cycles)
    }

    /// Cycles of the scheduler's pre-phase (common terms and lazy check).
    pub fn pre_cycles(&self) -> u32 {
        self.makespan(SCHEDULER_OPS, self.scheduler_blocks, 0)
    }

    /// A decision that keeps `s(k-1)`: pre-phase plus the output register.
    pub fn kept_cycles(&self) -> u32 {
        self.pre_cycles() + 1
    }

    /// A decision with a search: dispatch one candidate per cycle to the
    /// explorer that is free first, compare as results arrive, register the
    /// output. `lanes[i]` = slowest lane of candidate `i`.
    pub fn search_cycles(&self, n: u32, m_bits: u32, lanes: &[u32]) -> u32 {
        let _ = m_bits;
        let n = n.clamp(1, 64) as usize;
        let pre = self.pre_cycles() + 1; // + candidate generator start
        let mut free = [pre; 64];
        let mut next_dispatch = pre;
        let mut last = pre;
        for &lc in lanes {
            // Explorer free first (lowest index on ties).
            let (e, &t_free) = free[..n]
                .iter()
                .enumerate()
                .min_by_key(|&(i, &t)| (t, i))
                .unwrap_or((0, &pre));
            let start = t_free.max(next_dispatch);
            next_dispatch = start + 1;
            free[e] = start + self.candidate_cycles(lc);
            last = last.max(free[e]);
        }
        last + 1 + 1 // last compare, output register
    }

    /// Worst case for `n` explorers and `candidates` candidates, every lane
    /// running all `M + 1` cycles (no early exit).
    pub fn worst_case(&self, n: u32, candidates: u32, m_bits: u32) -> Breakdown {
        let lanes = [m_bits + 1; super::controller::MAX_CANDIDATES];
        let c = (candidates as usize).min(lanes.len());
        Breakdown {
            pre: self.pre_cycles() + 1,
            per_candidate: self.candidate_cycles(m_bits + 1),
            candidates: c as u32,
            explorers: n,
            total: self.search_cycles(n, m_bits, &lanes[..c]),
        }
    }
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
    /// Our model, worst case over our candidate sets (216 candidates), cycles.
    pub model_cycles: u32,
    /// Our model with the paper's apparent tree of 64 candidates
    /// (2176 = 64 x 34), cycles.
    pub model_cycles_64: u32,
    /// Our model's per-candidate explorer latency, cycles.
    pub model_per_candidate: u32,
    /// Our model's scheduler pre-phase, cycles.
    pub model_pre: u32,
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

/// Table II for `n = 1..6`, search width `m_bits` (`log2 N_bar`).
pub fn table2(m_bits: u32) -> [Table2Row; 6] {
    let model = CycleModel::default();
    let cmax = max_candidates();
    core::array::from_fn(|i| {
        let n = i as u32 + 1;
        let w = model.worst_case(n, cmax, m_bits);
        Table2Row {
            explorers: n,
            paper_cycles: PAPER_TABLE2[i],
            paper_formula_cycles: paper_formula(n),
            model_cycles: w.total,
            model_cycles_64: model.worst_case(n, 64, m_bits).total,
            model_per_candidate: w.per_candidate,
            model_pre: w.pre,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn programs_are_in_dependency_order() {
        for ops in [EXPLORER_OPS, SCHEDULER_OPS] {
            for (i, o) in ops.iter().enumerate() {
                assert!(o.deps.iter().all(|&d| d < i), "{}", o.name);
            }
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
        const CHAIN: &[Op] = &[op("a", B, &[]), op("b", B, &[0]), op("c", B, &[1])];
        assert_eq!(m.makespan(CHAIN, 4, 0), 9);
        const PAR: &[Op] = &[
            op("a", B, &[]),
            op("b", B, &[]),
            op("c", B, &[]),
            op("d", B, &[]),
        ];
        assert_eq!(m.makespan(PAR, 1, 0), 6);
        assert_eq!(m.makespan(PAR, 4, 0), 3);
        const LANE: &[Op] = &[
            op("a", B, &[]),
            op("l", Lanes, &[0]),
            op("t", Tree(3), &[1]),
        ];
        assert_eq!(m.makespan(LANE, 4, 8), 3 + 8 + 3);
    }

    #[test]
    fn worst_case_structure() {
        let m = CycleModel::default();
        let t = m.candidate_cycles(8);
        let pre = m.pre_cycles() + 1;
        // One explorer: strictly sequential candidates.
        let w1 = m.worst_case(1, 64, 7);
        assert_eq!(w1.total, pre + 64 * t + 2);
        // n dividing the count: exact split (dispatch skew hidden by the latency).
        let w4 = m.worst_case(4, 64, 7);
        assert_eq!(w4.total, pre + 16 * t + 3 + 2);
        // Otherwise the ceiling shows.
        let w3 = m.worst_case(3, 64, 7);
        assert_eq!(w3.total, pre + 22 * t + 2);
        // Monotone in n.
        for n in 1..6 {
            assert!(m.worst_case(n + 1, 216, 7).total < m.worst_case(n, 216, 7).total);
        }
    }
}
