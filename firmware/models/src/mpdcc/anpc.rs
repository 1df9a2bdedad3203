//! Five-level ANPC phase leg: the 8 switch positions, their output voltage,
//! their effect on the neutral point potential `v_n` and the phase capacitor
//! voltage `v_ph` (the `B_inv(s)` of paper 001 eq. 2), admissible transitions
//! and the switching-transition count `f_s`.
//!
//! # Topology (our derivation; the paper defers to its ref. [16])
//!
//! DC link: a stiff source `V_dc` between rails P (`+V_dc/2`) and M
//! (`-V_dc/2`), split by two equal capacitors `C_dc`; their midpoint N sits
//! at `v_n` (the neutral point potential, 0 when balanced). Each phase leg
//! has two stages, each pair of devices driven complementarily:
//!
//! ```text
//!  P --S1--+                 stage 1 (d1): X,Y = P,N (d1=1) or N,M (d1=0)
//!  N --S2--+-- X --S5-- T --S7--+
//!                      |C_ph|    +-- O (phase output)
//!  N --S3--+-- Y --S6-- B --S8--+
//!  M --S4--+                 stage 2: d2 selects S5 (1) / S6 (0),
//!                                     d3 selects S7 (1) / S8 (0)
//! ```
//!
//! The phase capacitor sits between T and B, `v_ph = v_T - v_B`, nominally
//! `V_dc/4`. Walking the conduction path from the selected input node to O:
//!
//! | s | d1 d2 d3 | path | output voltage | level | NP current | dv_ph/dt * C_ph |
//! |---|---|---|---|---|---|---|
//! | 0 | 0 0 0 | M-Y-B-O | `-V_dc/2` | -2 | 0 | 0 |
//! | 1 | 0 0 1 | M-Y-B-C-T-O | `-V_dc/2 + v_ph` | -1 | 0 | `-i` |
//! | 2 | 0 1 0 | N-X-T-C-B-O | `v_n - v_ph` | -1 | `i` | `+i` |
//! | 3 | 0 1 1 | N-X-T-O | `v_n` | 0 | `i` | 0 |
//! | 4 | 1 0 0 | N-Y-B-O | `v_n` | 0 | `i` | 0 |
//! | 5 | 1 0 1 | N-Y-B-C-T-O | `v_n + v_ph` | +1 | `i` | `-i` |
//! | 6 | 1 1 0 | P-X-T-C-B-O | `V_dc/2 - v_ph` | +1 | 0 | `+i` |
//! | 7 | 1 1 1 | P-X-T-O | `+V_dc/2` | +2 | 0 | 0 |
//!
//! (`i` = phase current, positive out of the leg into the machine; "NP
//! current" = current drawn out of node N.) The index is `s = 4 d1 + 2 d2 + d3`,
//! so the level is monotonic in `s`. Levels -1, 0, +1 have two positions each:
//! these redundancies balance `v_n` and `v_ph`.
//!
//! Capacitor dynamics in normalized time (pu): with a stiff `V_dc` the two
//! dc-link capacitor voltages move in opposite directions, so a current
//! `i_N` drawn out of N gives `dv_n/dt = -i_N / (2 C_dc)`. The phase
//! capacitor: `dv_ph,x/dt = c(s_x) i_x / C_ph` with `c` from the last column.
//! Energy check (tested): the power the capacitors give up equals the
//! `v_n`/`v_ph` part of the power delivered to the machine.
//!
//! # Decisions
//! - **Admissible transitions**: "one phase level up or down" (paper, Sec.
//!   III-B) is read as `|level(s') - level(s)| <= 1` in every phase; moving
//!   between redundant positions of the same level is allowed (it is how the
//!   capacitors are balanced). Up to 6 positions per phase, 216 candidates.
//! - **f_s counts device turn-ons**: each flip of `d2` or `d3` turns one device
//!   on (and its partner off); a flip of `d1` turns two devices on (S1/S2 and
//!   S3/S4). The paper's dependence of `f_s` on the stator current (through
//!   the ANPC's clamping details of ref. [16]) is not modelled.
//! - **Devices**: 8 per phase, 24 in total; the switching frequency per
//!   semiconductor is `sum f_s / (24 * duration)` (see `stats`).
#![allow(clippy::needless_range_loop)] // index loops mirror the matrix equations

