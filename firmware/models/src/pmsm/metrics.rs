//! Step-response and switching metrics over sampled signals.
//!
//! The one place of these definitions: the FOC and MPDTC tests and
//! `drivectl paper mpdtc` (which applies them to 15.625 us window means) all
//! call the functions below.
//!
//! Definitions:
//! - **Settling time** of a step from `y0` to `y1` applied at `t_step`: the
//!   time from `t_step` to the first sample instant in the window
//!   `[t_step, t_end]` from which on `|y - y1| <= band_abs` holds for every
//!   sample up to `t_end` (enters the band and stays). `None` if the last
//!   sample of the window is outside the band. The resolution is the sample
//!   spacing (3.9 us at 256 kHz).
//!   The band is [`settling_band`]: [`SETTLING_BAND_FRACTION`] = 10 % of the
//!   step size, for every controller and every table.
//! - **Overshoot**: `max over the window of (y - y1) * sign(y1 - y0)`, in
//!   percent of `|y1 - y0|`, floored at 0.
//! - **Switching frequency**: gate transitions per leg per second, averaged
//!   over the three legs ([`transitions_per_leg_per_s`]). A centre-aligned
//!   PWM leg makes two transitions per carrier period, so carrier PWM at
//!   `f_pwm` gives `2 f_pwm` by this count; [`equivalent_carrier_hz`] halves it
//!   (one on + one off = one switching cycle).
//! - **Ripple**: RMS of `y - ref` about its mean over the steady-state
//!   samples, with the mean error reported beside it
//!   ([`error_mean_and_ripple_rms`]).

/// Half-width of the settling band as a fraction of the step size `|y1 - y0|`.
/// 10 %: the band must contain the steady-state ripple the MPDTC's torque
/// tolerance allows (T_tol = 0.08 N m = 10 % of the 0.8 N m toggle of the
/// paper's Fig. 10); a 5 % band would measure that ripple, not the dynamics.
pub const SETTLING_BAND_FRACTION: f64 = 0.10;

/// Settling band, absolute: [`SETTLING_BAND_FRACTION`] of the step size `|y1 - y0|`.
pub fn settling_band(y0: f64, y1: f64) -> f64 {
    SETTLING_BAND_FRACTION * libm::fabs(y1 - y0)
}

/// Settling time, s (definition in the module doc). `samples` yields
/// `(t_s, y)` in time order; samples before `t_step_s` and after `t_end_s`
/// are ignored.
pub fn settling_time_s(
    samples: impl IntoIterator<Item = (f64, f64)>,
    t_step_s: f64,
    t_end_s: f64,
    y1: f64,
    band_abs: f64,
) -> Option<f64> {
    // First in-band instant after the last out-of-band one.
    let mut enter: Option<f64> = None;
    for (t, y) in samples {
        if t < t_step_s || t > t_end_s {
            continue;
        }
        if libm::fabs(y - y1) <= band_abs {
            enter.get_or_insert(t);
        } else {
            enter = None;
        }
    }
    enter.map(|t| t - t_step_s)
}

/// Overshoot, percent of the step size (definition in the module doc).
pub fn overshoot_percent(
    samples: impl IntoIterator<Item = (f64, f64)>,
    t_step_s: f64,
    t_end_s: f64,
    y0: f64,
    y1: f64,
) -> f64 {
    let step = y1 - y0;
    if step == 0.0 {
        return 0.0;
    }
    let sign = if step > 0.0 { 1.0 } else { -1.0 };
    let mut m: f64 = 0.0;
    for (t, y) in samples {
        if t >= t_step_s && t <= t_end_s {
            m = m.max((y - y1) * sign);
        }
    }
    100.0 * m / libm::fabs(step)
}

/// Mean gate transitions per leg per second between two cumulative counts.
pub fn transitions_per_leg_per_s(from: [u64; 3], to: [u64; 3], duration_s: f64) -> f64 {
    let n: u64 = (0..3).map(|x| to[x].saturating_sub(from[x])).sum();
    n as f64 / 3.0 / duration_s
}

/// Carrier-equivalent switching frequency: half of [`transitions_per_leg_per_s`].
pub fn equivalent_carrier_hz(from: [u64; 3], to: [u64; 3], duration_s: f64) -> f64 {
    0.5 * transitions_per_leg_per_s(from, to, duration_s)
}

/// Mean error and ripple of `(y, ref)` samples (the caller picks the
/// steady-state ones): `(mean of y - ref, RMS of y - ref about that mean)`;
/// `None` if there are no samples.
pub fn error_mean_and_ripple_rms(
    samples: impl IntoIterator<Item = (f64, f64)>,
) -> Option<(f64, f64)> {
    let (mut s1, mut s2, mut n) = (0.0, 0.0, 0usize);
    for (y, r) in samples {
        let e = y - r;
        s1 += e;
        s2 += e * e;
        n += 1;
    }
    if n == 0 {
        return None;
    }
    let mean = s1 / n as f64;
    Some((mean, libm::sqrt((s2 / n as f64 - mean * mean).max(0.0))))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settling_and_overshoot_on_a_constructed_first_order_response() {
        // y = 1 - exp(-t/tau) sampled every 1 us, step at 0, tau = 10 us:
        // enters the 10 % band at tau ln 10 = 23.03 us -> first sample inside at 24 us.
        let tau = 10e-6;
        let s: Vec<(f64, f64)> = (0..200)
            .map(|k| (k as f64 * 1e-6, 1.0 - (-(k as f64) * 1e-6 / tau).exp()))
            .collect();
        let ts =
            settling_time_s(s.iter().copied(), 0.0, 1.0, 1.0, settling_band(0.0, 1.0)).unwrap();
        assert!((ts - 24e-6).abs() < 1e-12, "{ts}");
        assert_eq!(
            overshoot_percent(s.iter().copied(), 0.0, 1.0, 0.0, 1.0),
            0.0
        );
        // Downward step with 10 % overshoot.
        let s2 = [
            (0.0, 1.0),
            (1.0, -0.2),
            (2.0, -1.1),
            (3.0, -1.0),
            (4.0, -1.0),
        ];
        assert!((overshoot_percent(s2, 0.0, 4.0, 1.0, -1.0) - 5.0).abs() < 1e-12);
        assert_eq!(settling_time_s(s2, 0.0, 4.0, -1.0, 0.15), Some(2.0));
        assert_eq!(settling_time_s(s2, 0.0, 4.0, -1.0, 0.05), Some(3.0));
        // Never settles: outside at the end.
        assert_eq!(settling_time_s(s2, 0.0, 2.0, -1.0, 0.05), None);
        assert_eq!(
            transitions_per_leg_per_s([0, 0, 0], [3, 3, 0], 1e-3),
            2000.0
        );
        // Errors 0.1 +- 0.02 (square wave): mean 0.1, ripple 0.02.
        let (mean, rip) =
            error_mean_and_ripple_rms([(0.52, 0.4), (0.48, 0.4), (0.52, 0.4), (0.48, 0.4)])
                .unwrap();
        assert!(
            (mean - 0.1).abs() < 1e-12 && (rip - 0.02).abs() < 1e-12,
            "{mean} {rip}"
        );
        assert_eq!(error_mean_and_ripple_rms([]), None);
    }
}
