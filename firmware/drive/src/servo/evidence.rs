//! The open-phase and dead-encoder checks, in two tiers. The fast tier
//! decides on one control period's evidence and turns the gates off at
//! the first step after the cause; where it cannot decide (a phase the
//! model predicts little current in, a rotor slower than its speed), the
//! window tier below decides over [`WINDOW_S`].
//!
//! Fast, open phase: the motor model the MPDTC predicts with
//! (`MpdtcConfig::predict_u`, at the FOC's period in FOC) gives this
//! period's current from the last measured one and the voltage applied in
//! between (the FOC's duties or the MPDTC's switching state); a phase
//! predicted at [`FAST_PRED_MIN_A`] or more that measures at most
//! [`ZERO_MAX_A`] or [`FAST_OPEN_FRACTION`] of its prediction is open. A
//! torque step or a reversal is in the prediction (it follows the applied
//! voltage); a model error of 30 % shows as a fraction of one period's
//! change of current only.
//!
//! Fast, dead encoder: the back-EMF over one period, `e = u - R (i_0 +
//! i_1) / 2 - L (i_1 - i_0) / T` (alpha-beta, angle-free), less what a
//! model off by [`MODEL_TOL`] (`R`) and [`INDUCTIVE_TOL`] (`L`) could put
//! in it and, in FOC, what a measurement's age off by [`FOC_TIMING_TOL`]
//! periods could (that share of the change of voltage between the two
//! periods), gives the counts the rotor turned in the period; their share
//! over the interval the count was seen still must reach the mode's
//! threshold ([`FAST_DEAD_COUNTS`] in FOC, [`MPDTC_DEAD_COUNTS`]). The
//! interval: from the live count at the end of the last step to this
//! step's sample, if that count moved after the last sample (a cause
//! right after a step may follow an edge since that sample), else the
//! whole period; the end read's `BOUNDARY_AGE` gives the share of the
//! period after it. A step that ran past the next boundary (its end read
//! finds the age restarted) may have read the next period's sample, which
//! the next step finds again: the fast tier starts afresh there. A rotor
//! that turns one count moves the count, so the estimate may be off by a
//! factor of two in FOC and 1.25 in MPDTC before a healthy encoder trips.
//! The speed this needs over a whole period: two counts of 4096 per
//! period, 343 rad/s electrical (7.8 rev/s) in FOC (62.56 us), and 1.25
//! counts, 858 rad/s (19.5 rev/s), in MPDTC (15.64 us), with the paper's
//! motor (7 pole pairs, 9.3 mWb), and more while the tolerance's share is
//! large (high current, a current step) or the interval short; the host
//! tests trip at 1.5 times these speeds at 0.5 N m.
//!
//! The window tier: checks that need a window of evidence, not one sample: a dead encoder
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
//! current in every phase whose reference needs it. FOC only: the MPDTC
//! controls the torque, not the d-axis current, so the `i_d = 0` reference
//! does not say which phase must carry current there (a healthy phase
//! stayed at zero for a window during a move on a heavy load); in MPDTC
//! the fast tier judges an open phase alone.

/// Predicted phase current that must show in one period, A.
pub const FAST_PRED_MIN_A: f64 = 1.0;
/// The fast tier's allowances in one mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Allowance {
    /// A measured phase current at most this fraction of its prediction
    /// is no current: a cause inside the measurement's average leaves the
    /// share of its samples before the cause.
    pub open_fraction: f64,
    /// The share of `L di/dt` a dead-encoder estimate may carry (the
    /// model's 30 % and the measurement's timing).
    pub inductive: f64,
    /// Encoder counts the back-EMF must prove while the count stood still.
    pub dead_counts: f64,
    /// The share of the change of applied voltage from one period to the
    /// next a dead-encoder estimate may carry: the measurement's age is
    /// known to within this many periods.
    pub timing: f64,
}

