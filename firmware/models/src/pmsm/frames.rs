//! Reference frames (the transforms are [`crate::frames`]'s) and inverter
//! switch states.
//!
//! - Clarke transform: amplitude-invariant, `x_alpha = (2/3)(a - (b+c)/2)`,
//!   `x_beta = (b - c)/sqrt(3)`; a balanced set of amplitude X gives |x_ab| = X.
//! - Park transform: `theta_e` is the electrical angle from the alpha axis
//!   (phase a) to the d axis (angle 0 = d axis on phase a), so
//!   `x_d = cos(th) x_alpha + sin(th) x_beta`, `x_q = -sin(th) x_alpha + cos(th) x_beta`.
//!   Paper eq. (9) prints the rotation matrix transposed (it would map dq to
//!   alpha-beta); we use the standard direction, which is what eq. (1) needs.
//! - Switch state: bits `SaSbSc`, `Sx = 1` = upper switch of leg x on, index
//!   `4 Sa + 2 Sb + Sc` (0..=7). Leg x is at `Sx * U_dc` w.r.t. the negative rail.
//!
//! Interpretation of eq. (9): the paper lists the active vectors with magnitude
//! `U_dc`; with the amplitude-invariant transform the physical magnitude is
//! `2/3 U_dc` (phase voltages to the star point `U_dc (Sx - (Sa+Sb+Sc)/3)`).
//! We use the physical value everywhere (plant and controllers).

pub use crate::frames::{clarke, inv_clarke, inv_park, inv_park_sc, park, park_sc, sc_add};

/// Leg states of switch state `s` (index `4 Sa + 2 Sb + Sc`): `[Sa, Sb, Sc]`.
/// Only the low 3 bits are used.
pub fn legs(s: u8) -> [u8; 3] {
    [(s >> 2) & 1, (s >> 1) & 1, s & 1]
}

/// Switch state index from leg states (each 0 or 1; other bits ignored).
pub fn state_from_legs(l: [u8; 3]) -> u8 {
    ((l[0] & 1) << 2) | ((l[1] & 1) << 1) | (l[2] & 1)
}

/// Stator voltage `(u_alpha, u_beta)` in V of switch state `s` at DC-link `u_dc_v`:
/// `u_alpha = U_dc (2 Sa - Sb - Sc) / 3`, `u_beta = U_dc (Sb - Sc) / sqrt(3)`.
pub fn switch_state_alpha_beta(s: u8, u_dc_v: f64) -> (f64, f64) {
    let [a, b, c] = legs(s);
    leg_voltage_alpha_beta([a as f64, b as f64, c as f64], u_dc_v)
}

/// Stator voltage of leg potentials given as fractions of `U_dc` (0..1 each,
/// e.g. duties averaged over a period), V.
pub fn leg_voltage_alpha_beta(leg_frac: [f64; 3], u_dc_v: f64) -> (f64, f64) {
    let (a, b) = clarke(leg_frac);
    (a * u_dc_v, b * u_dc_v)
}

/// Number of legs that change between switch states `from` and `to` (0..=3).
pub fn legs_switched(from: u8, to: u8) -> u32 {
    ((from ^ to) & 0b111).count_ones()
}

/// Formats switch state `s` as the three characters `SaSbSc`, e.g. `b"101"`.
pub fn state_bits(s: u8) -> [u8; 3] {
    let l = legs(s);
    [b'0' + l[0], b'0' + l[1], b'0' + l[2]]
}

/// Parses exactly three characters `0`/`1` (`SaSbSc`) into a switch state.
pub fn parse_state_bits(s: &str) -> Option<u8> {
    let b = s.as_bytes();
    if b.len() != 3 || !b.iter().all(|&c| c == b'0' || c == b'1') {
        return None;
    }
    Some(state_from_legs([b[0] - b'0', b[1] - b'0', b[2] - b'0']))
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn clarke_is_amplitude_invariant_and_park_aligns_d_with_phase_a() {
        // Balanced set cos(wt), cos(wt - 2pi/3), cos(wt + 2pi/3) with amplitude 2.
        for k in 0..12 {
            let th = k as f64 * 0.5;
            let abc = [
                2.0 * th.cos(),
                2.0 * (th - 2.0 * PI / 3.0).cos(),
                2.0 * (th + 2.0 * PI / 3.0).cos(),
            ];
            let (al, be) = clarke(abc);
            assert!((al - 2.0 * th.cos()).abs() < 1e-12);
            assert!((be - 2.0 * th.sin()).abs() < 1e-12);
            // Rotating with the vector: d = 2, q = 0.
            let (d, q) = park(al, be, th);
            assert!((d - 2.0).abs() < 1e-12 && q.abs() < 1e-12);
            let (a2, b2) = inv_park(d, q, th);
            assert!((a2 - al).abs() < 1e-12 && (b2 - be).abs() < 1e-12);
            let back = inv_clarke(al, be);
            for i in 0..3 {
                assert!((back[i] - abc[i]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn switch_state_vectors_hand_computed() {
        let u = 48.0;
        let r3 = 3f64.sqrt();
        // (state, alpha, beta) in units of U_dc: hexagon of radius 2/3.
        let want = [
            (0b000, 0.0, 0.0),
            (0b100, 2.0 / 3.0, 0.0),
            (0b110, 1.0 / 3.0, 1.0 / r3),
            (0b010, -1.0 / 3.0, 1.0 / r3),
            (0b011, -2.0 / 3.0, 0.0),
            (0b001, -1.0 / 3.0, -1.0 / r3),
            (0b101, 1.0 / 3.0, -1.0 / r3),
            (0b111, 0.0, 0.0),
        ];
        for (s, a, b) in want {
            let (ua, ub) = switch_state_alpha_beta(s, u);
            assert!(
                (ua - a * u).abs() < 1e-12 && (ub - b * u).abs() < 1e-12,
                "{s:03b}"
            );
        }
        assert_eq!(legs(0b110), [1, 1, 0]);
        assert_eq!(state_from_legs([1, 0, 1]), 5);
        assert_eq!(legs_switched(0b000, 0b111), 3);
        assert_eq!(legs_switched(0b101, 0b100), 1);
        assert_eq!(parse_state_bits("101"), Some(5));
        assert_eq!(&state_bits(5), b"101");
        for bad in ["", "10", "1010", "102", " 01", "abc"] {
            assert_eq!(parse_state_bits(bad), None, "{bad:?}");
        }
    }
}
