//! Checks that need a window of evidence, not one sample: a dead encoder
//! (the motor turns, the count does not) and an open phase (a phase
//! current stays at zero while the reference says it must not). A
//! transient (a torque step, a reversal) is no fault, so each needs its
//! condition for a whole window of [`WINDOW_S`]; the gates go off in the
//! control step that completes the window.
//!
//! Dead encoder, and why a locked rotor does not trip it: with the count
//! standing still, the rotor's motion shows in the back-EMF. Over the
//! window, the stator's voltage equation `u = R i + L di/dt + e` summed
//! period by period telescopes: `mean(e) = mean(u) - R mean(i) - L (i_end -
//! i_start) / T_window` (alpha-beta vectors; `u` the voltage applied in
//! each period, from the duties or the switching state). The window is
//! contiguous: leaving a period out would leave its share of the applied
//! voltage, which the measurement's timing spreads over its neighbours, in
//! the sums (volts of error with the MPDTC's switching). A held rotor has
//! `e = 0`: only the applied voltage's errors (dead time, about 0.5 V here)
//! remain, below [`EMF_MIN_V`]. A rotor that turns at `w_e` has `|e| = w_e
//! psi`; a healthy encoder counts at least once per window from
//! `w_m = 2 pi / (cpr T_window)` on (3.1 rad/s at 4096 counts and 0.5 ms,
//! `e` = 0.2 V with the paper's motor): far below the threshold, so a
//! window with `|mean(e)| > EMF_MIN_V` and no count is a dead encoder. The
//! threshold is a speed: `EMF_MIN_V / psi` (161 rad/s electrical, 3.7
//! rev/s with the paper's motor); slower, a dead encoder is not seen.
//! The window is short against an electrical turn: the mean of a vector
//! turning by `w_e T_window` shrinks by at most 4 % below 1000 rad/s
//! electrical (about 17 % at 2000 rad/s).
//!
//! Open phase: the reference current vector (`i_d = 0`, `i_q` from the
//! torque reference) projected on phase `x`'s axis is at least
//! [`REF_MIN_A`] while the measured `|i_x|` stays at most [`ZERO_MAX_A`]
//! (10 ADC counts) in every period of the window, with current in another
//! phase (all three at zero is no one phase's fault). A healthy current loop
//! follows a step well within the window; a locked rotor carries its
//! current in every phase whose reference needs it.

/// Window of both checks, s.
pub const WINDOW_S: f64 = 0.5e-3;
/// Back-EMF magnitude that proves motion, V.
pub const EMF_MIN_V: f64 = 1.5;
/// Reference phase current that must show, A.
pub const REF_MIN_A: f64 = 1.0;
/// A phase current this small is zero, A.
pub const ZERO_MAX_A: f64 = 0.1;

/// Control periods in the window at `period_s` (at least 2).
pub fn window_periods(period_s: f64) -> u32 {
    let n = libm::ceil(WINDOW_S / period_s);
    if n.is_finite() && n >= 2.0 {
        n.min(1e6) as u32
    } else {
        2
    }
}

/// The dead-encoder check's state.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EncoderDead {
    last_pos: Option<u32>,
    /// Periods summed since the last count (or the last window).
    n: u32,
    sum_u: (f64, f64),
    sum_i: (f64, f64),
    i_start: (f64, f64),
}

impl EncoderDead {
    /// Starts afresh (gates off, mode change, a stall).
    pub fn reset(&mut self) {
        *self = Self::default();
    }

    /// One control period: encoder count `pos`, the voltage `u` applied
    /// during the period the current `i` (both alpha-beta, V and A) was
    /// measured over, whether a phase looks open in it (`suspect`), the
    /// motor's `r_ohm` and `l_h`, the period `ts_s` and the window `m` in
    /// periods. True: a dead encoder.
    ///
    /// A phase that looks open voids the voltage equation (its terminal
    /// floats away from the applied voltage), so a window does not close
    /// in such a period: it waits one period more (a dead encoder's wrong
    /// angle makes a healthy phase's zero crossing look open for a period)
    /// and is given up when that one looks open too (an open phase, which
    /// its own check reports).
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &mut self,
        pos: u32,
        u: (f64, f64),
        i: (f64, f64),
        suspect: bool,
        r_ohm: f64,
        l_h: f64,
        ts_s: f64,
        m: u32,
    ) -> bool {
        if self.last_pos != Some(pos) {
            self.last_pos = Some(pos);
            self.restart(i);
            return false;
        }
        self.n += 1;
        self.sum_u.0 += u.0;
        self.sum_u.1 += u.1;
        self.sum_i.0 += i.0;
        self.sum_i.1 += i.1;
        if self.n < m || (suspect && self.n == m) {
            return false;
        }
        if suspect {
            self.restart(i);
            return false;
        }
        let n = f64::from(self.n);
        let t = n * ts_s;
        let e = |su: f64, si: f64, i1: f64, i0: f64| su / n - r_ohm * si / n - l_h * (i1 - i0) / t;
        let ea = e(self.sum_u.0, self.sum_i.0, i.0, self.i_start.0);
        let eb = e(self.sum_u.1, self.sum_i.1, i.1, self.i_start.1);
        self.restart(i);
        libm::sqrt(ea * ea + eb * eb) > EMF_MIN_V
    }

    fn restart(&mut self, i: (f64, f64)) {
        self.n = 0;
        self.sum_u = (0.0, 0.0);
        self.sum_i = (0.0, 0.0);
        self.i_start = i;
    }
}

/// The open-phase check's state: periods in a row each phase looked open.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PhaseOpen {
    n: [u32; 3],
}

impl PhaseOpen {
    /// Starts afresh.
    pub fn reset(&mut self) {
        *self = Self::default();
    }