/// FOC: the average's 4 samples lie after a step's end (the last 0.19
/// periods); a current step shows up to 16 % of `L di/dt` in the axis the
/// voltage did not drive. Healthy runs came to 0.437 of the prediction.
/// A still count needs [`FAST_DEAD_COUNTS`]: a healthy slow run came to
/// 1.11 counts (quantisation against an estimate over the measurement's
/// lagging average).
pub const FOC_ALLOWANCE: Allowance = Allowance {
    open_fraction: 0.3,
    inductive: INDUCTIVE_TOL,
    dead_counts: FAST_DEAD_COUNTS,
    timing: FOC_TIMING_TOL,
};
/// MPDTC: the average spans the whole period, so a cause after a step
/// that ends in its second quarter leaves two of four samples (0.5) in
/// the next step's average; the model holds the measurement's timing (the
/// ratio was 0.995 to 1.0 over a current step): the model's 30 % alone.
/// Healthy runs came to 0.666 of the prediction. A still count needs
/// [`MPDTC_DEAD_COUNTS`]: healthy runs came to 0.52 counts.
pub const MPDTC_ALLOWANCE: Allowance = Allowance {
    open_fraction: 0.55,
    inductive: MODEL_TOL,
    dead_counts: MPDTC_DEAD_COUNTS,
    timing: 0.0,
};
/// FOC: how far the measurement's age may stand from
/// `FOC_VOLTAGE_AGE`, periods. The PL averages four ADC samples (a
/// quarter of the PWM period); where that block falls in the period
/// follows the ADC timer's restart in the first step after `enable`,
/// whose latency varies, and the grouping of samples into blocks, which
/// the restart does not reset: a block anywhere in a quarter period. On
/// the co-simulated `pl_top` the measurement stood 0.13 periods younger
/// than assumed after an enable whose first step ran 381 cycles late, and
/// the period after the FOC's first (19.4 V) voltage read 2.05 counts on
/// a locked rotor. A voltage that does not change from period to period
/// (a steady current, a slow rotor) carries no such error.
pub const FOC_TIMING_TOL: f64 = 0.25;
/// A phase at zero against a prediction of this much floats: no
/// back-EMF estimate in that period, A (the estimate's error from a
/// floating terminal reaches the dead-encoder threshold at about 0.3 A of
/// prediction in both modes: `T / L` times its voltage).
pub const FLOAT_PRED_MIN_A: f64 = 0.2;
/// Encoder counts the back-EMF must prove while the count stood still
/// (FOC): a rotor that turns one count moves the count, so the estimate
/// may be off by a factor of two.
pub const FAST_DEAD_COUNTS: f64 = 2.0;
/// The same in MPDTC, whose short period leaves a still interval of
/// little more than a third of it after a slow step's last read (under
/// co-simulation the step's guest time reaches 0.6 to 0.7 periods): 1.25
/// counts are 2.4 times the most a healthy run came to.
pub const MPDTC_DEAD_COUNTS: f64 = 1.25;

/// The open phase (0 = a), if any, from one period's predicted and
/// measured phase currents, A, and the `fraction` of its prediction a
/// phase may show and still be open.
pub fn open_in_one_period(pred: [f64; 3], meas: [f64; 3], fraction: f64) -> Option<usize> {
    (0..3).find(|&x| {
        let p = libm::fabs(pred[x]);
        p >= FAST_PRED_MIN_A && libm::fabs(meas[x]) <= ZERO_MAX_A.max(fraction * p)
    })
}

/// The back-EMF over an interval of length `t_s` and the inductive term
/// `L di/dt` of its voltage equation, V (alpha-beta vectors' magnitudes):
/// mean applied voltage `u`, mean current `i_mean`, currents `i0` at its
/// start and `i1` at its end (A), the motor's `r_ohm` and `l_h`. One
/// period (`i_mean` the mean of its ends) or a window of them.
pub fn back_emf(
    u: (f64, f64),
    i_mean: (f64, f64),
    i0: (f64, f64),
    i1: (f64, f64),
    r_ohm: f64,
    l_h: f64,
    t_s: f64,
) -> (f64, f64) {
    let l = |a: f64, b: f64| l_h * (b - a) / t_s;
    let (ea, eb) = (
        u.0 - r_ohm * i_mean.0 - l(i0.0, i1.0),
        u.1 - r_ohm * i_mean.1 - l(i0.1, i1.1),
    );
    (
        libm::hypot(ea, eb),
        libm::hypot(l(i0.0, i1.0), l(i0.1, i1.1)),
    )
}

