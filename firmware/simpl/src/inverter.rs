//! The inverter between the gate outputs and the plant: leg potentials
//! from the six gate levels and the phase currents.
//!
//! A leg with its upper gate on is at `U_dc`, with its lower gate on at 0.
//! With both off (dead time, or gates disabled) the current flows through a
//! diode: the lower one (leg at 0) for `i_x > 0`, the upper one (`U_dc`) for
//! `i_x < 0` (the convention of `pmsm::plant`), judged at the start of each
//! segment. A leg with both gates off and (nearly) no current floats.
//! With all six gates off and every phase current below
//! [`OPEN_CIRCUIT_A`], the motor is disconnected: the currents stay 0 (valid
//! while the line-to-line back-EMF stays below `U_dc`).

/// Below this current (A) in every phase, all gates off = open circuit.
pub const OPEN_CIRCUIT_A: f64 = 0.05;

/// Leg potential, fraction of `U_dc`; `None` = floating.
pub fn leg_potential(hi: bool, lo: bool, i_a: f64, all_off: bool) -> Option<f64> {
    let eps = if all_off { OPEN_CIRCUIT_A } else { 1e-9 };
    if hi {
        Some(1.0)
    } else if lo || i_a > eps {
        Some(0.0)
    } else if i_a < -eps {
        Some(1.0)
    } else {
        None
    }
}

/// Leg potentials of legs a, b, c for gate vectors `hi`, `lo` (bit 2 = leg
/// a) and phase currents `i_abc`; a floating leg takes the mean of the
/// others (it carries no current, so it does not matter to the others).
/// `None`: every leg floats (open circuit).
pub fn potentials(hi: u8, lo: u8, i_abc: [f64; 3]) -> Option<[f64; 3]> {
    let all_off = hi == 0 && lo == 0;
    let p: [Option<f64>; 3] = core::array::from_fn(|x| {
        let bit = 2 - x;
        leg_potential(hi >> bit & 1 == 1, lo >> bit & 1 == 1, i_abc[x], all_off)
    });
    let (sum, n) = p
        .iter()
        .flatten()
        .fold((0.0, 0u32), |(s, n), v| (s + v, n + 1));
    if n == 0 {
        return None;
    }
    let mean = sum / n as f64;
    Some(p.map(|v| v.unwrap_or(mean)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gates_diodes_and_open_circuit() {
        // 100 driven: a up, b and c down.
        assert_eq!(potentials(0b100, 0b011, [0.0; 3]), Some([1.0, 0.0, 0.0]));
        // Dead time on leg a: lower diode for i_a > 0, upper for i_a < 0.
        assert_eq!(
            potentials(0, 0b011, [2.0, -1.0, -1.0]),
            Some([0.0, 0.0, 0.0])
        );
        assert_eq!(
            potentials(0, 0b011, [-2.0, 1.0, 1.0]),
            Some([1.0, 0.0, 0.0])
        );
        // All off with current: every leg on a diode.
        assert_eq!(potentials(0, 0, [3.0, -1.0, -2.0]), Some([0.0, 1.0, 1.0]));
        // All off, no current: open circuit.
        assert_eq!(potentials(0, 0, [0.01, -0.005, -0.005]), None);
        // Leg a floating (no current) while b, c conduct: mean of b and c.
        assert_eq!(
            potentials(0b010, 0b001, [0.0, -1.0, 1.0]),
            Some([0.5, 1.0, 0.0])
        );
    }
}