/// Number of switch positions per phase.
pub const POSITIONS: usize = 8;
/// Semiconductors per phase (S1..S8).
pub const DEVICES_PER_PHASE: u32 = 8;
/// Semiconductors in the three-phase inverter.
pub const DEVICES_TOTAL: u32 = 3 * DEVICES_PER_PHASE;

/// Electrical effect of one switch position (one row of the table above).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Position {
    /// Output level, -2..=2 (in units of `V_dc/4`).
    pub level: i8,
    /// Constant part of the output voltage in units of `V_dc/2`: -1, 0, +1.
    pub rail: i8,
    /// Coefficient of `v_n` in the output voltage (1 when O connects to N).
    pub n_coef: i8,
    /// Coefficient of `v_ph` in the output voltage.
    pub ph_coef: i8,
    /// NP current drawn out of N per unit phase current (0 or 1).
    pub np_current: i8,
    /// Phase capacitor charging current per unit phase current (-1, 0, +1).
    pub ph_current: i8,
}

/// Switch signals `(d1, d2, d3)` of position `s` (s = 4 d1 + 2 d2 + d3).
pub const fn signals(s: u8) -> (bool, bool, bool) {
    (s & 4 != 0, s & 2 != 0, s & 1 != 0)
}

/// Derives a position's electrical effect by walking the topology (see the
/// module docs): this is the derivation, [`TABLE`] is its written-down result.
pub const fn derive(s: u8) -> Position {
    let (d1, d2, d3) = signals(s);
    // Input nodes of stage 2: X = P or N, Y = N or M, as (rail, is_n).
    let (x_rail, x_is_n) = if d1 { (1, 0) } else { (0, 1) };
    let (y_rail, y_is_n) = if d1 { (0, 1) } else { (-1, 0) };
    // Stage 2: d2 picks the input (S5 from X to T, or S6 from Y to B);
    // d3 picks the output node (S7 from T, or S8 from B).
    let (rail, n_coef, ph_coef, ph_current) = match (d2, d3) {
        (true, true) => (x_rail, x_is_n, 0, 0),   // X-T-O
        (true, false) => (x_rail, x_is_n, -1, 1), // X-T-C-B-O: O = X - v_ph, charges C
        (false, true) => (y_rail, y_is_n, 1, -1), // Y-B-C-T-O: O = Y + v_ph, discharges C
        (false, false) => (y_rail, y_is_n, 0, 0), // Y-B-O
    };
    // Level in units of V_dc/4 at nominal v_n = 0, v_ph = V_dc/4.
    let level = 2 * rail + ph_coef;
    Position {
        level,
        rail,
        n_coef,
        ph_coef,
        np_current: n_coef,
        ph_current,
    }
}

/// The switch position table, written out by hand (tested equal to [`derive`]).
pub const TABLE: [Position; POSITIONS] = [
    Position {
        level: -2,
        rail: -1,
        n_coef: 0,
        ph_coef: 0,
        np_current: 0,
        ph_current: 0,
    },
    Position {
        level: -1,
        rail: -1,
        n_coef: 0,
        ph_coef: 1,
        np_current: 0,
        ph_current: -1,
    },
    Position {
        level: -1,
        rail: 0,
        n_coef: 1,
        ph_coef: -1,
        np_current: 1,
        ph_current: 1,
    },
    Position {
        level: 0,
        rail: 0,
        n_coef: 1,
        ph_coef: 0,
        np_current: 1,
        ph_current: 0,
    },
    Position {
        level: 0,
        rail: 0,
        n_coef: 1,
        ph_coef: 0,
        np_current: 1,
        ph_current: 0,
    },
    Position {
        level: 1,
        rail: 0,
        n_coef: 1,
        ph_coef: 1,
        np_current: 1,
        ph_current: -1,
    },
    Position {
        level: 1,
        rail: 1,
        n_coef: 0,
        ph_coef: -1,
        np_current: 0,
        ph_current: 1,
    },
    Position {
        level: 2,
        rail: 1,
        n_coef: 0,
        ph_coef: 0,
        np_current: 0,
        ph_current: 0,
    },
];