/// Encoder counts the rotor turns in `ts_s` at a back-EMF of `e_v`
/// (flux `psi_wb`, `pole_pairs`, `cpr` counts per turn).
pub fn counts_in_period(e_v: f64, psi_wb: f64, pole_pairs: u32, cpr: u32, ts_s: f64) -> f64 {
    let w_m = e_v / psi_wb / f64::from(pole_pairs.max(1));
    w_m * ts_s * f64::from(cpr) / (2.0 * core::f64::consts::PI)
}

/// One control period as the fast tier sees it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Period {
    /// Sampled encoder count.
    pub pos: u32,
    /// Measured phase currents, A.
    pub i_abc: [f64; 3],
    /// Electrical angle and speed from the encoder, rad and rad/s.
    pub theta_e_rad: f64,
    pub omega_e_rad_s: f64,
    /// Voltage applied over the period that ends at this step (alpha-beta),
    /// V.
    pub u_ab: (f64, f64),
}

/// The fast tier's verdict of one period.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FastVerdict {
    /// The open phase (0 = a).
    pub open: Option<usize>,
    /// The count stood still while the back-EMF proved motion.
    pub dead: bool,
    /// Smallest `|measured| / |predicted|` of a phase predicted at
    /// [`FAST_PRED_MIN_A`] or more (`INFINITY`: none), for the margins.
    pub open_ratio: f64,
    /// Counts the back-EMF says the rotor turned while the count was seen
    /// still in the period (0 when not judged).
    pub counts: f64,
    /// The count stood still over the period.
    pub still: bool,
    /// The predicted phase currents, A.
    pub pred_abc: [f64; 3],
}

/// The live count the last step read late in its period, and the share of
/// the period still to come after that read (0..=1): the count stood still
/// from there if this step's sample is the same.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Since {
    /// Counts.
    pub pos: u32,
    /// Share of the control period after the read.
    pub share: f64,
}

/// The fast tier's state: the period before.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FastTier {
    last: Option<Period>,
}

impl FastTier {
    /// Starts afresh (gates off, mode change, a stall).
    pub fn reset(&mut self) {
        *self = Self::default();
    }

    /// One control period with `model` (the controller's motor and period,
    /// observer unused), the measurement's age in periods `age` (its
    /// average stands that far before the step: the change of current
    /// between two steps follows the voltage of the period before by that
    /// share) and the encoder's `cpr`. The count stands still when `now`'s
    /// equals the last count read in the period before: `since`, the live
    /// count at the end of the last step, if it moved after that step's
    /// sample (then the still interval is the share of the period after
    /// it), else that step's sample (the whole period).
    pub fn step(
        &mut self,
        model: &MpdtcConfig,
        now: Period,
        since: Option<Since>,
        age: f64,
        cpr: u32,
        allow: Allowance,
    ) -> FastVerdict {
        let Some(last) = self.last.replace(now) else {
            return FastVerdict {
                open_ratio: f64::INFINITY,
                ..FastVerdict::default()
            };
        };
        let ts = model.params.control_period_s;
        let mo = &model.model;
        let age = age.clamp(0.0, 1.0);
        let u = (
            (1.0 - age) * now.u_ab.0 + age * last.u_ab.0,
            (1.0 - age) * now.u_ab.1 + age * last.u_ab.1,
        );
        // The model's step, in the rotor frame of the last step.
        let (al, be) = clarke(last.i_abc);
        let i_dq = park(al, be, last.theta_e_rad);
        let u_dq = park(u.0, u.1, last.theta_e_rad);
        let (pd, pq) = model.predict_u(i_dq, u_dq, last.omega_e_rad_s, (0.0, 0.0));
        let th1 = last.theta_e_rad + last.omega_e_rad_s * ts;
        let (pa, pb) = inv_park(pd, pq, th1);
        let pred = inv_clarke(pa, pb);
        // No current ever measured (a PL without a motor) is no phase's
        // evidence: an open phase follows a period with current.
        let flowed = |i: &[f64; 3]| i.iter().any(|&x| libm::fabs(x) > ZERO_MAX_A);
        let open = if flowed(&now.i_abc) || flowed(&last.i_abc) {
            open_in_one_period(pred, now.i_abc, allow.open_fraction)
        } else {
            None
        };
        let open_ratio = (0..3)
            .filter(|&x| libm::fabs(pred[x]) >= FAST_PRED_MIN_A)
            .map(|x| libm::fabs(now.i_abc[x]) / libm::fabs(pred[x]))
            .fold(f64::INFINITY, f64::min);
        // The voltage equation does not hold with a terminal that floats
        // (an open phase: no current against a prediction of some); a
        // healthy phase crossing zero is predicted near zero too.
        let floating = (0..3).any(|x| {
            libm::fabs(now.i_abc[x]) <= ZERO_MAX_A && libm::fabs(pred[x]) >= FLOAT_PRED_MIN_A
        });
        let mut counts = 0.0;
        if open.is_none() && flowed(&now.i_abc) && !floating {
            let (i0, i1) = (clarke(last.i_abc), clarke(now.i_abc));
            let mean = (0.5 * (i0.0 + i1.0), 0.5 * (i0.1 + i1.1));
            let (e, l_term) = back_emf(u, mean, i0, i1, mo.r_s_ohm, mo.l_d_h, ts);
            // Less what a model off by `MODEL_TOL` could put in it (the
            // inductive term also carries the measurement's timing).
            let ri = mo.r_s_ohm * 0.5 * libm::hypot(i0.0 + i1.0, i0.1 + i1.1);
            // And what the measurement's timing could put in it: a share
            // of the change of voltage between the two periods.
            let du = libm::hypot(now.u_ab.0 - last.u_ab.0, now.u_ab.1 - last.u_ab.1);
            let proven = e - MODEL_TOL * ri - allow.inductive * l_term - allow.timing * du;
            counts = counts_in_period(proven.max(0.0), mo.psi_pm_wb, mo.pole_pairs, cpr, ts);
        }
        // Only the interval the count was seen still over proves anything:
        // the period's counts in its share of the period.
        let (from, share) = match since {
            Some(s) if s.pos != last.pos => (s.pos, s.share),
            _ => (last.pos, 1.0),
        };
        let still = now.pos == from;
        counts *= share;
        FastVerdict {
            open,
            dead: still && counts >= allow.dead_counts,
            open_ratio,
            counts,
            still,
            pred_abc: pred,
        }
    }
}

