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

/// One explorer evaluation with the paper's structure (`Structure::PAPER`):
/// one chord, no accuracy options.
pub const EXPLORER_OPS_PAPER: &[Op] = &[
    op("load candidate, f_s", Reg, &[]),                    // 0
    op("v_a = ph v_ph,a + mux(rail Vdc/2 | v_n)", B, &[0]), // 1
    op("v_b = ph v_ph,b + mux(rail Vdc/2 | v_n)", B, &[0]), // 2
    op("v_c = ph v_ph,c + mux(rail Vdc/2 | v_n)", B, &[0]), // 3
    op("sum = v_a + v_b", B, &[1, 2]),                      // 4
    op("sum += v_c", B, &[4, 3]),                           // 5
    op("u_a = 3 v_a - sum", B, &[1, 5]),                    // 6
    op("u_b = 3 v_b - sum", B, &[2, 5]),                    // 7
    op("u_c = 3 v_c - sum", B, &[3, 5]),                    // 8
    op("D_a = dn_a - g3 u_a", B, &[6]),                     // 9
    op("D_b = dn_b - g3 u_b", B, &[7]),                     // 10
    op("D_c = dn_c - g3 u_c", B, &[8]),                     // 11
    op("D_vn = np_a P_n,a", B, &[0]),                       // 12
    op("D_vn += np_b P_n,b", B, &[12]),                     // 13
    op("D_vn += np_c P_n,c", B, &[13]),                     // 14
    op("D_ph,a = -c P_ph,a", B, &[0]),                      // 15
    op("D_ph,b = -c P_ph,b", B, &[0]),                      // 16
    op("D_ph,c = -c P_ph,c", B, &[0]),                      // 17
    op(
        "Algorithm 2 x7 (J_dl terms in cycle 1)",
        Lanes,
        &[9, 10, 11, 14, 15, 16, 17],
    ), // 18
    op("min l_j, max J_dl", Tree(3), &[18]),                // 19
    op("recip ROM [L*]", Reg, &[19]),                       // 20
    op("J_sw = f_s recip", B, &[20]),                       // 21
    op("e_vn = e_vn0 + L* D_vn / L", B, &[19]),             // 22
    op("sq = e_vn^2", B, &[22]),                            // 23
    op("J = lambda sq + J_sw", B, &[23, 21]),               // 24
    op("return result", Reg, &[24]),                        // 25
];