/// Output voltage of one phase w.r.t. the dc-link midpoint, pu.
#[inline]
pub fn phase_voltage(s: u8, v_dc: f64, v_n: f64, v_ph: f64) -> f64 {
    let p = &TABLE[(s & 7) as usize];
    p.rail as f64 * 0.5 * v_dc + p.n_coef as f64 * v_n + p.ph_coef as f64 * v_ph
}

/// Three-phase output voltages `v_abc(s)`, pu.
#[inline]
pub fn output_voltages(s: [u8; 3], v_dc: f64, v_n: f64, v_ph: [f64; 3]) -> [f64; 3] {
    [
        phase_voltage(s[0], v_dc, v_n, v_ph[0]),
        phase_voltage(s[1], v_dc, v_n, v_ph[1]),
        phase_voltage(s[2], v_dc, v_n, v_ph[2]),
    ]
}

/// `B_inv(s)` of eq. (2): rows `[v_n, v_ph,a, v_ph,b, v_ph,c]`, columns
/// `[i_a, i_b, i_c]`, in 1/pu-capacitance (multiply by `T_s,pu` and the
/// phase currents to get the per-step change).
pub fn b_inv(s: [u8; 3], c_dc: f64, c_ph: f64) -> [[f64; 3]; 4] {
    let mut b = [[0.0; 3]; 4];
    for x in 0..3 {
        let p = &TABLE[(s[x] & 7) as usize];
        b[0][x] = -(p.np_current as f64) / (2.0 * c_dc);
        b[1 + x][x] = p.ph_current as f64 / c_ph;
    }
    b
}

/// Applies eq. (2) once: `x_inv += T_s,pu B_inv(s) i_abc` (currents held constant).
#[inline]
pub fn inverter_euler_step(
    x_inv: &mut [f64; 4],
    s: [u8; 3],
    i_abc: [f64; 3],
    ts_pu: f64,
    c_dc: f64,
    c_ph: f64,
) {
    let mut i_n = 0.0;
    for x in 0..3 {
        let p = &TABLE[(s[x] & 7) as usize];
        i_n += p.np_current as f64 * i_abc[x];
        x_inv[1 + x] += ts_pu * p.ph_current as f64 * i_abc[x] / c_ph;
    }
    x_inv[0] -= ts_pu * i_n / (2.0 * c_dc);
}

/// Whether `to` may follow `from` in one phase: at most one level up or down.
#[inline]
pub fn admissible_phase(from: u8, to: u8) -> bool {
    if from > 7 || to > 7 {
        return false;
    }
    (TABLE[from as usize].level - TABLE[to as usize].level).abs() <= 1
}

/// Whether the three-phase transition `from -> to` is admissible.
pub fn admissible(from: [u8; 3], to: [u8; 3]) -> bool {
    (0..3).all(|x| admissible_phase(from[x], to[x]))
}

/// Device turn-ons of the transition `from -> to` in one phase.
#[inline]
pub fn phase_transitions(from: u8, to: u8) -> u32 {
    let d = (from ^ to) & 7;
    2 * ((d >> 2) & 1) as u32 + ((d >> 1) & 1) as u32 + (d & 1) as u32
}