use models::pmsm::frames::{clarke, inv_clarke, inv_park, park};
use models::pmsm::mpdtc_ref::MpdtcConfig;

/// Whether `delta` new ADC results since the last step's read are what
/// one control period of `period_cycles` gives with one result every
/// `result_cycles` (the lower or the upper whole number when they do not
/// divide). Anything else pairs the step's currents with another period
/// than its voltage: a boundary served without a step (an overrun) leaves
/// that period's voltage out, and a step that read the ADC after the next
/// result (a late start) has the next period's currents, and the step
/// after it none. The checks of a period need the voltage that made its
/// currents, so they start afresh there.
pub fn results_regular(delta: u32, period_cycles: u32, result_cycles: u32) -> bool {
    let r = result_cycles.max(1);
    let lo = period_cycles / r;
    let hi = period_cycles.div_ceil(r);
    (lo..=hi).contains(&delta)
}

/// Window of both checks, s.
pub const WINDOW_S: f64 = 0.5e-3;
/// Relative error of the controller's `R` and `L` against the motor's
/// that the dead-encoder checks stand: the estimate must exceed what
/// such an error could put in it (`MODEL_TOL R |i| + INDUCTIVE_TOL L
/// |di/dt|`).
pub const MODEL_TOL: f64 = 0.3;
/// The same for the inductive term: the model's 0.3 and the
/// measurement's timing (in FOC, a current step of one period shows up to
/// 16 % of `L di/dt` in the axis the voltage did not drive: the average's
/// samples are not all of one instant).
pub const INDUCTIVE_TOL: f64 = 0.5;
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
        let u_mean = (self.sum_u.0 / n, self.sum_u.1 / n);
        let i_mean = (self.sum_i.0 / n, self.sum_i.1 / n);
        let (e, li) = back_emf(u_mean, i_mean, self.i_start, i, r_ohm, l_h, n * ts_s);
        // What a model off by `MODEL_TOL` could put in the estimate.
        let ri = r_ohm * libm::hypot(i_mean.0, i_mean.1);
        self.restart(i);
        e > EMF_MIN_V + MODEL_TOL * ri + INDUCTIVE_TOL * li
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
    /// still count never trips; the same count with a back-EMF of 3 V
    /// (over the 1.5 V and the 0.83 V a 30 % error of `R` could give at
    /// 5 A) trips at the window's end.
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
            assert!(!dead.step(7, (3.0, r * 5.0), i, false, r, l, TS, m), "{k}");
        }
        assert!(dead.step(7, (3.0, r * 5.0), i, false, r, l, TS, m));
        // A count starts the window again.
        assert!(!dead.step(8, (3.0, r * 5.0), i, false, r, l, TS, m));
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
            assert!(!dead.step(7, (3.0, r * 5.0), i, k == 4, r, l, TS, m));
        }
        assert!(!dead.step(7, (3.0, r * 5.0), i, true, r, l, TS, m));
        assert!(dead.step(7, (3.0, r * 5.0), i, false, r, l, TS, m));
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

    /// Hand-computed: 1.7 A predicted, 0.05 A measured is open; 0.6 A
    /// (over 0.3 of it) is not; 0.9 A predicted is no evidence.
    #[test]
    fn one_period_open_phase() {
        assert_eq!(
            open_in_one_period([0.0, 1.7, -1.7], [0.0, 0.05, -1.7], 0.3),
            Some(1)
        );
        assert_eq!(
            open_in_one_period([0.0, 1.7, -1.7], [0.0, 0.5, -1.7], 0.3),
            Some(1)
        );
        assert_eq!(
            open_in_one_period([0.0, 1.7, -1.7], [0.0, 0.6, -1.7], 0.3),
            None
        );
        assert_eq!(
            open_in_one_period([0.0, 0.9, -0.9], [0.0, 0.0, -0.9], 0.3),
            None
        );
    }

    /// `u = R i + L di/dt + e` by hand: 0.555 V at 1 A, 1 A more over one
    /// period (10.23 V of `L di/dt`) and 3 V of back-EMF.
    #[test]
    fn one_period_back_emf_and_its_counts() {
        let (r, l) = (0.555, 0.64e-3);
        let u = (0.0, r * 1.5 + l / TS + 3.0);
        let (e, li) = back_emf(u, (0.0, 1.5), (0.0, 1.0), (0.0, 2.0), r, l, TS);
        assert!(
            (e - 3.0).abs() < 1e-9 && (li - l / TS).abs() < 1e-9,
            "{e} {li}"
        );
        // 3 V at 0.0093 Wb: 322 rad/s electrical, 46 rad/s at 7 pole
        // pairs, 1.88 counts of 4096 in 62.56 us.
        let c = counts_in_period(3.0, 0.0093, 7, 4096, TS);
        assert!((c - 3.0 / 0.0093 / 7.0 * TS * 4096.0 / core::f64::consts::TAU).abs() < 1e-12);
        assert!((1.8..1.9).contains(&c), "{c}");
    }

    /// Hand-computed: FOC 6256 cycles over 1564-cycle results is 4 a
    /// period; the MPDTC's period is one result; 6256 over 1500 is 4 or
    /// 5. An overrun doubles the count, a late read takes one from the
    /// next period.
    #[test]
    fn regular_result_counts() {
        assert!(results_regular(4, 6256, 1564));
        assert!(!results_regular(8, 6256, 1564));
        assert!(!results_regular(5, 6256, 1564));
        assert!(!results_regular(3, 6256, 1564));
        assert!(results_regular(1, 1564, 1564));
        assert!(!results_regular(0, 1564, 1564));
        assert!(!results_regular(2, 1564, 1564));
        assert!(results_regular(4, 6256, 1500) && results_regular(5, 6256, 1500));
        assert!(!results_regular(3, 6256, 1500) && !results_regular(6, 6256, 1500));
        assert!(results_regular(7, 7, 0));
    }

    /// The fault matrix's false `ENCODER_DEAD` on the co-simulated
    /// `pl_top` (FOC, locked rotor at angle 0, 0.2 N m from `enable`):
    /// the two periods after the FOC's first voltage as the control step
    /// saw them (the ADC's currents, A; the voltage applied over each
    /// period, V; the count still for 0.839 of the last period). Without
    /// the timing allowance the estimate was 2.05 counts, a dead encoder;
    /// the allowance takes a quarter of the 16.4 V change of voltage.
    #[test]
    fn the_first_period_after_the_focs_first_voltage_is_no_dead_encoder() {
        let mo = models::pmsm::params::MotorParams::default();
        let m = MpdtcConfig::prediction_model(mo, TS).unwrap();
        let p = |i_abc: [f64; 3], u_ab: (f64, f64)| Period {
            pos: 0,
            i_abc,
            theta_e_rad: 0.0,
            omega_e_rad_s: 0.0,
            u_ab,
        };
        let run = |allow: Allowance| {
            let mut f = FastTier::default();
            f.step(
                &m,
                p([-0.0547, 1.5156, -1.4766], (0.0, 19.3989)),
                None,
                0.31,
                4096,
                allow,
            );
            let since = Some(Since {
                pos: 0,
                share: 0.8386,
            });
            f.step(
                &m,
                p([0.0, 1.6875, -1.6953], (0.0, 2.9643)),
                since,
                0.31,
                4096,
                allow,
            )
        };
        let without = run(Allowance {
            timing: 0.0,
            ..FOC_ALLOWANCE
        });
        assert!(
            without.dead && (2.0..2.1).contains(&without.counts),
            "{without:?}"
        );
        let v = run(FOC_ALLOWANCE);
        assert!(v.still && !v.dead && v.counts < 1.0, "{v:?}");
    }

    /// The fast tier on hand-made periods: a steady current with `u = R i`
    /// and a still count is no fault; the next period's current gone from
    /// phase b is open; a count that stood still while 40 V of back-EMF
    /// (about 25 counts) turned the rotor is dead.
    #[test]
    fn fast_tier_verdicts() {
        let mo = models::pmsm::params::MotorParams::default();
        let m = MpdtcConfig::prediction_model(mo, TS).unwrap();
        let i = [0.0, 1.7, -1.7];
        let (al, be) = clarke(i);
        let p = |i_abc: [f64; 3], u_ab: (f64, f64)| Period {
            pos: 5,
            i_abc,
            theta_e_rad: 0.0,
            omega_e_rad_s: 0.0,
            u_ab,
        };
        let held = (mo.r_s_ohm * al, mo.r_s_ohm * be);
        let mut f = FastTier::default();
        f.step(&m, p(i, held), None, 0.0, 4096, FOC_ALLOWANCE);
        let v = f.step(&m, p(i, held), None, 0.0, 4096, FOC_ALLOWANCE);
        assert!(v.open.is_none() && !v.dead && v.still, "{v:?}");
        assert!((v.open_ratio - 1.0).abs() < 1e-3, "{v:?}");
        let v = f.step(&m, p([0.0, 0.0, 0.0], held), None, 0.0, 4096, FOC_ALLOWANCE);
        assert_eq!(v.open, Some(1), "{v:?}");
        let mut f = FastTier::default();
        let emf = (held.0, held.1 + 40.0);
        f.step(&m, p(i, emf), None, 0.0, 4096, FOC_ALLOWANCE);
        let since = |pos, share| Some(Since { pos, share });
        let v = f.step(&m, p(i, emf), since(5, 0.5), 0.0, 4096, FOC_ALLOWANCE);
        assert!(v.dead && v.counts > 20.0, "{v:?}");
        let whole = v.counts;
        // The same with the count moved since the last step's end.
        let v = f.step(&m, p(i, emf), since(6, 0.5), 0.0, 4096, FOC_ALLOWANCE);
        assert!(!v.dead, "{v:?}");
        // The count moved after the last sample (5) and stood still from
        // the end read on: only the share of the period after the read
        // counts (a tenth of the whole period's counts).
        let mut f = FastTier::default();
        f.step(&m, p(i, emf), None, 0.0, 4096, FOC_ALLOWANCE);
        let now = Period {
            pos: 6,
            ..p(i, emf)
        };
        let v = f.step(&m, now, since(6, 0.1), 0.0, 4096, FOC_ALLOWANCE);
        assert!(v.still && (v.counts - 0.1 * whole).abs() < 1e-9, "{v:?}");
        // Just below the threshold.
        let mut f = FastTier::default();
        f.step(&m, p(i, emf), None, 0.0, 4096, FOC_ALLOWANCE);
        let share = 0.99 * FOC_ALLOWANCE.dead_counts / whole;
        let v = f.step(&m, now, since(6, share), 0.0, 4096, FOC_ALLOWANCE);
        assert!(v.still && !v.dead, "{v:?}");
    }
}