    /// A phase looks open this period (its count runs): the voltage
    /// equation of the dead-encoder check does not hold then (the open
    /// terminal floats away from its duty).
    pub fn suspect(&self) -> bool {
        self.n.iter().any(|&n| n > 0)
    }

    /// One control period: reference and measured phase currents, A, and
    /// the window `m` in periods. The open phase (0 = a), if any.
    pub fn step(&mut self, i_ref: [f64; 3], i: [f64; 3], m: u32) -> Option<usize> {
        let mut open = None;
        // One open phase leaves the current to the other two; no current
        // in any phase is no phase's evidence (nothing is driven at all).
        if !i.iter().any(|&x| libm::fabs(x) > ZERO_MAX_A) {
            self.n = [0; 3];
            return None;
        }
        for x in 0..3 {
            if libm::fabs(i_ref[x]) >= REF_MIN_A && libm::fabs(i[x]) <= ZERO_MAX_A {
                self.n[x] += 1;
                if self.n[x] >= m && open.is_none() {
                    open = Some(x);
                }
            } else {
                self.n[x] = 0;
            }
        }
        open
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TS: f64 = 62.56e-6;

    #[test]
    fn window_is_half_a_millisecond_in_periods() {
        assert_eq!(window_periods(TS), 8);
        assert_eq!(window_periods(1564e-8), 32);
        assert_eq!(window_periods(1.0), 2);
        assert_eq!(window_periods(f64::NAN), 2);
    }

    /// A held rotor: `u = R i` (plus 0.5 V of dead-time error) with a
    /// still count never trips; the same count with a back-EMF of 2 V
    /// (the voltage a turning rotor needs) trips at the window's end.
    #[test]
    fn back_emf_with_a_still_count_is_a_dead_encoder_and_a_held_rotor_is_not() {
        let (r, l, m) = (0.555, 0.64e-3, 8);
        let i = (0.0, 5.0);
        let mut held = EncoderDead::default();
        for _ in 0..100 {
            assert!(!held.step(7, (0.5, r * 5.0 + 0.3), i, false, r, l, TS, m));
        }
        let mut dead = EncoderDead::default();
        assert!(!dead.step(7, (0.0, 0.0), i, false, r, l, TS, m));
        for k in 1..m {
            assert!(!dead.step(7, (2.0, r * 5.0), i, false, r, l, TS, m), "{k}");
        }
        assert!(dead.step(7, (2.0, r * 5.0), i, false, r, l, TS, m));
        // A count starts the window again.
        assert!(!dead.step(8, (2.0, r * 5.0), i, false, r, l, TS, m));
    }

    /// A current rising at 1 A per period under `u = L di/dt`: no
    /// back-EMF (the `L` term takes the voltage), no trip.
    #[test]
    fn a_current_step_is_not_back_emf() {
        let (r, l, m) = (0.555, 0.64e-3, 8);
        let mut d = EncoderDead::default();
        let mut i = 0.0;
        d.step(0, (0.0, 0.0), (0.0, i), false, r, l, TS, m);
        for _ in 0..3 * m {
            let u = r * (i + 1.0) + l * 1.0 / TS;
            i += 1.0;
            assert!(!d.step(0, (0.0, u), (0.0, i), false, r, l, TS, m));
        }
    }

    /// A window does not close in a period where a phase looks open: one
    /// such period (a healthy phase's zero crossing under a dead encoder's
    /// wrong angle) delays the verdict by one period; two (an opening
    /// phase, its terminal floating) give the window up.
    #[test]
    fn a_phase_looking_open_at_the_close_delays_the_window_by_one_period() {
        let (r, l, m) = (0.555, 0.64e-3, 8);
        let i = (0.0, 5.0);
        let mut dead = EncoderDead::default();
        dead.step(7, (0.0, 0.0), i, false, r, l, TS, m);
        for k in 1..m {
            assert!(!dead.step(7, (2.0, r * 5.0), i, k == 4, r, l, TS, m));
        }
        assert!(!dead.step(7, (2.0, r * 5.0), i, true, r, l, TS, m));
        assert!(dead.step(7, (2.0, r * 5.0), i, false, r, l, TS, m));
        // A held rotor whose phase opens: 40 V off in the period before
        // the suspect ones, at the end of a window.
        let mut held = EncoderDead::default();
        held.step(7, (0.0, 0.0), i, false, r, l, TS, m);
        for k in 1..3 * m {
            let u = if k == 2 * m - 2 {
                (40.0, r * 5.0)
            } else {
                (0.0, r * 5.0)
            };
            assert!(!held.step(7, u, i, k > 2 * m - 2, r, l, TS, m), "{k}");
        }
    }

    #[test]
    fn a_phase_at_zero_against_its_reference_for_a_window_is_open() {
        let m = 8;
        let mut p = PhaseOpen::default();
        // Phase a's reference is 0 (angle 0, pure q): a is not open.
        let r = [0.0, 1.73, -1.73];
        for _ in 0..20 {
            assert_eq!(p.step(r, [0.0, 1.7, -1.7], m), None);
        }
        // Phase b stays at 0.05 A against 1.73 A.
        for _ in 1..m {
            assert_eq!(p.step(r, [1.7, 0.05, -1.7], m), None);
        }
        assert_eq!(p.step(r, [1.7, 0.05, -1.7], m), Some(1));
        // One period with current starts the count again.
        p.step(r, [0.0, 1.7, -1.7], m);
        assert_eq!(p.step(r, [1.7, 0.05, -1.7], m), None);
        // A small reference is no evidence.
        let mut q = PhaseOpen::default();
        for _ in 0..20 {
            assert_eq!(q.step([0.9, -0.45, -0.45], [0.0; 3], m), None);
        }
    }
}