/// `f_s(s1, s2)`: device turn-ons of a three-phase transition.
pub fn switch_transitions(from: [u8; 3], to: [u8; 3]) -> u32 {
    (0..3).map(|x| phase_transitions(from[x], to[x])).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_equals_topology_derivation() {
        for s in 0..8u8 {
            assert_eq!(TABLE[s as usize], derive(s), "position {s}");
        }
        // Levels: monotonic in s, with the 1-2-2-2-1 redundancy pattern.
        let levels: [i8; 8] = core::array::from_fn(|s| TABLE[s].level);
        assert_eq!(levels, [-2, -1, -1, 0, 0, 1, 1, 2]);
    }

    #[test]
    fn nominal_voltages_are_five_equidistant_levels() {
        let vdc = 1.93;
        for s in 0..8u8 {
            let v = phase_voltage(s, vdc, 0.0, vdc / 4.0);
            let expect = TABLE[s as usize].level as f64 * vdc / 4.0;
            assert!((v - expect).abs() < 1e-12, "s={s}: {v} vs {expect}");
        }
    }

    /// Energy: with `v_n`, `v_ph` perturbed, the extra power delivered to
    /// the load equals the power given up by the dc-link and phase capacitors,
    /// `-(d/dt)(C_dc v_n^2 + sum C_ph v_ph^2 / 2)` (the dc-link part: the two
    /// capacitors hold `C/2 (V/2 -+ v_n)^2`, whose v_n-dependent sum is `C v_n^2`).
    #[test]
    fn capacitor_energy_balances_output_power() {
        let (vdc, cdc, cph) = (1.93, 11.769, 4.0);
        let i = [0.7, -0.2, -0.5];
        let (vn, vph) = (0.03, [0.47, 0.5, 0.49]);
        for code in 0..512u32 {
            let s = [
                (code & 7) as u8,
                ((code >> 3) & 7) as u8,
                ((code >> 6) & 7) as u8,
            ];
            let v = output_voltages(s, vdc, vn, vph);
            let v0 = output_voltages(s, vdc, 0.0, [0.0; 3]);
            let p_extra: f64 = (0..3).map(|x| (v[x] - v0[x]) * i[x]).sum();
            let b = b_inv(s, cdc, cph);
            let dvn: f64 = (0..3).map(|x| b[0][x] * i[x]).sum();
            let mut de = 2.0 * cdc * vn * dvn;
            for x in 0..3 {
                de += cph * vph[x] * b[1 + x][x] * i[x];
            }
            assert!((p_extra + de).abs() < 1e-12, "s={s:?}: {p_extra} vs {de}");
        }
    }

    #[test]
    fn admissible_is_one_level_and_counts_candidates() {
        let counts: [usize; 8] =
            core::array::from_fn(|f| (0..8u8).filter(|&t| admissible_phase(f as u8, t)).count());
        assert_eq!(counts, [3, 5, 5, 6, 6, 5, 5, 3]);
        assert!(!admissible_phase(0, 3));
        assert!(admissible_phase(3, 4));
        assert!(!admissible_phase(8, 0));
    }

    #[test]
    fn transition_counts_by_hand() {
        assert_eq!(phase_transitions(3, 3), 0);
        assert_eq!(phase_transitions(0, 1), 1); // d3 only
        assert_eq!(phase_transitions(1, 2), 2); // d2 and d3: redundant swap
        assert_eq!(phase_transitions(3, 4), 4); // d1 (2 devices) + d2 + d3
        assert_eq!(phase_transitions(2, 4), 3); // d1 + d2
        assert_eq!(switch_transitions([0, 3, 7], [1, 4, 6]), 1 + 4 + 1);
    }

    #[test]
    fn euler_step_matches_b_inv() {
        let s = [2, 5, 6];
        let i = [0.3, 0.6, -0.9];
        let mut x = [0.01, 0.48, 0.49, 0.47];
        let x0 = x;
        inverter_euler_step(&mut x, s, i, 0.01, 11.769, 4.0);
        let b = b_inv(s, 11.769, 4.0);
        for r in 0..4 {
            let d: f64 = (0..3).map(|c| b[r][c] * i[c]).sum();
            assert!((x[r] - x0[r] - 0.01 * d).abs() < 1e-15);
        }
    }
}