/// One explorer evaluation of our default core ([`super::fpga::Structure::CORE`]):
/// four interpolation nodes, capacitor drift, stator damping, exact first step.
pub const EXPLORER_OPS: &[Op] = &[
    op("load candidate, f_s", Reg, &[]),                    // 0
    op("D_vn = np_a P_n,a", B, &[0]),                       // 1
    op("D_vn += np_b P_n,b", B, &[1]),                      // 2
    op("D_vn += np_c P_n,c", B, &[2]),                      // 3
    op("D_ph,a = -c P_ph,a", B, &[0]),                      // 4
    op("D_ph,b = -c P_ph,b", B, &[0]),                      // 5
    op("D_ph,c = -c P_ph,c", B, &[0]),                      // 6
    op("v_a = ph v_ph,a + mux(rail Vdc/2 | v_n)", B, &[0]), // 7
    op("v_b = ph v_ph,b + mux(rail Vdc/2 | v_n)", B, &[0]), // 8
    op("v_c = ph v_ph,c + mux(rail Vdc/2 | v_n)", B, &[0]), // 9
    op("sum = v_a + v_b", B, &[7, 8]),                      // 10
    op("sum += v_c", B, &[10, 9]),                          // 11
    op("u0_a = 3 v_a - sum", B, &[7, 11]),                  // 12
    op("u0_b = 3 v_b - sum", B, &[8, 11]),                  // 13
    op("u0_c = 3 v_c - sum", B, &[9, 11]),                  // 14
    op(
        "vh_a = -(n D_vn + ph D_ph,a) / 2 (capacitor drift)",
        B,
        &[3, 4],
    ), // 15
    op("vh_b", B, &[3, 5]),                                 // 16
    op("vh_c", B, &[3, 6]),                                 // 17
    op("sum_h = vh_a + vh_b", B, &[15, 16]),                // 18
    op("sum_h += vh_c", B, &[18, 17]),                      // 19
    op("uh_a = 3 vh_a - sum_h", B, &[15, 19]),              // 20
    op("uh_b", B, &[16, 19]),                               // 21
    op("uh_c", B, &[17, 19]),                               // 22
    op("P0_a = g3 u0_a", B, &[12]),                         // 23
    op("P0_b = g3 u0_b", B, &[13]),                         // 24
    op("P0_c = g3 u0_c", B, &[14]),                         // 25
    op("Q_a = -gd u0_a", B, &[12]),                         // 26
    op("Q_b = -gd u0_b", B, &[13]),                         // 27
    op("Q_c = -gd u0_c", B, &[14]),                         // 28
    op("Q_a += g3 uh_a", B, &[26, 20]),                     // 29
    op("Q_b += g3 uh_b", B, &[27, 21]),                     // 30
    op("Q_c += g3 uh_c", B, &[28, 22]),                     // 31
    op("t = 1 P0_a + 1 Q_a (node 1L)", B, &[23, 29]),       // 32
    op("D1_a = dn1_a - t", B, &[32]),                       // 33
    op("t = 2 P0_a + 4 Q_a (node 2L)", B, &[23, 29]),       // 34
    op("D2_a = dn2_a - t", B, &[34]),                       // 35
    op("t = 4 P0_a + 16 Q_a (node 4L)", B, &[23, 29]),      // 36
    op("D4_a = dn4_a - t", B, &[36]),                       // 37
    op("t = 8 P0_a + 64 Q_a (node 8L)", B, &[23, 29]),      // 38
    op("D8_a = dn8_a - t", B, &[38]),                       // 39
    op("t = 1 P0_b + 1 Q_b (node 1L)", B, &[24, 30]),       // 40
    op("D1_b = dn1_b - t", B, &[40]),                       // 41
    op("t = 2 P0_b + 4 Q_b (node 2L)", B, &[24, 30]),       // 42
    op("D2_b = dn2_b - t", B, &[42]),                       // 43
    op("t = 4 P0_b + 16 Q_b (node 4L)", B, &[24, 30]),      // 44
    op("D4_b = dn4_b - t", B, &[44]),                       // 45
    op("t = 8 P0_b + 64 Q_b (node 8L)", B, &[24, 30]),      // 46
    op("D8_b = dn8_b - t", B, &[46]),                       // 47
    op("t = 1 P0_c + 1 Q_c (node 1L)", B, &[25, 31]),       // 48
    op("D1_c = dn1_c - t", B, &[48]),                       // 49
    op("t = 2 P0_c + 4 Q_c (node 2L)", B, &[25, 31]),       // 50
    op("D2_c = dn2_c - t", B, &[50]),                       // 51
    op("t = 4 P0_c + 16 Q_c (node 4L)", B, &[25, 31]),      // 52
    op("D4_c = dn4_c - t", B, &[52]),                       // 53
    op("t = 8 P0_c + 64 Q_c (node 8L)", B, &[25, 31]),      // 54
    op("D8_c = dn8_c - t", B, &[54]),                       // 55
    op(
        "D1_a = dn1_a - g3_1 (u0_a + uh_a/L) (first step)",
        B,
        &[12, 20],
    ), // 56
    op("D1_b", B, &[13, 21]),                               // 57
    op("D1_c", B, &[14, 22]),                               // 58
    op(
        "Algorithm 2 x7, up to 4 pieces each (J_dl terms in cycle 1)",
        Lanes,
        &[
            33, 41, 49, 35, 43, 51, 37, 45, 53, 39, 47, 55, 3, 4, 5, 6, 56, 57, 58,
        ],
    ), // 59
    op("min l_j, max J_dl", Tree(3), &[59]),                // 60
    op("recip ROM [L*]", Reg, &[60]),                       // 61
    op("J_sw = f_s recip", B, &[61]),                       // 62
    op("e_vn = e_vn0 + interpolated D_vn at L*", B, &[60]), // 63
    op("sq = e_vn^2", B, &[63]),                            // 64
    op("J = lambda sq + J_sw", B, &[64, 62]),               // 65
    op("return result", Reg, &[65]),                        // 66
];

/// The scheduler before dispatch ([`super::fpga::common_terms`] and
/// [`super::fpga::lazy_ok`]) of our default core (all accuracy options, four
/// nodes), worst case (the lazy check fails). [`SCHEDULER_OPS_PAPER`] is the
/// paper's structure.
pub const SCHEDULER_OPS: &[Op] = &[
    op("sample state registers", Reg, &[]),                // 0
    op("kw = c_w omega_r", B, &[0]),                       // 1
    op("w2 = omega_r^2", B, &[0]),                         // 2
    op("ks = c_s omega_s", B, &[0]),                       // 3
    op("s2 = omega_s^2", B, &[0]),                         // 4
    op("kp = c_p w2", B, &[2]),                            // 5
    op("k2 = ks^2 / 2 (2nd-order rotation)", B, &[3]),     // 6
    op("tr = c_3 w2 (3rd order)", B, &[2]),                // 7
    op("ts = c_3 s2 (3rd order)", B, &[4]),                // 8
    op("kw3 = kw tr", B, &[1, 7]),                         // 9
    op("ks3 = ks ts", B, &[3, 8]),                         // 10
    op("nat_a = -c_tau i_a", B, &[0]),                     // 11
    op("nat_a += c_r psi_a", B, &[11]),                    // 12
    op("nat_a += kw psi_b", B, &[1, 12]),                  // 13
    op("rate_a = -ks i*_b - nat_a", B, &[3, 13]),          // 14
    op("nat_b = -c_tau i_b", B, &[0]),                     // 15
    op("nat_b += c_r psi_b", B, &[15]),                    // 16
    op("nat_b -= kw psi_a", B, &[1, 16]),                  // 17
    op("rate_b = ks i*_a - nat_b", B, &[3, 17]),           // 18
    op("dmp_a = c_d nat_a (stator damping)", B, &[13]),    // 19
    op("dmp_b = c_d nat_b", B, &[17]),                     // 20
    op("kw1 = c_w1 omega_r (one-step products)", B, &[0]), // 21
    op("ks1 = c_s1 omega_s", B, &[0]),                     // 22
    op("nat1_a = -c_tau1 i_a", B, &[0]),                   // 23
    op("nat1_a += c_r1 psi_a", B, &[23]),                  // 24
    op("nat1_a += kw1 psi_b", B, &[21, 24]),               // 25
    op("rate1_a = -ks1 i*_b - nat1_a", B, &[22, 25]),      // 26
    op("nat1_b = -c_tau1 i_b", B, &[0]),                   // 27
    op("nat1_b += c_r1 psi_b", B, &[27]),                  // 28
    op("nat1_b -= kw1 psi_a", B, &[21, 28]),               // 29
    op("rate1_b = ks1 i*_a - nat1_b", B, &[22, 29]),       // 30
    op("cor_a = kp psi_a", B, &[5]),                       // 31
    op("cor_a += k2 i*_a", B, &[6, 31]),                   // 32
    op("cor_b = kp psi_b", B, &[5]),                       // 33
    op("cor_b += k2 i*_b", B, &[6, 33]),                   // 34
    op("cub_a = ks3 i*_b", B, &[10]),                      // 35
    op("cub_a += kw3 psi_b", B, &[9, 35]),                 // 36
    op("cub_b = -ks3 i*_a", B, &[10]),                     // 37
    op("cub_b -= kw3 psi_a", B, &[9, 37]),                 // 38
    op(
        "dl_a = rate_a + dmp_a - cor_a + cub_a (node L)",
        B,
        &[14, 19, 32, 36],
    ), // 39
    op(
        "dl_b = rate_b + dmp_b - cor_b + cub_b",
        B,
        &[18, 20, 34, 38],
    ), // 40
    op(
        "d1_a = rate1_a - cor_a / L^2 + cub_a / L^3 (one step)",
        B,
        &[26, 32, 36],
    ), // 41
    op(
        "d1_b = rate1_b - cor_b / L^2 + cub_b / L^3",
        B,
        &[30, 34, 38],
    ), // 42
    op("s3h dl_b", B, &[40]),                              // 43
    op("s3h d1_b", B, &[42]),                              // 44
    op("dn_l,b", B, &[39, 43]),                            // 45
    op("dn_l,c", B, &[39, 43]),                            // 46
    op("dn_1,b", B, &[41, 44]),                            // 47
    op("dn_1,c", B, &[41, 44]),                            // 48
    op(
        "dn_2L,a = 2 rate_a + 4 (dmp_a - cor_a) + 8 cub_a",
        B,
        &[14, 19, 32, 36],
    ), // 49
    op(
        "dl_2L,b = 2 rate_b + 4 (dmp_b - cor_b) + 8 cub_b",
        B,
        &[18, 20, 34, 38],
    ), // 50
    op("s3h dl_2L,b", B, &[50]),                           // 51
    op("dn_2L,b", B, &[49, 51]),                           // 52
    op("dn_2L,c", B, &[49, 51]),                           // 53
    op(
        "dn_4L,a = 4 rate_a + 16 (dmp_a - cor_a) + 64 cub_a",
        B,
        &[14, 19, 32, 36],
    ), // 54
    op(
        "dl_4L,b = 4 rate_b + 16 (dmp_b - cor_b) + 64 cub_b",
        B,
        &[18, 20, 34, 38],
    ), // 55
    op("s3h dl_4L,b", B, &[55]),                           // 56
    op("dn_4L,b", B, &[54, 56]),                           // 57
    op("dn_4L,c", B, &[54, 56]),                           // 58
    op(
        "dn_8L,a = 8 rate_a + 64 (dmp_a - cor_a) + 512 cub_a",
        B,
        &[14, 19, 32, 36],
    ), // 59
    op(
        "dl_8L,b = 8 rate_b + 64 (dmp_b - cor_b) + 512 cub_b",
        B,
        &[18, 20, 34, 38],
    ), // 60
    op("s3h dl_8L,b", B, &[60]),                           // 61
    op("dn_8L,b", B, &[59, 61]),                           // 62
    op("dn_8L,c", B, &[59, 61]),                           // 63
    op("s3h i_b", B, &[0]),                                // 64
    op("i_b", B, &[64]),                                   // 65
    op("i_c", B, &[64]),                                   // 66
    op("e_a = i*_a - i_a", B, &[0]),                       // 67
    op("e_b' = i*_b - i_b", B, &[0]),                      // 68
    op("s3h e_b'", B, &[68]),                              // 69
    op("e_b", B, &[67, 69]),                               // 70
    op("e_c", B, &[67, 69]),                               // 71
    op("e_vn = -v_n", B, &[0]),                            // 72
    op("e_ph,a", B, &[0]),                                 // 73
    op("e_ph,b", B, &[0]),                                 // 74
    op("e_ph,c", B, &[0]),                                 // 75
    op("P_n,a = c_n i_a", B, &[0]),                        // 76
    op("P_n,b", B, &[65]),                                 // 77
    op("P_n,c", B, &[66]),                                 // 78
    op("P_ph,a = c_ph i_a", B, &[0]),                      // 79
    op("P_ph,b", B, &[65]),                                // 80
    op("P_ph,c", B, &[66]),                                // 81
    op("v_a(s_prev) = ph v_ph,a + mux(rail Vdc/2 | v_n)", B, &[0]), // 82
    op("v_b(s_prev) = ph v_ph,b + mux(rail Vdc/2 | v_n)", B, &[0]), // 83
    op("v_c(s_prev) = ph v_ph,c + mux(rail Vdc/2 | v_n)", B, &[0]), // 84
    op(
        "v_a(s_prev) += (n D_vn + ph D_ph,a) / (2L) (capacitor drift)",
        B,
        &[76, 77, 78, 79, 82],
    ), // 85
    op("v_b(s_prev) += drift", B, &[76, 77, 78, 80, 83]),  // 86
    op("v_c(s_prev) += drift", B, &[76, 77, 78, 81, 84]),  // 87
    op("sum = v_a + v_b", B, &[85, 86]),                   // 88
    op("sum += v_c", B, &[87, 88]),                        // 89
    op("u_a = 3 v_a - sum", B, &[85, 89]),                 // 90
    op("u_b", B, &[86, 89]),                               // 91
    op("u_c", B, &[87, 89]),                               // 92
    op("e1_a = e_a + dn_1,a - g3 u_a / L", B, &[41, 67, 90]), // 93
    op("e1_b", B, &[47, 70, 91]),                          // 94
    op("e1_c", B, &[48, 71, 92]),                          // 95
    op("e1_vn = e_vn + np_a P_n,a / L", B, &[72, 76]),     // 96
    op("e1_vn += np_b P_n,b / L", B, &[77, 96]),           // 97
    op("e1_vn += np_c P_n,c / L", B, &[78, 97]),           // 98
    op("e1_ph,a = e_ph,a - c P_ph,a / L", B, &[73, 79]),   // 99
    op("e1_ph,b", B, &[74, 80]),                           // 100
    op("e1_ph,c", B, &[75, 81]),                           // 101
    op(
        "7 bound compares, AND (lazy check); all nodes ready",
        Reg,
        &[
            45, 46, 49, 52, 53, 54, 57, 58, 59, 62, 63, 93, 94, 95, 98, 99, 100, 101,
        ],
    ), // 102
];

/// The scheduler before dispatch with the paper's structure
/// (`Structure::PAPER`: first-order rotations plus the `p`
/// correction, one node, no stator damping, no capacitor drift), worst case;
/// [`SCHEDULER_OPS`] without the operations of the accuracy options.
pub const SCHEDULER_OPS_PAPER: &[Op] = &[
    op("sample state registers", Reg, &[]),                // 0
    op("kw = c_w omega_r", B, &[0]),                       // 1
    op("w2 = omega_r^2", B, &[0]),                         // 2
    op("ks = c_s omega_s", B, &[0]),                       // 3
    op("kp = c_p w2", B, &[2]),                            // 4
    op("nat_a = -c_tau i_a", B, &[0]),                     // 5
    op("nat_a += c_r psi_a", B, &[5]),                     // 6
    op("nat_a += kw psi_b", B, &[1, 6]),                   // 7
    op("rate_a = -ks i*_b - nat_a", B, &[3, 7]),           // 8
    op("nat_b = -c_tau i_b", B, &[0]),                     // 9
    op("nat_b += c_r psi_b", B, &[9]),                     // 10
    op("nat_b -= kw psi_a", B, &[1, 10]),                  // 11
    op("rate_b = ks i*_a - nat_b", B, &[3, 11]),           // 12
    op("kw1 = c_w1 omega_r (one-step products)", B, &[0]), // 13
    op("ks1 = c_s1 omega_s", B, &[0]),                     // 14
    op("nat1_a = -c_tau1 i_a", B, &[0]),                   // 15
    op("nat1_a += c_r1 psi_a", B, &[15]),                  // 16
    op("nat1_a += kw1 psi_b", B, &[13, 16]),               // 17
    op("rate1_a = -ks1 i*_b - nat1_a", B, &[14, 17]),      // 18
    op("nat1_b = -c_tau1 i_b", B, &[0]),                   // 19
    op("nat1_b += c_r1 psi_b", B, &[19]),                  // 20
    op("nat1_b -= kw1 psi_a", B, &[13, 20]),               // 21
    op("rate1_b = ks1 i*_a - nat1_b", B, &[14, 21]),       // 22
    op("cor_a = kp psi_a", B, &[4]),                       // 23
    op("cor_b = kp psi_b", B, &[4]),                       // 24
    op("dl_a = rate_a - cor_a (node L)", B, &[0, 1, 2, 3, 7, 8, 23]), // 25
    op("dl_b = rate_b - cor_b", B, &[0, 1, 2, 3, 11, 12, 24]), // 26
    op(
        "d1_a = rate1_a - cor_a / L^2 (one step)",
        B,
        &[0, 1, 2, 3, 18, 23],
    ), // 27
    op("d1_b = rate1_b - cor_b / L^2", B, &[0, 1, 2, 3, 22, 24]), // 28
    op("s3h dl_b", B, &[26]),                              // 29
    op("s3h d1_b", B, &[28]),                              // 30
    op("dn_l,b", B, &[25, 29]),                            // 31
    op("dn_l,c", B, &[25, 29]),                            // 32
    op("dn_1,b", B, &[27, 30]),                            // 33
    op("dn_1,c", B, &[27, 30]),                            // 34
    op("s3h i_b", B, &[0]),                                // 35
    op("i_b", B, &[35]),                                   // 36
    op("i_c", B, &[35]),                                   // 37
    op("e_a = i*_a - i_a", B, &[0]),                       // 38
    op("e_b' = i*_b - i_b", B, &[0]),                      // 39
    op("s3h e_b'", B, &[39]),                              // 40
    op("e_b", B, &[38, 40]),                               // 41
    op("e_c", B, &[38, 40]),                               // 42
    op("e_vn = -v_n", B, &[0]),                            // 43
    op("e_ph,a", B, &[0]),                                 // 44
    op("e_ph,b", B, &[0]),                                 // 45
    op("e_ph,c", B, &[0]),                                 // 46
    op("P_n,a = c_n i_a", B, &[0]),                        // 47
    op("P_n,b", B, &[36]),                                 // 48
    op("P_n,c", B, &[37]),                                 // 49
    op("P_ph,a = c_ph i_a", B, &[0]),                      // 50
    op("P_ph,b", B, &[36]),                                // 51
    op("P_ph,c", B, &[37]),                                // 52
    op("v_a(s_prev) = ph v_ph,a + mux(rail Vdc/2 | v_n)", B, &[0]), // 53
    op("v_b(s_prev) = ph v_ph,b + mux(rail Vdc/2 | v_n)", B, &[0]), // 54
    op("v_c(s_prev) = ph v_ph,c + mux(rail Vdc/2 | v_n)", B, &[0]), // 55
    op("sum = v_a + v_b", B, &[47, 48, 49, 50, 51, 53, 54]), // 56
    op("sum += v_c", B, &[47, 48, 49, 52, 55, 56]),        // 57
    op("u_a = 3 v_a - sum", B, &[47, 48, 49, 50, 53, 57]), // 58
    op("u_b", B, &[47, 48, 49, 51, 54, 57]),               // 59
    op("u_c", B, &[47, 48, 49, 52, 55, 57]),               // 60
    op("e1_a = e_a + dn_1,a - g3 u_a / L", B, &[27, 38, 58]), // 61
    op("e1_b", B, &[33, 41, 59]),                          // 62
    op("e1_c", B, &[34, 42, 60]),                          // 63
    op("e1_vn = e_vn + np_a P_n,a / L", B, &[43, 47]),     // 64
    op("e1_vn += np_b P_n,b / L", B, &[48, 64]),           // 65
    op("e1_vn += np_c P_n,c / L", B, &[49, 65]),           // 66
    op("e1_ph,a = e_ph,a - c P_ph,a / L", B, &[44, 50]),   // 67
    op("e1_ph,b", B, &[45, 51]),                           // 68
    op("e1_ph,c", B, &[46, 52]),                           // 69
    op(
        "7 bound compares, AND (lazy check)",
        Reg,
        &[
            0, 1, 2, 3, 7, 8, 11, 12, 23, 24, 31, 32, 61, 62, 63, 66, 67, 68, 69,
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
